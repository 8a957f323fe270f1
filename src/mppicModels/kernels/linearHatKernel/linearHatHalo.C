/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "linearHatHalo.H"
#include "cellFaceGeometry.H"
#include "processorPolyPatch.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::linearHatHalo::setRemoteFaces()
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (const label patchi : neighbours_.processorPatches())
    {
        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>(patches[patchi]);
            List<vectorField> normals;
        labelListList across;
        faces(pp.faceCells(), normals, across);
        UOPstream toNbr(pp.neighbProcNo(), buffers);
        toNbr << normals << across;
    }
    buffers.finishedSends();

    for (const label patchi : neighbours_.processorPatches())
    {
        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>(patches[patchi]);
        UIPstream fromNbr(pp.neighbProcNo(), buffers);
        const List<vectorField> normals(fromNbr);
        const labelListList across(fromNbr);

        labelList cells(pp.size());
        forAll(cells, facei)
        {
            cells[facei] =
                neighbours_.across(pp.faceCells()[facei], pp.start() + facei);
        }
        addRemote(cells, normals, across);
    }
}


void Foam::linearHatHalo::faces
(
    const labelUList& cells,
    List<vectorField>& normals,
    labelListList& across
) const
{
    normals.setSize(cells.size());
    across.setSize(cells.size());
    forAll(cells, i)
    {
        const label celli = cells[i];
        const labelList& cellFaces = mesh_.cells()[celli];
        normals[i].setSize(cellFaces.size());
        across[i].setSize(cellFaces.size());
        forAll(cellFaces, j)
        {
            normals[i][j] =
                cellFaceGeometry::outwardNormal(mesh_, celli, cellFaces[j]);
            across[i][j] = neighbours_.across(celli, cellFaces[j]);
        }
    }
}


void Foam::linearHatHalo::addRemote
(
    const labelUList& globalCells,
    const List<vectorField>& normals,
    const labelListList& across
)
{
    label n = remoteNormals_.size();
    remoteNormals_.setSize(n + globalCells.size());
    remoteAcross_.setSize(n + globalCells.size());
    forAll(globalCells, i)
    {
        if (remoteIndex_.insert(globalCells[i], n))
        {
            remoteNormals_[n] = normals[i];
            remoteAcross_[n] = across[i];
            ++n;
        }
    }
    remoteNormals_.setSize(n);
    remoteAcross_.setSize(n);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearHatHalo::linearHatHalo(const fvMesh& mesh)
:
    mesh_(mesh),
    neighbours_(coupledCellNeighbours::New(mesh)),
    remoteIndex_(),
    remoteNormals_(),
    remoteAcross_(),
    slotOf_(),
    sendCells_(Pstream::nProcs()),
    slotsFrom_(Pstream::nProcs())
{
    if (Pstream::parRun())
    {
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


void Foam::linearHatHalo::fetchFaces(const labelUList& globalCells)
{
    if (!Pstream::parRun())
    {
        return;
    }

    // Ask each owner for the faces of its cells ...
    List<DynamicList<label>> requested(Pstream::nProcs());
    for (const label globali : globalCells)
    {
        if (!neighbours_.isLocal(globali) && !remoteIndex_.found(globali))
        {
            requested[neighbours_.whichProcID(globali)].append(globali);
        }
    }

    PstreamBuffers requests(Pstream::commsTypes::nonBlocking);
    forAll(requested, proci)
    {
        if (requested[proci].size())
        {
            UOPstream toOwner(proci, requests);
            toOwner << labelList(requested[proci]);
        }
    }
    labelList recvSizes;
    requests.finishedSends(recvSizes);

    // ... which answers in the order asked
    PstreamBuffers answers(Pstream::commsTypes::nonBlocking);
    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            UIPstream fromNbr(proci, requests);
            labelList cells(fromNbr);
            for (label& celli : cells)
            {
                celli = neighbours_.toLocal(celli);
            }
            List<vectorField> normals;
            labelListList across;
            faces(cells, normals, across);
            UOPstream toNbr(proci, answers);
            toNbr << normals << across;
        }
    }
    answers.finishedSends();

    forAll(requested, proci)
    {
        if (requested[proci].size())
        {
            UIPstream fromOwner(proci, answers);
            const List<vectorField> normals(fromOwner);
            const labelListList across(fromOwner);
            addRemote(requested[proci], normals, across);
        }
    }
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
        const label proci = neighbours_.whichProcID(globalOfSlot[s]);
        requests[proci].append
        (
            neighbours_.globalCells().toLocal(proci, globalOfSlot[s])
        );
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
