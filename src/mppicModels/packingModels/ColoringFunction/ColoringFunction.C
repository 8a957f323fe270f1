/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "ColoringFunction.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PackingModels::ColoringFunction<CloudType>::ColoringFunction
(
    const dictionary& dict,
    CloudType& owner
)
:
    MfixPackingModel<CloudType>(dict, owner, typeName),
    rules_(this->coeffs())
{}


template<class CloudType>
Foam::PackingModels::ColoringFunction<CloudType>::ColoringFunction
(
    const ColoringFunction<CloudType>& cm
)
:
    MfixPackingModel<CloudType>(cm),
    rules_(cm.rules_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::vector Foam::PackingModels::ColoringFunction<CloudType>::
velocityCorrection
(
    typename CloudType::parcelType& p,
    const scalar deltaT
) const
{
    const vector impulse = -this->packingGradAt(p);

    return
        rules_.correctedVelocity
        (
            p.U(),
            this->uMeanAt(p),
            impulse,
            this->owner().g().value()
        )
      - p.U();
}


// ************************************************************************* //
