/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "PhaseInjection.H"
#include "boundedCoefficient.H"

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
    phase_
    (
        label
        (
            mppicCoefficients::read
            (
                this->coeffDict(), "phase", mppicCoefficients::bounds::atLeast(1)
            )
        )
    ),
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
    const scalar phase = this->coeffDict().template get<scalar>("phase");
    if (phase != phase_)
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "Dictionary " << this->coeffDict().name() << ", keyword phase: "
            << "value " << phase << " must be an integer, at least 1"
            << exit(FatalIOError);
    }

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
