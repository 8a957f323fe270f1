/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    ParcelEntries' push-through (pushThrough): a full cell that refuses an
    entrant takes it after all when it can pass one of its own parcels on,
    through full cells, to the nearest cell with room (included by
    ParcelEntries.H). A cell takes an entrant only when one of its own
    parcels has left in the same step, and a packed region that moves as
    a whole (a bed lifted from below, an emulsion pushed aside by a
    bubble) has its crossings at different steps in different cells, so
    every cell it moves into refuses and the region could start to move
    only at its free surface. Pushed on, each cell of the chain gives one
    parcel and takes one, and the last cell, which had room, takes one
    more: the packed region moves by one parcel's volume, as an
    incompressible one would.

    After the admissions (admitUpToClosePack), pushRefusedOn:
    1. takes as pushed on only a refused entrant that came out of a full
       cell (a packed region on the move; one from another processor is
       taken as such); one from a cell that had room for it (a parcel
       falling out of a suspension onto a bed) lands on the pack, as
       pushing such parcels on would carry a settling bed's surface up
       and shuffle a bed at rest;
    2. serves the refusing cells in the order of their first refused
       entrant's pushOrderKey (a hash of its identity and the step), not
       in the mesh's numbering, so that a continued or re-ordered run
       chooses the same;
    3. finds the chain by a breadth-first search, level by level (the
       cells as many faces away), from the refusing cell through face
       neighbours (not back into the cell the entrant came from; internal
       faces only: in parallel a chain stays on its processor), through
       cells that have a parcel that stayed in them not yet pushed, to
       the nearest cells with room for the entrant's volume
       (cellRoom::fits: exact for parcels of one size, the pushed parcel
       may be larger); at most maxChainCells cells are visited;
    4. of several equally near cells with room, takes the one the
       entrant's pushOrderKey picks: the entrant's volume goes to the
       nearest room, whichever way, as an incompressible emulsion's would;
    5. down the chain from that cell, has each cell push the parcel that
       stayed in it and lies furthest toward the next cell (level
       parcels, within 1e-9 of the distance between the cells, by their
       lower (origProc, origId)) into it;
    6. admits the entrant, and counts the push toward which of -x, +x,
       -y, +y, -z, +z its room lay.
    In parallel an entrant from another processor pushed on here has been
    counted back in its old cell there for the step (one parcel too many
    there, never too few).

\*---------------------------------------------------------------------------*/

