/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "coupledCellNeighbours.H"
#include "cellFaceGeometry.H"
#include "cyclicPolyPatch.H"
#include "processorPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(coupledCellNeighbours, 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coupledCellNeighbours::coupledCellNeighbours(const fvMesh& mesh)
:
    MeshObject<fvMesh, GeometricMeshObject, coupledCellNeighbours>(mesh),
    globalCells_(mesh.nCells()),
    processorPatches_(),
    patchNeighbours_(mesh.boundaryMesh().size())
{
    if (!Pstream::parRun())
    {
        return;
    }

    const polyBoundaryMesh& patches = mesh.boundaryMesh();

    DynamicList<label> processorPatches;
    labelHashSet neighbours;
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        if (!isA<processorPolyPatch>(pp) || isA<processorCyclicPolyPatch>(pp))
        {
            continue;
        }

        // The exchange sends one list per neighbouring processor
        const label nbrProc =
            refCast<const processorPolyPatch>(pp).neighbProcNo();
        if (!neighbours.insert(nbrProc))
        {
            FatalErrorInFunction
                << "Two processor patches of processor "
                << Pstream::myProcNo() << " face processor " << nbrProc
                << " (patch " << pp.name() << "): expected one per "
                << "neighbour" << exit(FatalError);
        }
        processorPatches.append(patchi);
    }
    processorPatches_.transfer(processorPatches);

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (const label patchi : processorPatches_)
    {
        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>(patches[patchi]);
        labelList faceCells(pp.faceCells());
        for (label& celli : faceCells)
        {
            celli = toGlobal(celli);
        }
        UOPstream toNbr(pp.neighbProcNo(), buffers);
        toNbr << faceCells;
    }
    buffers.finishedSends();

    for (const label patchi : processorPatches_)
    {
        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>(patches[patchi]);
        UIPstream fromNbr(pp.neighbProcNo(), buffers);
        fromNbr >> patchNeighbours_[patchi];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::coupledCellNeighbours::across
(
    const label celli,
    const label facei
) const
{
    const fvMesh& mesh = this->mesh();

    if (mesh.isInternalFace(facei))
    {
        return toGlobal(cellFaceGeometry::cellAcross(mesh, celli, facei));
    }

    const label patchi = mesh.boundaryMesh().whichPatch(facei);
    const polyPatch& pp = mesh.boundaryMesh()[patchi];
    const label patchFacei = facei - pp.start();

    if (isProcessorPatch(patchi))
    {
        return patchNeighbours_[patchi][patchFacei];
    }

    if (isA<cyclicPolyPatch>(pp))
    {
        const cyclicPolyPatch& cyclic = refCast<const cyclicPolyPatch>(pp);
        if (cyclic.parallel())
        {
            return toGlobal(cyclic.neighbPatch().faceCells()[patchFacei]);
        }
    }

    return -1;
}


// ************************************************************************* //
