/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "linearHatKernel.H"
#include "linearHatKernelBlock.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::linearHatKernel::evaluate
(
    const point& position,
    const label celli,
    weights& w
) const
{
    const vector offset = position - mesh().cellCentres()[celli];
    const label firstFace = facesPerCell*celli;

    // Along each direction: the fraction t toward the chosen face and the
    // block step to the cell across it
    FixedList<scalar, 3> t;
    FixedList<label, 3> step;
    for (label i = 0; i < 3; ++i)
    {
        const scalar towardPlus = offset & towardFace_[firstFace + 2*i];
        if (towardPlus > 0)
        {
            t[i] = min(towardPlus, scalar(1));
            step[i] = blockStride[i];
        }
        else
        {
            const scalar towardMinus =
                offset & towardFace_[firstFace + 2*i + 1];
            t[i] = min(max(towardMinus, scalar(0)), scalar(1));
            step[i] = -blockStride[i];
        }
    }

    // Corner k takes the far side along direction i when bit i of k is set
    const label firstEntry = blockSize*celli + blockCentre;
    for (label k = 0; k < 8; ++k)
    {
        label entry = firstEntry;
        scalar weight = 1;
        for (label i = 0; i < 3; ++i)
        {
            if (k & (1 << i))
            {
                entry += step[i];
                weight *= t[i];
            }
            else
            {
                weight *= 1 - t[i];
            }
        }
        w.cells[k] = block_[entry];
        w.values[k] = weight;
    }
}


void Foam::linearHatKernel::evaluate
(
    const point& position,
    const label celli,
    cornerNodeWeights& w
) const
{
    const vector offset = position - mesh().cellCentres()[celli];
    const label firstFace = facesPerCell*celli;

    // Along each direction: the weights of the steps -1, 0 and +1. The
    // point's place between the cell's two faces, a in [-1, 1] (+1 on the
    // face of side +), splits it between the two corner nodes, (1 + a)/2
    // and (1 - a)/2; each node's share goes half to this cell and half to
    // the cell across, whose mean of corners it also enters
    FixedList<scalar, 3> places;
    const FixedList<FixedList<scalar, 3>, 3> along =
        cornerNodeSteps(offset, towardOwnFace_, firstFace, places);

    const label firstEntry = blockSize*celli;
    for (label entry = 0; entry < blockSize; ++entry)
    {
        w.cells[entry] = block_[firstEntry + entry];
        w.values[entry] =
            along[0][entry/9]*along[1][(entry/3)%3]*along[2][entry%3];
    }
}


// ************************************************************************* //
