/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    linearHatKernel::cornerNodeFaceGradient: the gradient of a cell field
    at a point as MFiX-PIC's GARG_2012 interpolation brings its packing
    gradient to a parcel (interpolate_pic.f, INTERPOLATE_PIC0, read in
    MFiX's source): the gradient lives on the faces (MFiX's staggered
    grid), each component on the faces normal to it; a cell corner (node)
    takes, per component, the mean of the 4 face values around it (the
    faces of that orientation that share the corner), and the parcel the
    trilinear interpolant of its cell's 8 corners.

    In cell terms (as cornerNodeWeights for the deposition): component i
    at a point of cell c is

        sum over the transverse steps s_j, s_k in {-1, 0, 1} of
            W_j(s_j) W_k(s_k)
           *[ (1 - a_i)/2 D_i^-(c + s) + (1 + a_i)/2 D_i^+(c + s) ]

    with W(-1) = (1 - a)/4, W(0) = 1/2, W(+1) = (1 + a)/4, a the point's
    place between the cell's two faces along each direction, and D_i^+-
    the difference across the cell's face of side +- along i over the
    centre distance, (value across - value)/d (+) and (value - value
    across)/d (-), times that face's outward normal (+) or its opposite (-).

    Beyond a non-coupled face (wall, inflow, outflow: MFiX's non-fluid
    cells) the value across is the cell's own beyond value (cellBeyond,
    ghostBeyond: the caller's wall colouring) at twice the centre-to-face
    distance. A transverse step beyond such a face stays in the cell (the
    kernel's reflection): where MFiX averages a wall-side node with a zero
    face value, this takes the near face's value twice. The distances and
    normals are those of the point's own cell, so the neighbours' faces are
    taken at its spacing (exact on a uniform hexahedral mesh, as MFiX's
    Cartesian grid). A face has no cell across where the block's step
    stays in the cell; so a cyclic direction one cell across is taken for
    a boundary. A non-hexahedral cell has no corner-node form: zero (the
    caller uses its own cell's faces). Cost per parcel: 27 block cells,
    four values each; the face differences are not cached per cell, as the
    ghosts' would need a second exchange.

\*---------------------------------------------------------------------------*/

#include "linearHatKernel.H"
#include "linearHatKernelBlock.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::linearHatKernel::cornerNodeFaceGradient
(
    const UList<scalar>& cellValues,
    const UList<scalar>& ghostValues,
    const UList<scalar>& cellBeyond,
    const UList<scalar>& ghostBeyond,
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

    // Along each direction: the transverse weights of the steps -1, 0, +1,
    // the weights of the two faces, their outward normals over the centre
    // distance across them (twice the distance to the face beyond a
    // boundary)
    FixedList<scalar, 3> places;
    const FixedList<FixedList<scalar, 3>, 3> along =
        cornerNodeSteps(offset, towardOwnFace_, firstFace, places);
    FixedList<scalar, 3> plusWeight;
    FixedList<vector, 3> plusDelta;
    FixedList<vector, 3> minusDelta;

    for (label i = 0; i < 3; ++i)
    {
        plusWeight[i] = 0.5*(1 + places[i]);

        const vector& plus = towardFace_[firstFace + 2*i];
        const vector& minus = towardFace_[firstFace + 2*i + 1];
        plusDelta[i] =
            magSqr(plus) > 0 ? plus : 0.5*towardOwnFace_[firstFace + 2*i];
        minusDelta[i] =
            magSqr(minus) > 0 ? minus : 0.5*towardOwnFace_[firstFace + 2*i + 1];
    }

    vector grad(Zero);

    for (label i = 0; i < 3; ++i)
    {
        const label j = (i + 1) % 3;
        const label k = (i + 2) % 3;

        for (label sj = -1; sj <= 1; ++sj)
        {
            for (label sk = -1; sk <= 1; ++sk)
            {
                const label entry =
                    centreEntry + sj*blockStride[j] + sk*blockStride[k];
                const label cell = block_[entry];
                const label plusCell = block_[entry + blockStride[i]];
                const label minusCell = block_[entry - blockStride[i]];

                const scalar v = value(cellValues, ghostValues, cell);
                const scalar beyond = value(cellBeyond, ghostBeyond, cell);
                const scalar plusValue =
                    plusCell == cell
                  ? beyond
                  : value(cellValues, ghostValues, plusCell);
                const scalar minusValue =
                    minusCell == cell
                  ? beyond
                  : value(cellValues, ghostValues, minusCell);

                grad +=
                    along[j][sj + 1]*along[k][sk + 1]
                   *(
                        plusWeight[i]*(plusValue - v)*plusDelta[i]
                      + (1 - plusWeight[i])*(minusValue - v)*minusDelta[i]
                    );
            }
        }
    }

    return grad;
}


// ************************************************************************* //