#include "pushOrderKey.H"
#include <algorithm>
#include <vector>

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::ParcelEntries<CloudType>::pushRefusedOn
(
    const fvMesh& mesh,
    const scalar closePackFraction,
    const scalarField& keptVolume,
    const List<DynamicList<entrant>>& entrants,
    List<DynamicList<const parcelType*>>& stayers
)
{
    const label maxChainCells = 400;
    const vectorField& C = mesh.cellCentres();

    // What each cell holds after the admissions
    scalarField load(keptVolume);
    forAll(entrants, celli)
    {
        for (const entrant& candidate : entrants[celli])
        {
            if (entries_[candidate.parcel].admitted)
            {
                load[celli] += candidate.volume;
            }
        }
    }

    // The stayers already pushed on, by cell: the next one to push
    labelList pushed(mesh.nCells(), Zero);

    // Breadth-first search state, reset for the cells visited only
    labelList parent(mesh.nCells(), -2);
    DynamicList<label> visited;
    label nAdmitted = 0;

    auto hasRoom = [&](const label celli, const scalar volume)
    {
        return cellRoom::fits
        (
            volume, closePackFraction*mesh.V()[celli] - load[celli]
        );
    };

    // A refused entrant that came out of a full cell (a packed region
    // moving as a whole; from another processor: its cell's load is not
    // known here, taken as full) is pushed on; one that came from a cell
    // with room for it lands on the pack: a parcel falling out of a
    // suspension onto a bed at rest is refused. (load[from] holds the
    // refused entrant already: admitUpToClosePack sent it back.)
    auto refused = [&](const entrant& candidate)
    {
        if (entries_[candidate.parcel].admitted)
        {
            return false;
        }
        if (candidate.remote >= 0)
        {
            return true;
        }
        const label from = candidate.from;
        return
            from >= 0
         && !cellRoom::fits
            (
                candidate.volume, closePackFraction*mesh.V()[from] - load[from]
            );
    };

    // The refusing cells in an order the mesh's numbering does not set
    // (in the cells' order the lowest-numbered would take the rooms
    // first), by their first refused entrant's pushOrderKey
    const label timeIndex = mesh.time().timeIndex();
    std::vector<std::pair<std::uint64_t, label>> order;
    forAll(entrants, celli)
    {
        for (const entrant& candidate : entrants[celli])
        {
            if (refused(candidate))
            {
                const parcelType& p = *candidate.parcel;
                order.emplace_back
                (
                    pushOrderKey(p.origProc(), p.origId(), timeIndex),
                    celli
                );
                break;
            }
        }
    }
    std::sort(order.begin(), order.end());

    for (const auto& keyCell : order)
    {
        const label celli = keyCell.second;
        for (const entrant& candidate : entrants[celli])
        {
            entry& e = entries_[candidate.parcel];
            // (An entrant from another processor has been counted back in
            // its cell there (returnRefused): admitted here, that cell
            // counts one parcel too many this step, never too few)
            if (!refused(candidate))
            {
                continue;
            }

            // The nearest cell with room ahead, through full cells
            for (const label c : visited)
            {
                parent[c] = -2;
            }
            visited.clear();

            label target = -1;
            if (pushed[celli] < stayers[celli].size())
            {
                // Level by level (a level: the cells as many faces away),
                // so that every cell with room in the nearest level is seen
                DynamicList<label> front;
                DynamicList<label> rooms;
                parent[celli] = -1;
                visited.append(celli);
                front.append(celli);
                label levelStart = 0;
                while (levelStart < front.size() && rooms.empty())
                {
                    const label levelEnd = front.size();
                    for (label i = levelStart; i < levelEnd; ++i)
                    {
                        const label c = front[i];
                        for (const label facei : mesh.cells()[c])
                        {
                            if (!mesh.isInternalFace(facei))
                            {
                                continue;
                            }
                            const label n =
                                mesh.faceOwner()[facei] == c
                              ? mesh.faceNeighbour()[facei]
                              : mesh.faceOwner()[facei];
                            if (parent[n] != -2 || n == candidate.from)
                            {
                                continue;
                            }

                            if (hasRoom(n, candidate.volume))
                            {
                                parent[n] = c;
                                visited.append(n);
                                rooms.append(n);
                            }
                            else if
                            (
                                rooms.empty()
                             && pushed[n] < stayers[n].size()
                             && visited.size() < maxChainCells
                            )
                            {
                                parent[n] = c;
                                visited.append(n);
                                front.append(n);
                            }
                        }
                    }
                    levelStart = levelEnd;
                }

                // Of the nearest cells with room, the one the entrant's
                // pushOrderKey picks, not the first found (the
                // lowest-numbered neighbour, a preferred direction)
                if (rooms.size())
                {
                    const parcelType& p = *candidate.parcel;
                    target = rooms
                    [
                        pushOrderKey(p.origProc(), p.origId(), timeIndex)
                      % static_cast<std::uint64_t>(rooms.size())
                    ];
                }
            }
            if (target < 0)
            {
                continue;
            }
            const vector toRoom(C[target] - C[celli]);
            direction axis = 0;
            for (direction i = 1; i < vector::nComponents; ++i)
            {
                axis = mag(toRoom[i]) > mag(toRoom[axis]) ? i : axis;
            }
            ++nPushedToward_[2*axis + (toRoom[axis] > 0)];

            // Down the chain from the target: each cell pushes one of its
            // stayers, the one furthest toward the next cell, into it
            label to = target;
            while (parent[to] >= 0)
            {
                const label c = parent[to];
                vector d = C[to] - C[c];
                const scalar tie = 1e-9*mag(d);
                d /= max(mag(d), VSMALL);

                // The stayers of c not yet pushed are at the back of the
                // list from pushed[c] on: bring the one furthest along d
                // there, and take it. Pushed parcels sit at one distance
                // from the face they were pushed through, so several can
                // be level: within 1e-9 of the step between the cells the
                // lower (origProc, origId) goes, not the last bit of a
                // position (which a re-tracking or a restart changes)
                DynamicList<const parcelType*>& ahead = stayers[c];
                label best = pushed[c];
                for (label k = pushed[c] + 1; k < ahead.size(); ++k)
                {
                    const scalar further =
                        (ahead[k]->position() - ahead[best]->position()) & d;
                    if
                    (
                        further > tie
                     || (
                            further > -tie
                         && labelPair
                            (
                                ahead[k]->origProc(), ahead[k]->origId()
                            )
                          < labelPair
                            (
                                ahead[best]->origProc(), ahead[best]->origId()
                            )
                        )
                    )
                    {
                        best = k;
                    }
                }
                Swap(ahead[best], ahead[pushed[c]]);
                const parcelType* q = ahead[pushed[c]++];

                entry& qe = entries_[q];
                qe.direction = d;
                qe.admitted = true;
                qe.from = c;
                qe.pushedTo = to;

                const scalar volume = q->nParticle()*q->volume();
                load[c] -= volume;
                load[to] += volume;
                to = c;
            }

            // The refusing cell now has the room the entrant needs
            e.admitted = true;
            load[celli] += candidate.volume;
            if (candidate.from >= 0)
            {
                load[candidate.from] -= candidate.volume;
            }
            ++nAdmitted;
        }
    }

    return nAdmitted;
}


// ************************************************************************* //
