/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The velocity a parcel keeps in a packing step, written once in the
    step by one of the two functions below; the models give it through
    keepAfterTrack only:
    1. without conserveMomentum, keepAfterTrack writes U = kept - move at
       once; the correction track (LeanMPPICCloud::correctionTrack in
       mppicPimpleFoam, MPPICParcel's tpCorrectTrack in stock MPPICFoam,
       where the models run too), which moves the parcel by move*dt and
       adds move to U, leaves it kept;
    2. with conserveMomentum, keepAfterTrack records kept, and
       applyReactions writes kept plus the parcel's share of the
       reactions at cacheFields(false), after the track (the reactions
       need every parcel's impulse of the step first: PackReactions). The
       track moves the parcel by the correction alone, whatever its
       velocity.
    A parcel given no kept ends with U + move, the track's sum, plus with
    conserveMomentum its share of the reactions.

\*---------------------------------------------------------------------------*/

#include "DensePackingModel.H"

// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::PackingModels::DensePackingModel<CloudType>::keepAfterTrack
(
    typename CloudType::parcelType& p,
    const vector& kept,
    const vector& move
) const
{
    if (conserveMomentum_)
    {
        reactions_.give(p, kept);
    }
    else
    {
        p.U() = kept - move;
    }
}


// The packs take the step's reactions (PackReactions::apply) and each
// parcel gets its velocity, the change recorded. A held pack whose fall its
// support stopped in this step hands the reactions' part down along gravity
// to the support (CapacityLimit::settledVelocity); with conserveMomentum gas
// any other pack's share goes to the gas of its cell (UTrans, recorded in
// cellGasMomentum)
template<class CloudType>
void Foam::PackingModels::DensePackingModel<CloudType>::applyReactions()
{
    const CapacityLimit<CloudType>& limit = limit_;

    reactions_.apply
    (
        this->owner(),
        [&limit]
        (
            const typename CloudType::parcelType& p,
            const vector& U
        )
        {
            return limit.settledVelocity(p, U);
        },
        [this]
        (
            typename CloudType::parcelType& p,
            const vector& from,
            const vector& U
        )
        {
            this->recordVelocityChange(p, U - from);
            p.U() = U;
        },
        [this, &limit]
        (
            const typename CloudType::parcelType& p,
            const vector& momentum
        )
        {
            // A pack no support holds this step is carried by the gas
            const label celli = p.cell();
            if (!freePackReactionsToGas_ || limit.resting(celli))
            {
                return false;
            }
            this->owner().UTrans()[celli] += momentum;
            cellGasMomentum_[celli] += momentum;
            return true;
        }
    );
}


// ************************************************************************* //
