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
    { impulseType::neighbour, "neighbour" },
});

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PackingModels::ColoringFunction<CloudType>::ColoringFunction
(
    const dictionary& dict,
    CloudType& owner
)
:
    MfixPackingModel<CloudType>(dict, owner, typeName),
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
    capacityLimit_(this->coeffs().lookupOrDefault("capacityLimit", true)),
    conserveMomentum_
    (
        this->coeffs().lookupOrDefault("conserveMomentum", false)
    ),
    entries_(),
    reactions_()
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
    conserveMomentum_(cm.conserveMomentum_),
    entries_(),
    reactions_()
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::PackingModels::ColoringFunction<CloudType>::impulseAndPackVelocity
(
    const typename CloudType::parcelType& p,
    vector& impulse,
    vector& uPack,
    label& packCell
) const
{
    // The pack is the parcel's own cell unless it lies ahead
    packCell = p.cell();

    if (impulse_ == impulseType::gradient)
    {
        impulse = -this->packingGradAt(p);
        uPack = this->uMeanAt(p);
        return;
    }

    // A parcel that moved into its cell in this step and may not stay:
    // the pack is its own cell, along the way it came in
    const typename ParcelEntries<CloudType>::entry* entered =
        entries_.find(p);

    if (entered)
    {
        const scalar packValue =
            max(this->cellValue(p.cell()), rules_.closePackFraction());

        const bool blocked =
            capacityLimit_
          ? !entered->admitted
          : this->cellValue(p.cell()) > 0;

        if (blocked)
        {
            impulse = -packValue*entered->direction;
            uPack = this->cellUMean(p.cell());
            return;
        }
    }

    // The cell ahead: when close packed, the pack lies along the normal
    const typename MfixPackingModel<CloudType>::neighbourState ahead =
        this->neighbourAhead(p);

    impulse = -ahead.value*ahead.normal;
    uPack = ahead.found ? ahead.uMean : this->uMeanAt(p);
    packCell = ahead.found ? ahead.cell : p.cell();
}


template<class CloudType>
Foam::tmp<Foam::scalarField>
Foam::PackingModels::ColoringFunction<CloudType>::cellPackingValues() const
{
    if (!capacityLimit_)
    {
        return MfixPackingModel<CloudType>::cellPackingValues();
    }

    tmp<scalarField> tvalues(new scalarField(entries_.startFraction()));
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

    if (conserveMomentum_ && packCell >= 0 && magSqr(dU) > 0)
    {
        reactions_.record(p, packCell, dU);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::PackingModels::ColoringFunction<CloudType>::cacheFields
(
    const bool store
)
{
    if (store && impulse_ == impulseType::neighbour)
    {
        entries_.debug = debug;
        entries_.update
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
            entries_.reportGrowth(this->owner(), rules_.closePackFraction());
        }

        // End of the packing step: the packs take their impulses back
        reactions_.apply
        (
            this->owner(),
            [this](const typename CloudType::parcelType& p, const vector& dU)
            {
                this->recordVelocityChange(p, dU);
            }
        );

        // Where each parcel now is
        entries_.clear();
        if (impulse_ == impulseType::neighbour)
        {
            entries_.recordCells(this->owner());
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
    vector impulse, uPack;
    label packCell;
    impulseAndPackVelocity(p, impulse, uPack, packCell);

    vector correction =
        rules_.correctedVelocity
        (
            p.U(),
            uPack,
            impulse,
            this->owner().g().value()
        )
      - p.U();

    if (capacityLimit_ && impulse_ == impulseType::neighbour)
    {
        // The correction move puts the parcel where it may be; OpenFOAM
        // then adds the move's velocity to the parcel's (MPPICParcel,
        // tpCorrectTrack). Set the velocity now so that the sum is the
        // velocity the rules give, without a component into a cell that
        // refused the parcel: a move back across a cell is a displacement,
        // and kept as a velocity it would fling the parcel out of the pack
        const vector move =
            entries_.limitedCorrection
            (
                this->owner().mesh(),
                p,
                correction,
                deltaT
            );

        const vector kept = entries_.keptVelocity(p, p.U() + correction);
        recordChange(p, kept - p.U(), packCell);
        p.U() = kept - move;

        return move;
    }

    recordChange(p, correction, packCell);
    return correction;
}


// ************************************************************************* //
