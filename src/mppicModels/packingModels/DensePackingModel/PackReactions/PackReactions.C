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
void Foam::PackReactions<CloudType>::give
(
    const parcelType& p,
    const vector& U
)
{
    given_.set(labelPair(p.origProc(), p.origId()), U);
}


template<class CloudType>
template<class Settle, class Write, class ToGas>
void Foam::PackReactions<CloudType>::apply
(
    CloudType& cloud,
    const Settle& settle,
    const Write& write,
    const ToGas& toGas
)
{
    const bool anyTurned = returnReduce(turned_.size(), sumOp<label>()) > 0;
    if (!anyTurned && !returnReduce(given_.size(), sumOp<label>()))
    {
        return;
    }

    if (Pstream::parRun())
    {
        gatherDeparted(cloud);
    }

    // A parcel's velocity before its share: the one the model gave it
    const auto given = [this](const parcelType& p)
    {
        const auto iter = given_.cfind(labelPair(p.origProc(), p.origId()));
        return iter.found() ? *iter : p.U();
    };

    if (!anyTurned)
    {
        for (parcelType& p : cloud)
        {
            const auto iter =
                given_.cfind(labelPair(p.origProc(), p.origId()));
            if (iter.found())
            {
                write(p, *iter, *iter);
            }
        }
        given_.clear();
        return;
    }

    const fvMesh& mesh = cloud.mesh();
    const coupledCellNeighbours& cells = coupledCellNeighbours::New(mesh);
    const label nCells = mesh.nCells();

    // Mass turned by each pack, and mass of the pack itself (its parcels
    // at the end of the step, less any it turned)
    scalarField incomingMass(nCells, Zero);
    scalarField packMass(nCells, Zero);
    vectorField packImpulse(nCells, Zero);

    // The same for the packs on other processors, by their global index
    Map<label> remoteIndex;
    DynamicList<label> remotePack;
    DynamicList<scalar> remoteMass;
    DynamicList<vector> remoteImpulse;

    for (const parcelType& p : cloud)
    {
        const scalar m = p.nParticle()*p.mass();
        const auto iter = turned_.cfind(labelPair(p.origProc(), p.origId()));

        if (iter.found())
        {
            const label pack = iter().first();
            if (cells.isLocal(pack))
            {
                const label packCell = cells.toLocal(pack);
                incomingMass[packCell] += m;
                packImpulse[packCell] += m*iter().second();
                if (packCell == p.cell())
                {
                    continue;
                }
            }
            else
            {
                if (remoteIndex.insert(pack, remotePack.size()))
                {
                    remotePack.append(pack);
                    remoteMass.append(0);
                    remoteImpulse.append(Zero);
                }
                const label i = remoteIndex[pack];
                remoteMass[i] += m;
                remoteImpulse[i] += m*iter().second();
            }
        }
        packMass[p.cell()] += m;
    }

    if (Pstream::parRun())
    {
        sendRemoteImpulses
        (
            cells,
            remotePack,
            remoteMass,
            remoteImpulse,
            incomingMass,
            packImpulse
        );
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

    const scalarList keptThere
    (
        Pstream::parRun() ? remoteKept(cells, remotePack, kept) : scalarList()
    );

    for (parcelType& p : cloud)
    {
        const auto iter = turned_.cfind(labelPair(p.origProc(), p.origId()));
        const vector U0(given(p));

        vector dU = Zero;
        if (iter.found())
        {
            const label pack = iter().first();
            const bool here = cells.isLocal(pack);
            const scalar f =
                here
              ? kept[cells.toLocal(pack)]
              : keptThere[remoteIndex[pack]];
            dU = -(1 - f)*iter().second();

            if (here && cells.toLocal(pack) == p.cell())
            {
                write(p, U0, settle(p, U0 + dU));
                continue;
            }
        }

        // The parcel's share of its own pack's reaction, unless the gas of
        // its cell takes it
        const label celli = p.cell();
        if (packMass[celli] > 0)
        {
            const vector share =
                kept[celli]*packImpulse[celli]/packMass[celli];
            if (!toGas(p, -p.nParticle()*p.mass()*share))
            {
                dU -= share;
            }
        }
        write(p, U0, settle(p, U0 + dU));
    }

    turned_.clear();
    given_.clear();
}


// ************************************************************************* //
