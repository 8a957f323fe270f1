/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    ParcelEntries::reportGrowth: the diagnostic report of the cells that
    grew above close pack in a step and how their parcels got there.

\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::ParcelEntries<CloudType>::reportGrowth
(
    const CloudType& cloud,
    const scalar closePackFraction
) const
{
    const fvMesh& mesh = cloud.mesh();
    scalarField endVolume(mesh.nCells(), Zero);
    for (const parcelType& p : cloud)
    {
        endVolume[p.cell()] += p.nParticle()*p.volume();
    }
    const scalarField endFraction(endVolume/mesh.V());

    auto grew = [&](const label celli)
    {
        const scalar tolerance = cellRoom::roundOff*closePackFraction;
        return
            endFraction[celli] > closePackFraction + tolerance
         && endFraction[celli] > startFraction_[celli] + tolerance;
    };

    label nCells = 0;
    forAll(endFraction, celli)
    {
        nCells += grew(celli);
    }
    if (!nCells)
    {
        return;
    }

    label admitted = 0, refusedStayed = 0, returned = 0, movedIn = 0;
    for (const parcelType& p : cloud)
    {
        if (!grew(p.cell()))
        {
            continue;
        }
        const entry* e = find(p);
        const auto step = stepCells_.find(&p);
        const label stepCell = step == stepCells_.end() ? -1 : step->second;

        if (stepCell == p.cell())
        {
            if (e && e->admitted) ++admitted;
            else if (e) ++refusedStayed;
        }
        else if (e && !e->admitted && e->from == p.cell())
        {
            ++returned;
        }
        else
        {
            ++movedIn;
            Pout<< "ParcelEntries: parcel " << p.origId() << " moved by the"
                << " correction from cell " << stepCell << " into cell "
                << p.cell() << (e ? " (an entrant" : " (not an entrant")
                << (e && e->admitted ? ", admitted" : "")
                << ", from " << (e ? e->from : -2)
                << ") at " << p.position() << " U " << p.U()
                << " UCorrect " << p.UCorrect() << endl;
        }
    }

    Pout<< "ParcelEntries: " << nCells << " cells grew above close pack;"
        << " their parcels: admitted " << admitted << ", refused but stayed "
        << refusedStayed << ", returned " << returned << ", moved in by the"
        << " correction " << movedIn << endl;
}


// ************************************************************************* //
