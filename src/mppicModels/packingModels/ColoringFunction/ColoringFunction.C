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
    impulse_(cm.impulse_)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::PackingModels::ColoringFunction<CloudType>::impulseAndPackVelocity
(
    const typename CloudType::parcelType& p,
    vector& impulse,
    vector& uPack
) const
{
    if (impulse_ == impulseType::gradient)
    {
        impulse = -this->packingGradAt(p);
        uPack = this->uMeanAt(p);
        return;
    }

    // The cell ahead: when close packed, the pack lies along the normal
    const typename MfixPackingModel<CloudType>::neighbourState ahead =
        this->neighbourAhead(p);

    impulse = -ahead.value*ahead.normal;
    uPack = ahead.found ? ahead.uMean : this->uMeanAt(p);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::vector Foam::PackingModels::ColoringFunction<CloudType>::
velocityCorrection
(
    typename CloudType::parcelType& p,
    const scalar deltaT
) const
{
    vector impulse, uPack;
    impulseAndPackVelocity(p, impulse, uPack);

    return
        rules_.correctedVelocity
        (
            p.U(),
            uPack,
            impulse,
            this->owner().g().value()
        )
      - p.U();
}


// ************************************************************************* //
