/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "processorPolyPatch.H"
#include "PstreamBuffers.H"
#include "UIndirectList.H"
#include "SubList.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
Type Foam::linearHatKernel::interpolate
(
    const UList<Type>& cellValues,
    const UList<Type>& ghostValues,
    const point& position,
    const label celli
) const
{
    weights w;
    evaluate(position, celli, w);

    Type sum = w.values[0]*value(cellValues, ghostValues, w.cells[0]);
    for (label k = 1; k < 8; ++k)
    {
        sum += w.values[k]*value(cellValues, ghostValues, w.cells[k]);
    }
    return sum;
}


template<class Type>
void Foam::linearHatKernel::deposit
(
    UList<Type>& cellDensity,
    UList<Type>& ghostDensity,
    const point& position,
    const label celli,
    const Type& value
) const
{
    weights w;
    evaluate(position, celli, w);

    const scalarField& V = mesh().V();
    const label nCells = V.size();
    for (label k = 0; k < 8; ++k)
    {
        const label cellk = w.cells[k];
        if (cellk < nCells)
        {
            cellDensity[cellk] += (w.values[k]/V[cellk])*value;
        }
        else
        {
            const label slot = cellk - nCells;
            ghostDensity[slot] += (w.values[k]/ghostVolumes_[slot])*value;
        }
    }
}


template<class Type>
void Foam::linearHatKernel::ghostValues
(
    const UList<Type>& cellValues,
    List<Type>& ghosts
) const
{
    ghosts.setSize(nGhosts_);
    if (!Pstream::parRun())
    {
        return;
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (const label patchi : ghostPatches_)
    {
        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>(mesh().boundaryMesh()[patchi]);
        UOPstream toNbr(pp.neighbProcNo(), buffers);
        toNbr << List<Type>(UIndirectList<Type>(cellValues, pp.faceCells()));
    }
    buffers.finishedSends();

    for (const label patchi : ghostPatches_)
    {
        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>(mesh().boundaryMesh()[patchi]);
        UIPstream fromNbr(pp.neighbProcNo(), buffers);
        const List<Type> received(fromNbr);
        SubList<Type>(ghosts, pp.size(), patchGhostStart_[patchi]) = received;
    }
}


template<class Type>
void Foam::linearHatKernel::ghostValues
(
    const GeometricField<Type, fvPatchField, volMesh>& field,
    List<Type>& ghosts
) const
{
    ghosts.setSize(nGhosts_);
    for (const label patchi : ghostPatches_)
    {
        SubList<Type>
        (
            ghosts,
            field.boundaryField()[patchi].size(),
            patchGhostStart_[patchi]
        ) = field.boundaryField()[patchi];
    }
}


template<class Type>
void Foam::linearHatKernel::addGhostDeposits
(
    UList<Type>& cellValues,
    UList<Type>& ghosts
) const
{
    if (!Pstream::parRun())
    {
        return;
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (const label patchi : ghostPatches_)
    {
        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>(mesh().boundaryMesh()[patchi]);
        UOPstream toNbr(pp.neighbProcNo(), buffers);
        toNbr << SubList<Type>(ghosts, pp.size(), patchGhostStart_[patchi]);
    }
    buffers.finishedSends();

    for (const label patchi : ghostPatches_)
    {
        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>(mesh().boundaryMesh()[patchi]);
        UIPstream fromNbr(pp.neighbProcNo(), buffers);
        const List<Type> received(fromNbr);
        const labelUList& faceCells = pp.faceCells();
        forAll(received, facei)
        {
            cellValues[faceCells[facei]] += received[facei];
        }
    }

    ghosts = Zero;
}


// ************************************************************************* //
