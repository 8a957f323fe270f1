/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    ParcelEntries in parallel (included by ParcelEntries.H): what the
    processors exchange in a step.
    1. shareDepartures: the records of the parcels that moved to another
       processor (with their cells' centres and faces), received as the
       origins of the parcels that arrived;
    2. returnRefused: the refused parcels that go back to a cell on
       another processor, until no processor sends any;
    3. shareHeld: the held state of the cells they go back to.
    Every processor sends to every other, so that a parcel that crossed
    several processors in one move is still found; the lists hold only
    the parcels that crossed a processor face in this step.

\*---------------------------------------------------------------------------*/

#include "PstreamBuffers.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::ParcelEntries<CloudType>::shareDepartures
(
    const fvMesh& mesh,
    const boolList& matched
)
{
    // The records no parcel here matched: the parcel left this processor
    // (or the domain) in the intermediate move
    DynamicList<label> departed;
    forAll(matched, recordi)
    {
        if (!matched[recordi])
        {
            departed.append(recordi);
        }
    }

    List<labelPair> keys(departed.size());
    departedFrom_.setSize(departed.size());
    pointField centres(departed.size());
    List<pointField> faceCentres(departed.size());
    List<vectorField> faceNormals(departed.size());
    forAll(departed, i)
    {
        const record& r = lastCells_[departed[i]];
        keys[i] = r.key;
        departedFrom_[i] = r.cell;
        centres[i] = mesh.cellCentres()[r.cell];
        cellFaceGeometry::faces cell = cellFaceGeometry::cellFaces(mesh, r.cell);
        faceCentres[i].transfer(cell.centres);
        faceNormals[i].transfer(cell.normals);
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci != Pstream::myProcNo())
        {
            UOPstream send(proci, buffers);
            send<< keys << departedFrom_ << centres << faceCentres
                << faceNormals;
        }
    }
    buffers.finishedSends();

    DynamicList<origin> origins;
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        UIPstream receive(proci, buffers);
        List<labelPair> theirKeys(receive);
        labelList theirCells(receive);
        pointField theirCentres(receive);
        List<pointField> theirFaceCentres(receive);
        List<vectorField> theirFaceNormals(receive);

        forAll(theirKeys, i)
        {
            originIndex_.set(theirKeys[i], origins.size());
            origins.append
            (
                origin
                {
                    proci,
                    theirCells[i],
                    theirCentres[i],
                    {theirFaceCentres[i], theirFaceNormals[i]}
                }
            );
        }
    }
    origins_.transfer(origins);
}


template<class CloudType>
bool Foam::ParcelEntries<CloudType>::returnRefused
(
    List<DynamicList<entrant>>& refused,
    scalarField& keptVolume,
    const List<DynamicList<entrant>>& entrants,
    DynamicList<label>& pending
)
{
    bool sent = false;

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        labelList cells(refused[proci].size());
        scalarList volumes(refused[proci].size());
        forAll(refused[proci], i)
        {
            cells[i] = origins_[refused[proci][i].remote].cell;
            volumes[i] = refused[proci][i].volume;
        }
        sent = sent || cells.size();
        refused[proci].clear();

        UOPstream send(proci, buffers);
        send<< cells << volumes;
    }
    buffers.finishedSends();

    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        UIPstream receive(proci, buffers);
        const labelList cells(receive);
        const scalarList volumes(receive);
        forAll(cells, i)
        {
            const label celli = cells[i];
            keptVolume[celli] += volumes[i];
            returnedVolume_[celli] += volumes[i];
            returnedLargest_[celli] = max(returnedLargest_[celli], volumes[i]);
            if (entrants[celli].size())
            {
                pending.append(celli);
            }
        }
    }

    reduce(sent, orOp<bool>());
    return sent;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::ParcelEntries<CloudType>::shareHeld(const boolList& heldCells)
{
    if (!Pstream::parRun())
    {
        return;
    }

    // Each processor's answer for its departed records, in the order it
    // sent them, which is the order of the origins received from it
    boolList mine(departedFrom_.size());
    forAll(departedFrom_, i)
    {
        mine[i] = heldCells[departedFrom_[i]];
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci != Pstream::myProcNo())
        {
            UOPstream send(proci, buffers);
            send<< mine;
        }
    }
    buffers.finishedSends();

    originHeld_.setSize(origins_.size());
    label origini = 0;
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        UIPstream receive(proci, buffers);
        const boolList theirs(receive);
        for (const bool held : theirs)
        {
            originHeld_[origini++] = held;
        }
    }
}


// ************************************************************************* //
