/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "PackReactions.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::PackReactions<CloudType>::record
(
    const parcelType& p,
    const label packCell,
    const vector& dU
)
{
    turned_.set
    (
        labelPair(p.origProc(), p.origId()),
        Tuple2<label, vector>(packCell, dU)
    );
}


template<class CloudType>
template<class Report>
void Foam::PackReactions<CloudType>::apply
(
    CloudType& cloud,
    const Report& report
)
{
    if (turned_.empty())
    {
        return;
    }

    const label nCells = cloud.mesh().nCells();

    // Mass turned by each pack, and mass of the pack itself (its parcels
    // at the end of the step, less any it turned)
    scalarField incomingMass(nCells, Zero);
    scalarField packMass(nCells, Zero);
    vectorField packImpulse(nCells, Zero);

    for (const parcelType& p : cloud)
    {
        const scalar m = p.nParticle()*p.mass();
        const auto iter = turned_.cfind(labelPair(p.origProc(), p.origId()));

        if (iter.found())
        {
            const label packCell = iter().first();
            incomingMass[packCell] += m;
            packImpulse[packCell] += m*iter().second();
            if (packCell == p.cell())
            {
                continue;
            }
        }
        packMass[p.cell()] += m;
    }

    // Share of its impulse each turned parcel keeps
    scalarField kept(nCells, Zero);
    forAll(kept, celli)
    {
        if (packMass[celli] > 0)
        {
            kept[celli] =
                packMass[celli]/(packMass[celli] + incomingMass[celli]);
        }
    }

    for (parcelType& p : cloud)
    {
        const auto iter = turned_.cfind(labelPair(p.origProc(), p.origId()));

        vector dU = Zero;
        if (iter.found())
        {
            const label packCell = iter().first();
            dU = -(1 - kept[packCell])*iter().second();

            if (packCell == p.cell())
            {
                p.U() += dU;
                report(p, dU);
                continue;
            }
        }

        const label celli = p.cell();
        if (packMass[celli] > 0)
        {
            dU -= kept[celli]*packImpulse[celli]/packMass[celli];
        }
        p.U() += dU;
        report(p, dU);
    }

    turned_.clear();
}


// ************************************************************************* //
