/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "MfixSnider.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PackingModels::MfixSnider<CloudType>::MfixSnider
(
    const dictionary& dict,
    CloudType& owner
)
:
    MfixPackingModel<CloudType>(dict, owner, typeName),
    rules_(this->coeffs())
{}


template<class CloudType>
Foam::PackingModels::MfixSnider<CloudType>::MfixSnider
(
    const MfixSnider<CloudType>& cm
)
:
    MfixPackingModel<CloudType>(cm),
    rules_(cm.rules_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::vector Foam::PackingModels::MfixSnider<CloudType>::velocityCorrection
(
    typename CloudType::parcelType& p,
    const scalar deltaT
) const
{
    const vector tauGrad = this->packingGradAt(p);

    const vector dU =
        rules_.impulseVelocity(tauGrad, p.rho(), this->alphaAt(p), deltaT);

    const vector correction =
        rules_.correctedVelocity(p.U(), this->uMeanAt(p), dU, tauGrad)
      - p.U();

    this->recordVelocityChange(p, correction);
    return correction;
}


// ************************************************************************* //
