/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "ColoringFunction.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

template<class CloudType>
const Foam::Enum
<
    typename Foam::PackingModels::ColoringFunction<CloudType>::impulseType
>
Foam::PackingModels::ColoringFunction<CloudType>::impulseTypeNames
({
    { impulseType::gradient, "gradient" },
    { impulseType::faceGradient, "faceGradient" },
    { impulseType::cornerNodeGradient, "cornerNodeGradient" },
    { impulseType::neighbour, "neighbour" },
});


template<class CloudType>
const Foam::wordList
Foam::PackingModels::ColoringFunction<CloudType>::keywords
({
    "closePackFraction", "e1", "e2", "case1a", "case1b",
    "reflection", "impulse", "holdSupportedPacks"
});

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PackingModels::ColoringFunction<CloudType>::ColoringFunction
(
    const dictionary& dict,
    CloudType& owner
)
:
    MfixPackingModel<CloudType>(dict, owner, typeName, keywords),
    rules_(this->coeffs()),
    impulse_
    (
        impulseTypeNames.lookupOrDefault
        (
            "impulse",
            this->coeffs(),
            impulseType::neighbour
        )
    ),
    capacityLimit_(CapacityLimit<CloudType>::mode(this->coeffs()) != "none"),
    limit_
    (
        owner.mesh(),
        this->coeffs(),
        capacityLimit_
     && this->coeffs().lookupOrDefault("holdSupportedPacks", true)
    )
{}


template<class CloudType>
Foam::PackingModels::ColoringFunction<CloudType>::ColoringFunction
(
    const ColoringFunction<CloudType>& cm
)
:
    MfixPackingModel<CloudType>(cm),
    rules_(cm.rules_),
    impulse_(cm.impulse_),
    capacityLimit_(cm.capacityLimit_),
    limit_(cm.limit_)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
typename Foam::PackingModels::ColoringFunction<CloudType>::packState
Foam::PackingModels::ColoringFunction<CloudType>::packFor
(
    const typename CloudType::parcelType& p
) const
{
    packState pack;

    if (impulse_ == impulseType::gradient)
    {
        pack.impulse = -this->packingGradAt(p);
        pack.uMean = this->uMeanAt(p);
        pack.cell = this->globalCell(p);
        return pack;
    }

    if (impulse_ != impulseType::neighbour)
    {
        pack.impulse =
            impulse_ == impulseType::faceGradient
          ? -this->faceGradientAt(p)
          : -this->cornerNodeFaceGradientAt(p);
        pack.uMean = this->uMeanAt(p);
        pack.cell = this->globalCell(p);
        return pack;
    }

    // A parcel that moved into its cell in this step and may not stay:
    // the pack is its own cell, along the way it came in
    const typename ParcelEntries<CloudType>::entry* entered =
        limit_.entries().find(p);

    if (entered)
    {
        const scalar cellValue = this->cellValue(p.cell());

        const bool blocked =
            capacityLimit_ ? !entered->admitted : cellValue > 0;

        if (blocked)
        {
            pack.impulse =
                -max(cellValue, rules_.closePackFraction())
                *entered->direction;
            pack.uMean = this->cellUMean(p.cell());
            pack.cell = this->globalCell(p);
            pack.closePacked = cellValue > 0;
            return pack;
        }
    }

    // The cell ahead: when close packed, the pack lies along the normal
    const typename MfixPackingModel<CloudType>::neighbourState ahead =
        this->neighbourAhead(p);

    pack.impulse = -ahead.value*ahead.normal;
    pack.uMean = ahead.found ? ahead.uMean : this->uMeanAt(p);
    pack.cell = ahead.found ? ahead.cell : this->globalCell(p);
    return pack;
}


template<class CloudType>
Foam::tmp<Foam::scalarField>
Foam::PackingModels::ColoringFunction<CloudType>::cellPackingValues() const
{
    if (!capacityLimit_ || impulse_ != impulseType::neighbour)
    {
        return MfixPackingModel<CloudType>::cellPackingValues();
    }

    tmp<scalarField> tvalues(new scalarField(limit_.entries().startFraction()));
    for (scalar& value : tvalues.ref())
    {
        value = rules_.colour(value);
    }
    return tvalues;
}


template<class CloudType>
void Foam::PackingModels::ColoringFunction<CloudType>::recordChange
(
    const typename CloudType::parcelType& p,
    const vector& dU,
    const label packCell
) const
{
    this->recordVelocityChange(p, dU);

    if (this->conserveMomentum() && packCell >= 0 && magSqr(dU) > 0)
    {
        this->recordReaction(p, packCell, dU);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::PackingModels::ColoringFunction<CloudType>::beforeMotion()
{
    // Nothing recorded yet while parcels that have moved before (age > 0)
    // are in the cloud: they were read from a written time. Record where
    // they are, which is where the uninterrupted run's last step left them
    // (the parcels injected since, of age 0, were not there then)
    if (impulse_ == impulseType::neighbour)
    {
        limit_.beforeMotion(this->owner());
    }
}


template<class CloudType>
void Foam::PackingModels::ColoringFunction<CloudType>::cacheFields
(
    const bool store
)
{
    if (store && impulse_ == impulseType::neighbour)
    {
        limit_.setDebug(debug);
        limit_.startStep
        (
            this->owner(),
            rules_.closePackFraction(),
            this->owner().db().time().deltaTValue()
        );
    }
    else
    {
        if (debug && impulse_ == impulseType::neighbour)
        {
            limit_.entries().reportGrowth
            (
                this->owner(),
                rules_.closePackFraction()
            );
        }

        // End of the packing step: the packs take their impulses back; a
        // held pack whose fall the support stopped in this step hands the
        // part down along gravity to it (CapacityLimit::settledVelocity)
        if (this->conserveMomentum())
        {
            this->applyReactions(limit_);
        }

        // Where each parcel now is
        if (impulse_ == impulseType::neighbour)
        {
            limit_.endStep(this->owner());
        }
    }

    MfixPackingModel<CloudType>::cacheFields(store);
}


template<class CloudType>
Foam::vector Foam::PackingModels::ColoringFunction<CloudType>::
velocityCorrection
(
    typename CloudType::parcelType& p,
    const scalar deltaT
) const
{
    const packState pack = packFor(p);

    vector correction =
        rules_.correctedVelocity
        (
            p.U(),
            pack.uMean,
            pack.impulse,
            this->owner().g().value(),
            pack.closePacked
        )
      - p.U();

    if (capacityLimit_ && impulse_ == impulseType::neighbour)
    {
        // The correction move puts the parcel where it may be; OpenFOAM
        // then adds the move's velocity to the parcel's (MPPICParcel,
        // tpCorrectTrack). The parcel is to end with the velocity the
        // rules give, without a component into a cell that refused it: a
        // move back across a cell is a displacement, and kept as a
        // velocity it would fling the parcel out of the pack
        // (keepAfterTrack: MfixPackingModel.H)
        vector kept;
        const vector move =
            limit_.move
            (
                this->owner().mesh(),
                p,
                correction,
                pack.uMean,
                deltaT,
                kept
            );

        recordChange(p, kept - p.U(), pack.cell);
        this->keepAfterTrack(p, kept, move);

        return move;
    }

    recordChange(p, correction, pack.cell);
    return correction;
}


// ************************************************************************* //
