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
    reactions_(),
    holdSupportedPacks_
    (
        this->coeffs().lookupOrDefault("holdSupportedPacks", true)
    ),
    support_(owner.mesh(), this->coeffs())
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
    reactions_(),
    holdSupportedPacks_(cm.holdSupportedPacks_),
    support_(cm.support_)
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
        pack.cell = p.cell();
        return pack;
    }

    if (impulse_ == impulseType::faceGradient)
    {
        pack.impulse = -this->faceGradientAt(p);
        pack.uMean = this->uMeanAt(p);
        pack.cell = p.cell();
        return pack;
    }

    // A parcel that moved into its cell in this step and may not stay:
    // the pack is its own cell, along the way it came in
    const typename ParcelEntries<CloudType>::entry* entered =
        entries_.find(p);

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
            pack.cell = p.cell();
            pack.closePacked = cellValue > 0;
            return pack;
        }
    }

    // The cell ahead: when close packed, the pack lies along the normal
    const typename MfixPackingModel<CloudType>::neighbourState ahead =
        this->neighbourAhead(p);

    pack.impulse = -ahead.value*ahead.normal;
    pack.uMean = ahead.found ? ahead.uMean : this->uMeanAt(p);
    pack.cell = ahead.found ? ahead.cell : p.cell();
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

    tmp<scalarField> tvalues(new scalarField(entries_.startFraction()));
    for (scalar& value : tvalues.ref())
    {
        value = rules_.colour(value);
    }
    return tvalues;
}


template<class CloudType>
Foam::boolList
Foam::PackingModels::ColoringFunction<CloudType>::fullCells() const
{
    const fvMesh& mesh = this->owner().mesh();

    scalarField volume(mesh.nCells(), Zero);
    scalarField largest(mesh.nCells(), Zero);

    for (const typename CloudType::parcelType& p : this->owner())
    {
        const label celli = entries_.finalCell(p);
        if (celli >= 0)
        {
            const scalar v = p.nParticle()*p.volume();
            volume[celli] += v;
            largest[celli] = max(largest[celli], v);
        }
    }

    // The refused parcels that go back to cells here from other processors
    const scalarField& returned = entries_.returnedVolume();
    if (returned.size())
    {
        volume += returned;
        largest = max(largest, entries_.returnedLargest());
    }

    // No room for half of its largest parcel, as the capacity limit admits
    boolList full(mesh.nCells());
    forAll(full, celli)
    {
        const scalar room =
            rules_.closePackFraction()*mesh.V()[celli] - volume[celli];
        full[celli] = largest[celli] > 0 && room < 0.5*largest[celli];
    }
    return full;
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
void Foam::PackingModels::ColoringFunction<CloudType>::beforeMotion()
{
    // Nothing recorded yet while parcels that have moved before (age > 0)
    // are in the cloud: they were read from a written time. Record where
    // they are, which is where the uninterrupted run's last step left them
    // (the parcels injected since, of age 0, were not there then)
    if (impulse_ == impulseType::neighbour && !entries_.hasRecords())
    {
        entries_.recordCells(this->owner(), true);
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
        entries_.debug = debug;
        entries_.update
        (
            this->owner(),
            rules_.closePackFraction(),
            this->owner().db().time().deltaTValue()
        );

        if (holdSupportedPacks_ && capacityLimit_)
        {
            support_.update(this->owner().g().value(), fullCells());

            if (Pstream::parRun())
            {
                boolList heldCells(this->owner().mesh().nCells());
                forAll(heldCells, celli)
                {
                    heldCells[celli] = support_.held(celli);
                }
                entries_.shareHeld(heldCells);
            }
        }
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

        vector kept =
            entries_.keptVelocity(p, p.U() + correction, pack.uMean);

        if
        (
            support_.held(entries_.finalCell(p))
         || entries_.returnsToHeldCell(p)
        )
        {
            kept = support_.heldVelocity(p.U(), kept);
        }

        recordChange(p, kept - p.U(), pack.cell);
        p.U() = kept - move;

        return move;
    }

    recordChange(p, correction, pack.cell);
    return correction;
}


// ************************************************************************* //
