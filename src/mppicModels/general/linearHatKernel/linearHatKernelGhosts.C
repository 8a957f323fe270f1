/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    linearHatKernel's ghosts: the cells across processor faces (see
    linearHatKernel.H), one slot per face of each processor patch.

\*---------------------------------------------------------------------------*/

#include "linearHatKernel.H"
#include "processorPolyPatch.H"
#include "processorCyclicPolyPatch.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::linearHatKernel::setGhostSlots()
{
    const polyBoundaryMesh& patches = mesh().boundaryMesh();

    DynamicList<label> ghostPatches;
    labelHashSet neighbours;
    nGhosts_ = 0;

    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        if
        (
            !isA<processorPolyPatch>(pp)
         || isA<processorCyclicPolyPatch>(pp)
        )
        {
            continue;
        }

        // The exchange sends one list per neighbouring processor
        const label nbrProc = refCast<const processorPolyPatch>(pp).neighbProcNo();
        if (!neighbours.insert(nbrProc))
        {
            FatalErrorInFunction
                << "Two processor patches of processor "
                << Pstream::myProcNo() << " face processor " << nbrProc
                << " (patch " << pp.name() << "): the linear-hat kernel "
                << "expects one per neighbour" << exit(FatalError);
        }

        ghostPatches.append(patchi);
        patchGhostStart_[patchi] = nGhosts_;
        nGhosts_ += pp.size();
    }

    ghostPatches_.transfer(ghostPatches);
}


// ************************************************************************* //
