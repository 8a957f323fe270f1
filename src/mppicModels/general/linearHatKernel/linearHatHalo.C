/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "linearHatHalo.H"
#include "cellFaceGeometry.H"
#include "cyclicPolyPatch.H"
#include "processorPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::linearHatHalo::globalAcross
(
    const label celli,
    const label facei
) const
{
    if (mesh_.isInternalFace(facei))
    {
        return toGlobal(cellFaceGeometry::cellAcross(mesh_, celli, facei));
    }

    const label patchi = mesh_.boundaryMesh().whichPatch(facei);
    const polyPatch& pp = mesh_.boundaryMesh()[patchi];
    const label patchFacei = facei - pp.start();

    if (isHaloPatch(patchi))
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


void Foam::linearHatHalo::setPatchNeighbours()
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();

    DynamicList<label> haloPatches;
    labelHashSet neighbours;
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        if (!isA<processorPolyPatch>(pp) || isA<processorCyclicPolyPatch>(pp))
        {
            continue;
        }

        // The exchanges send one list per neighbouring processor
        const label nbrProc =
            refCast<const processorPolyPatch>(pp).neighbProcNo();
        if (!neighbours.insert(nbrProc))
        {
            FatalErrorInFunction
                << "Two processor patches of processor "
                << Pstream::myProcNo() << " face processor " << nbrProc
                << " (patch " << pp.name() << "): the linear-hat kernel "
                << "expects one per neighbour" << exit(FatalError);
        }
        haloPatches.append(patchi);
    }
    haloPatches_.transfer(haloPatches);

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (const label patchi : haloPatches_)
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

    for (const label patchi : haloPatches_)
    {
        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>(patches[patchi]);
        UIPstream fromNbr(pp.neighbProcNo(), buffers);
        fromNbr >> patchNeighbours_[patchi];
    }
}


void Foam::linearHatHalo::setRemoteFaces()
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (const label patchi : haloPatches_)
    {
        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>(patches[patchi]);
        const labelUList& faceCells = pp.faceCells();

        List<vectorField> normals(faceCells.size());
        labelListList across(faceCells.size());
        forAll(faceCells, i)
        {
            const label celli = faceCells[i];
            const labelList& cellFaces = mesh_.cells()[celli];
            normals[i].setSize(cellFaces.size());
            across[i].setSize(cellFaces.size());
            forAll(cellFaces, j)
            {
                normals[i][j] =
                    cellFaceGeometry::outwardNormal(mesh_, celli, cellFaces[j]);
                across[i][j] = globalAcross(celli, cellFaces[j]);
            }
        }
        UOPstream toNbr(pp.neighbProcNo(), buffers);
        toNbr << normals << across;
    }
    buffers.finishedSends();

    DynamicList<vectorField> remoteNormals;
    DynamicList<labelList> remoteAcross;
    for (const label patchi : haloPatches_)
    {
        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>(patches[patchi]);
        UIPstream fromNbr(pp.neighbProcNo(), buffers);
        List<vectorField> normals(fromNbr);
        labelListList across(fromNbr);

        forAll(normals, i)
        {
            if (remoteIndex_.insert(patchNeighbours_[patchi][i], remoteNormals.size()))
            {
                remoteNormals.append(normals[i]);
                remoteAcross.append(across[i]);
            }
        }
    }
    remoteNormals_.transfer(remoteNormals);
    remoteAcross_.transfer(remoteAcross);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearHatHalo::linearHatHalo(const fvMesh& mesh)
:
    mesh_(mesh),
    globalCells_(mesh.nCells()),
    haloPatches_(),
    patchNeighbours_(mesh.boundaryMesh().size()),
    remoteIndex_(),
    remoteNormals_(),
    remoteAcross_(),
    slotOf_(),
    sendCells_(Pstream::nProcs()),
    slotsFrom_(Pstream::nProcs())
{
    if (Pstream::parRun())
    {
        setPatchNeighbours();
        setRemoteFaces();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::linearHatHalo::remoteFaces
(
    const label globali,
    const vectorField*& normals,
    const labelList*& across
) const
{
    const auto iter = remoteIndex_.cfind(globali);
    if (!iter.found())
    {
        return false;
    }
    normals = &remoteNormals_[*iter];
    across = &remoteAcross_[*iter];
    return true;
}


Foam::label Foam::linearHatHalo::slot(const label globali)
{
    const auto iter = slotOf_.cfind(globali);
    if (iter.found())
    {
        return *iter;
    }
    const label newSlot = slotOf_.size();
    slotOf_.insert(globali, newSlot);
    return newSlot;
}


void Foam::linearHatHalo::finalise()
{
    if (!Pstream::parRun())
    {
        return;
    }

    // The slots grouped by the processor owning their cells, in slot order
    labelList globalOfSlot(slotOf_.size());
    forAllConstIters(slotOf_, iter)
    {
        globalOfSlot[*iter] = iter.key();
    }

    List<DynamicList<label>> requests(Pstream::nProcs());
    List<DynamicList<label>> slots(Pstream::nProcs());
    forAll(globalOfSlot, s)
    {
        const label proci = globalCells_.whichProcID(globalOfSlot[s]);
        requests[proci].append(globalCells_.toLocal(proci, globalOfSlot[s]));
        slots[proci].append(s);
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(requests, proci)
    {
        slotsFrom_[proci].transfer(slots[proci]);
        if (requests[proci].size())
        {
            UOPstream toOwner(proci, buffers);
            toOwner << labelList(requests[proci]);
        }
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);

    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            UIPstream fromNbr(proci, buffers);
            fromNbr >> sendCells_[proci];
        }
    }
}


// ************************************************************************* //
