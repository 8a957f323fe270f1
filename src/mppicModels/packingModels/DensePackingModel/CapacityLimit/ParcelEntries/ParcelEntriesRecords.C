/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    ParcelEntries' record of where each parcel was after the last packing
    step, and the walk that finds a parcel's record (included by
    ParcelEntries.H).

\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::ParcelEntries<CloudType>::findRecord
(
    const labelPair& key,
    label& next,
    HashTable<label, labelPair, labelPair::Hash<>>& unmatched,
    bool& searched
) const
{
    // The common case: the next record is this parcel's
    if (next < lastCells_.size() && lastCells_[next].key == key)
    {
        return next++;
    }

    // A parcel left before this one, or this one is new here, or came back
    // from another processor: search the records not yet passed
    if (!searched)
    {
        for (label recordi = next; recordi < lastCells_.size(); ++recordi)
        {
            unmatched.set(lastCells_[recordi].key, recordi);
        }
        searched = true;
    }

    const auto iter = unmatched.cfind(key);
    if (!iter.found())
    {
        return -1;
    }
    const label recordi = iter.val();
    unmatched.erase(key);
    if (recordi >= next)
    {
        next = recordi + 1;
    }
    return recordi;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //


template<class CloudType>
void Foam::ParcelEntries<CloudType>::recordCells
(
    const CloudType& cloud,
    const bool agedOnly
)
{
    lastCells_.clear();
    lastCells_.setCapacity(cloud.size());

    for (const parcelType& p : cloud)
    {
        if (agedOnly && p.age() <= 0)
        {
            continue;
        }
        lastCells_.append
        (
            record
            {
                labelPair(p.origProc(), p.origId()),
                p.cell(),
                p.nParticle()*p.volume()
            }
        );
    }
}


// ************************************************************************* //
