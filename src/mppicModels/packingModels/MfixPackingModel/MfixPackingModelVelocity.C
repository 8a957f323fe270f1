/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Where the packing models write a parcel's velocity: once a step, at
    once without conserveMomentum, at the end of the step with it (see the
    class description).

\*---------------------------------------------------------------------------*/

#include "MfixPackingModel.H"

// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::PackingModels::MfixPackingModel<CloudType>::keepAfterTrack
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


template<class CloudType>
template<class Limit>
void Foam::PackingModels::MfixPackingModel<CloudType>::applyReactions
(
    const Limit& limit
)
{
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
