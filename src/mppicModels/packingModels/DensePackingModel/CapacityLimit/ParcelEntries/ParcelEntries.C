/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "ParcelEntries.H"
#include "cellRoom.H"
#include "coupledPolyPatch.H"
#include "cellFaceGeometry.H"
#include "pushOrderKey.H"
#include <algorithm>

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::ParcelEntries<CloudType>::crossedFace
(
    const fvMesh& mesh,
    const parcelType& p,
    const scalar deltaT,
    vector& normal,
    scalar& depth
)
{
    const label celli = p.cell();
    const point position = p.position();

    label crossed = -1;
    depth = 0;

    for (const label facei : mesh.cells()[celli])
    {
        const bool coupledFace =
            !mesh.isInternalFace(facei)
         && isA<coupledPolyPatch>
            (
                mesh.boundaryMesh()[mesh.boundaryMesh().whichPatch(facei)]
            );

        if (!mesh.isInternalFace(facei) && !coupledFace)
        {
            continue;
        }

        const vector n = cellFaceGeometry::outwardNormal(mesh, celli, facei);

        const scalar Un = p.U() & n;
        if (Un < 0)
        {
            const scalar beyond =
                -Un*deltaT - ((mesh.faceCentres()[facei] - position) & n);

            if (beyond > depth)
            {
                depth = beyond;
                crossed = facei;
                normal = n;
            }
        }
    }

    return crossed;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::ParcelEntries<CloudType>::update
(
    const CloudType& cloud,
    const scalar closePackFraction,
    const scalar deltaT
)
{
    const fvMesh& mesh = cloud.mesh();

    clear();
    scalarField startVolume(mesh.nCells(), Zero);

    // Volume of the parcels that stayed in each cell
    scalarField keptVolume(mesh.nCells(), Zero);

    // Entrants of each cell
    List<DynamicList<entrant>> entrants(mesh.nCells());

    // Parcels that stayed in each cell (pushThrough only)
    List<DynamicList<const parcelType*>> stayers
    (
        pushThrough_ ? mesh.nCells() : 0
    );
    auto stay = [&](const parcelType& p)
    {
        const scalar volume = p.nParticle()*p.volume();
        startVolume[p.cell()] += volume;
        keptVolume[p.cell()] += volume;
        if (pushThrough_)
        {
            stayers[p.cell()].append(&p);
        }
    };

    // Records matched by a parcel here; the others left (for another
    // processor, or through an outlet)
    boolList matched(lastCells_.size(), false);
    label next = 0;
    HashTable<label, labelPair, labelPair::Hash<>> unmatched;
    bool searched = false;

    // A parcel that entered its cell celli from cell from (or, remote >= 0,
    // from a cell on another processor) along direction, depth deep
    auto enter = [&]
    (
        const parcelType& p,
        const label from,
        const label remote,
        const vector& direction,
        const scalar depth
    )
    {
        const scalar volume = p.nParticle()*p.volume();
        entry& e = entries_[&p];
        e.direction = direction;
        e.from = from;
        e.remote = remote;
        entrants[p.cell()].append({&p, depth, volume, from, remote});

        if (from >= 0)
        {
            startVolume[from] += volume;
        }
    };

    // A parcel not recorded: it entered if its velocity carried it across
    // one of its cell's faces in this step
    auto enterOrStay = [&](const parcelType& p)
    {
        const label celli = p.cell();
        vector n;
        scalar depth = 0;
        const label facei = crossedFace(mesh, p, deltaT, n, depth);
        if (facei < 0)
        {
            stay(p);
            return;
        }
        enter
        (
            p,
            mesh.isInternalFace(facei)
          ? cellFaceGeometry::cellAcross(mesh, celli, facei)
          : -1,
            -1,
            -n,
            depth
        );
    };

    // Parcels not recorded here, in parallel: the processor they came from
    // may have recorded them
    DynamicList<const parcelType*> arrived;

    for (const parcelType& p : cloud)
    {
        const label celli = p.cell();

        if (debug)
        {
            stepCells_[&p] = celli;
        }

        const label recordi = findRecord
        (
            labelPair(p.origProc(), p.origId()), next, unmatched, searched
        );
        if (recordi >= 0)
        {
            matched[recordi] = true;
            const label from = lastCells_[recordi].cell;
            if (from == celli)
            {
                stay(p);
                continue;
            }
            vector direction =
                mesh.cellCentres()[celli] - mesh.cellCentres()[from];
            const scalar depth = mag(direction);
            direction /= max(depth, VSMALL);
            enter(p, from, -1, direction, depth);
        }
        else if (Pstream::parRun())
        {
            arrived.append(&p);
        }
        else
        {
            enterOrStay(p);
        }
    }

    forAll(lastCells_, recordi)
    {
        if (!matched[recordi])
        {
            startVolume[lastCells_[recordi].cell] += lastCells_[recordi].volume;
        }
    }

    if (Pstream::parRun())
    {
        shareDepartures(mesh, matched);
        returnedVolume_.setSize(mesh.nCells(), Zero);
        returnedLargest_.setSize(mesh.nCells(), Zero);

        for (const parcelType* pp : arrived)
        {
            const auto iter =
                originIndex_.cfind(labelPair(pp->origProc(), pp->origId()));
            if (!iter.found())
            {
                enterOrStay(*pp);
                continue;
            }
            const origin& o = origins_[iter.val()];
            vector direction = mesh.cellCentres()[pp->cell()] - o.centre;
            const scalar depth = mag(direction);
            direction /= max(depth, VSMALL);
            enter(*pp, -1, iter.val(), direction, depth);
        }
    }

    startFraction_ = startVolume/mesh.V();

    admitUpToClosePack(mesh, closePackFraction, keptVolume, entrants);

    nPushed_ = 0;
    nPushedToward_ = label(0);
    if (pushThrough_)
    {
        nPushed_ = pushRefusedOn
        (
            mesh, closePackFraction, keptVolume, entrants, stayers
        );
    }
}


template<class CloudType>
void Foam::ParcelEntries<CloudType>::admitUpToClosePack
(
    const fvMesh& mesh,
    const scalar closePackFraction,
    scalarField& keptVolume,
    List<DynamicList<entrant>>& entrants
)
{
    // Start from every entrant admitted; a cell refuses those that do not
    // fit (deepest first; of equal depth, as their pushOrderKey ranks them,
    // not the parcel list's order), a refused parcel goes back to the cell
    // it came from, which then has less room: revisit that cell.
    // Admissions only ever turn into refusals, so this ends.
    const label timeIndex = mesh.time().timeIndex();
    DynamicList<label> pending;
    forAll(entrants, celli)
    {
        if (entrants[celli].size())
        {
            std::stable_sort
            (
                entrants[celli].begin(),
                entrants[celli].end(),
                [timeIndex](const entrant& a, const entrant& b)
                {
                    if (a.depth != b.depth)
                    {
                        return a.depth > b.depth;
                    }
                    const parcelType& pa = *a.parcel;
                    const parcelType& pb = *b.parcel;
                    return
                        pushOrderKey(pa.origProc(), pa.origId(), timeIndex)
                      < pushOrderKey(pb.origProc(), pb.origId(), timeIndex);
                }
            );
            for (const entrant& candidate : entrants[celli])
            {
                entries_[candidate.parcel].admitted = true;
            }
            pending.append(celli);
        }
    }

    // Refused parcels that go back to a cell on another processor, by
    // processor; exchanged once no cell here is pending, which may make
    // cells there or here refuse more: until no processor has new ones
    List<DynamicList<entrant>> refusedAway(Pstream::nProcs());

    do
    {
        while (pending.size())
        {
            const label celli = pending.remove();

            // Room up to close pack: a cell takes entrants while it stays
            // within half a parcel above close pack (cellRoom: the parcel
            // count that comes closest to close pack)
            scalar room =
                closePackFraction*mesh.V()[celli] - keptVolume[celli];

            for (const entrant& candidate : entrants[celli])
            {
                entry& e = entries_[candidate.parcel];
                if (!e.admitted)
                {
                    continue;
                }
                if (cellRoom::fits(candidate.volume, room))
                {
                    room -= candidate.volume;
                    continue;
                }

                e.admitted = false;
                const label from = candidate.from;
                if (from >= 0)
                {
                    keptVolume[from] += candidate.volume;
                    if (entrants[from].size())
                    {
                        pending.append(from);
                    }
                }
                else if (candidate.remote >= 0)
                {
                    refusedAway[origins_[candidate.remote].proc].append
                    (
                        candidate
                    );
                }
            }
        }
    }
    while
    (
        Pstream::parRun()
     && returnRefused(refusedAway, keptVolume, entrants, pending)
    );
}


template<class CloudType>
void Foam::ParcelEntries<CloudType>::clear()
{
    stepCells_.clear();
    entries_.clear();
    startFraction_.clear();
    departedFrom_.clear();
    origins_.clear();
    originIndex_.clear();
    originHeld_.clear();
    returnedVolume_.clear();
    returnedLargest_.clear();
}


// ************************************************************************* //
