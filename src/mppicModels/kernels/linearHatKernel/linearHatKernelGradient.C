/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    linearHatKernel::extrapolatedGradient: the derivative of the kernel's
    interpolant, with linearly extrapolated mirror values beyond the
    boundaries (see linearHatKernel.H).

\*---------------------------------------------------------------------------*/

#include "linearHatKernel.H"
#include "linearHatKernelBlock.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::linearHatKernel::extrapolatedGradient
(
    const UList<scalar>& cellValues,
    const UList<scalar>& ghostValues,
    const point& position,
    const label celli
) const
{
    if (!hexahedral_[celli])
    {
        return Zero;
    }

    const vector offset = position - mesh().cellCentres()[celli];
    const label firstFace = facesPerCell*celli;
    const label centreEntry = blockSize*celli + blockCentre;

    // Along each direction: the fraction t toward the chosen side, its
    // gradient, the block step to the far centre, and whether that centre
    // is a mirror (no cell: the image of the opposite neighbour)
    FixedList<scalar, 3> t;
    FixedList<vector, 3> dtdx;
    FixedList<label, 3> step;
    FixedList<bool, 3> mirror;

    for (label i = 0; i < 3; ++i)
    {
        const vector& plus = towardFace_[firstFace + 2*i];
        const vector& minus = towardFace_[firstFace + 2*i + 1];
        const bool hasPlus = magSqr(plus) > 0;
        const bool hasMinus = magSqr(minus) > 0;

        const vector plusOrMirror = hasPlus ? plus : -minus;
        const vector minusOrMirror = hasMinus ? minus : -plus;

        const scalar towardPlus = offset & plusOrMirror;
        if (towardPlus > 0)
        {
            t[i] = min(towardPlus, scalar(1));
            dtdx[i] = plusOrMirror;
            step[i] = blockStride[i];
            mirror[i] = !hasPlus;
        }
        else
        {
            t[i] = min(max(offset & minusOrMirror, scalar(0)), scalar(1));
            dtdx[i] = minusOrMirror;
            step[i] = -blockStride[i];
            mirror[i] = !hasMinus;
        }
    }

    // Value at corner k (bit i set: the far centre along direction i); a
    // mirror centre along i is 2 v(near) - v(opposite), expanded over the
    // corner's mirror directions
    FixedList<scalar, 8> corner;
    for (label k = 0; k < 8; ++k)
    {
        label mirrorBits = 0;
        for (label i = 0; i < 3; ++i)
        {
            if ((k & (1 << i)) && mirror[i])
            {
                mirrorBits |= (1 << i);
            }
        }

        scalar value = 0;
        for (label sub = 0; sub < 8; ++sub)
        {
            if (sub & ~mirrorBits)
            {
                continue;
            }

            label entry = centreEntry;
            scalar coeff = 1;
            for (label i = 0; i < 3; ++i)
            {
                if (!(k & (1 << i)))
                {
                    continue;
                }
                if (!mirror[i])
                {
                    entry += step[i];
                }
                else if (sub & (1 << i))
                {
                    entry -= step[i];
                    coeff = -coeff;
                }
                else
                {
                    coeff *= 2;
                }
            }
            value += coeff*this->value(cellValues, ghostValues, block_[entry]);
        }
        corner[k] = value;
    }

    // d/dx of sum_k w_k(t) v_k: along i, the far minus the near corners,
    // weighted bilinearly in the other two directions
    vector grad(Zero);
    for (label i = 0; i < 3; ++i)
    {
        scalar dIdt = 0;
        for (label k = 0; k < 8; ++k)
        {
            if (!(k & (1 << i)))
            {
                continue;
            }
            scalar weight = 1;
            for (label j = 0; j < 3; ++j)
            {
                if (j != i)
                {
                    weight *= (k & (1 << j)) ? t[j] : 1 - t[j];
                }
            }
            dIdt += weight*(corner[k] - corner[k ^ (1 << i)]);
        }
        grad += dIdt*dtdx[i];
    }

    return grad;
}


// ************************************************************************* //
