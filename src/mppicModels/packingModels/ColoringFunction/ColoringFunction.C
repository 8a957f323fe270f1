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
    "e1", "e2", "case1a", "case1b", "reflection", "impulse"
});

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PackingModels::ColoringFunction<CloudType>::ColoringFunction
(
    const dictionary& dict,
    CloudType& owner
)
:
    DensePackingModel<CloudType>(dict, owner, typeName, keywords),
    rules_(this->coeffs(), this->closePackFraction()),
    impulse_
    (
        impulseTypeNames.lookupOrDefault
        (
            "impulse",
            this->coeffs(),
            impulseType::neighbour
        )
    )
{}


template<class CloudType>
Foam::PackingModels::ColoringFunction<CloudType>::ColoringFunction
(
    const ColoringFunction<CloudType>& cm
)
:
    DensePackingModel<CloudType>(cm),
    rules_(cm.rules_),
    impulse_(cm.impulse_)
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
        this->limit().entries().find(p);

    if (entered)
    {
        const scalar cellValue = this->cellValue(p.cell());

        const bool blocked =
            this->capacityLimit() ? !entered->admitted : cellValue > 0;

        if (blocked)
        {
            pack.impulse =
                -max(cellValue, this->closePackFraction())
                *entered->direction;
            pack.uMean = this->cellUMean(p.cell());
            pack.cell = this->globalCell(p);
            pack.closePacked = cellValue > 0;
            return pack;
        }
    }

    // The cell ahead: when close packed, the pack lies along the normal
    const neighbourState ahead =
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
    if (!this->capacityLimit() || impulse_ != impulseType::neighbour)
    {
        return DensePackingModel<CloudType>::cellPackingValues();
    }

    tmp<scalarField> tvalues
    (
        new scalarField(this->limit().entries().startFraction())
    );
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
void Foam::PackingModels::ColoringFunction<CloudType>::cacheFields
(
    const bool store
)
{
    if (debug && tracksEntries())
    {
        if (store)
        {
            this->limitRef().setDebug(debug);
        }
        else
        {
            this->limit().entries().reportGrowth
            (
                this->owner(),
                this->closePackFraction()
            );
        }
    }

    DensePackingModel<CloudType>::cacheFields(store);
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

    if (this->capacityLimit() && impulse_ == impulseType::neighbour)
    {
        // The correction move puts the parcel where it may be; OpenFOAM
        // then adds the move's velocity to the parcel's (MPPICParcel,
        // tpCorrectTrack). The parcel is to end with the velocity the
        // rules give, without a component into a cell that refused it: a
        // move back across a cell is a displacement, and kept as a
        // velocity it would fling the parcel out of the pack
        // (keepAfterTrack: DensePackingModel.H)
        vector kept;
        const vector move =
            this->limit().move
            (
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
