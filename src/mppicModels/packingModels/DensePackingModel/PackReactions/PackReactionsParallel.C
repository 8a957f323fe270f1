/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    PackReactions across processors: the records of parcels that changed
    processor, and the packs on other processors (see PackReactions.H).

\*---------------------------------------------------------------------------*/

#include "PackReactions.H"
#include "PstreamBuffers.H"
#include "UIndirectList.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
template<class Type>
void Foam::PackReactions<CloudType>::gatherDeparted
(
    const HashSet<labelPair, labelPair::Hash<>>& here,
    HashTable<Type, labelPair, labelPair::Hash<>>& records
)
{
    // The records of parcels no longer here, in key order
    const label me = Pstream::myProcNo();
    List<List<labelPair>> keys(Pstream::nProcs());
    List<List<Type>> values(Pstream::nProcs());
    {
        DynamicList<labelPair> departed;
        DynamicList<Type> departedValues;
        for (const labelPair& key : records.sortedToc())
        {
            if (!here.found(key))
            {
                departed.append(key);
                departedValues.append(records[key]);
                records.erase(key);
            }
        }
        keys[me].transfer(departed);
        values[me].transfer(departedValues);
    }

    Pstream::gatherList(keys);
    Pstream::scatterList(keys);
    Pstream::gatherList(values);
    Pstream::scatterList(values);

    forAll(keys, proci)
    {
        if (proci == me)
        {
            continue;
        }
        forAll(keys[proci], i)
        {
            if (here.found(keys[proci][i]))
            {
                records.set(keys[proci][i], values[proci][i]);
            }
        }
    }
}


template<class CloudType>
void Foam::PackReactions<CloudType>::gatherDeparted(const CloudType& cloud)
{
    HashSet<labelPair, labelPair::Hash<>> here;
    for (const parcelType& p : cloud)
    {
        here.insert(labelPair(p.origProc(), p.origId()));
    }

    gatherDeparted(here, turned_);
    gatherDeparted(here, given_);
}


template<class CloudType>
void Foam::PackReactions<CloudType>::sendRemoteImpulses
(
    const coupledCellNeighbours& cells,
    const UList<label>& pack,
    const UList<scalar>& mass,
    const UList<vector>& impulse,
    scalarField& incomingMass,
    vectorField& packImpulse
)
{
    List<DynamicList<label>> toProc(Pstream::nProcs());
    forAll(pack, i)
    {
        toProc[cells.whichProcID(pack[i])].append(i);
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(toProc, proci)
    {
        const DynamicList<label>& sent = toProc[proci];
        if (sent.empty())
        {
            continue;
        }
        labelList packCells(sent.size());
        scalarList sentMass(sent.size());
        vectorField sentImpulse(sent.size());
        forAll(sent, k)
        {
            packCells[k] = cells.globalCells().toLocal(proci, pack[sent[k]]);
            sentMass[k] = mass[sent[k]];
            sentImpulse[k] = impulse[sent[k]];
        }
        UOPstream toOwner(proci, buffers);
        toOwner << packCells << sentMass << sentImpulse;
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);

    askedBy_.setSize(Pstream::nProcs());
    forAll(recvSizes, proci)
    {
        askedBy_[proci].clear();
        if (recvSizes[proci])
        {
            UIPstream fromNbr(proci, buffers);
            const labelList packCells(fromNbr);
            const scalarList receivedMass(fromNbr);
            const vectorField receivedImpulse(fromNbr);
            forAll(packCells, k)
            {
                incomingMass[packCells[k]] += receivedMass[k];
                packImpulse[packCells[k]] += receivedImpulse[k];
            }
            askedBy_[proci] = packCells;
        }
    }
}


template<class CloudType>
Foam::scalarList Foam::PackReactions<CloudType>::remoteKept
(
    const coupledCellNeighbours& cells,
    const UList<label>& pack,
    const scalarField& kept
)
{
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(askedBy_, proci)
    {
        if (askedBy_[proci].size())
        {
            UOPstream toNbr(proci, buffers);
            toNbr << scalarList(UIndirectList<scalar>(kept, askedBy_[proci]));
        }
    }
    buffers.finishedSends();
    askedBy_.clear();

    // In the order sendRemoteImpulses sent the packs
    List<DynamicList<label>> toProc(Pstream::nProcs());
    forAll(pack, i)
    {
        toProc[cells.whichProcID(pack[i])].append(i);
    }

    scalarList keptThere(pack.size(), Zero);
    forAll(toProc, proci)
    {
        if (toProc[proci].size())
        {
            UIPstream fromOwner(proci, buffers);
            const scalarList received(fromOwner);
            forAll(received, k)
            {
                keptThere[toProc[proci][k]] = received[k];
            }
        }
    }
    return keptThere;
}


// ************************************************************************* //
