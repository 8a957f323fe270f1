/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "PhaseInjection.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType, template<class> class Injection>
Foam::label Foam::PhaseInjection<CloudType, Injection>::readPhase
(
    const dictionary& coeffs
)
{
    const scalar phase =
        mppicCoefficients::read
        (
            coeffs, "phase", mppicCoefficients::bounds::atLeast(1)
        );
    if (phase != label(phase))
    {
        FatalIOErrorInFunction(coeffs)
            << "Dictionary " << coeffs.name() << ", keyword phase: "
            << "value " << phase << " must be an integer, at least 1"
            << exit(FatalIOError);
    }
    return label(phase);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType, template<class> class Injection>
Foam::PhaseInjection<CloudType, Injection>::PhaseInjection
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    Injection<CloudType>(dict, owner, modelName),
    phase_(readPhase(this->coeffDict())),
    rho_
    (
        mppicCoefficients::read
        (
            this->coeffDict(),
            "rho",
            owner.constProps().rho0(),
            mppicCoefficients::bounds::above(0)
        )
    )
{
    // OpenFOAM gives each injected parcel the injector's ID as its typeId
    // (keyword injectorID): the phase's index, or the same value
    if (this->injectorID_ != -1 && this->injectorID_ != phase_)
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "Dictionary " << this->coeffDict().name() << ", keyword "
            << "injectorID: value " << this->injectorID_ << " must be the "
            << "phase's index " << phase_ << " or left out"
            << exit(FatalIOError);
    }
    this->injectorID_ = phase_;
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType, template<class> class Injection>
void Foam::PhaseInjection<CloudType, Injection>::setProperties
(
    const label parcelI,
    const label nParcels,
    const scalar time,
    typename CloudType::parcelType& parcel
)
{
    Injection<CloudType>::setProperties(parcelI, nParcels, time, parcel);

    parcel.rho() = rho_;
}


// ************************************************************************* //
