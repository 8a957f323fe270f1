/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "ConstantCdDragForce.H"
#include "dragCorrelations.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::ConstantCdDragForce<CloudType>::ConstantCdDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    ParticleForce<CloudType>(owner, mesh, dict, typeName, true),
    Cd_
    (
        mppicCoefficients::read
        (
            this->coeffs(),
            "Cd",
            mppicCoefficients::bounds::atLeast(0)
        )
    ),
    feedback_(this->coeffs().lookupOrDefault("feedback", true))
{}


template<class CloudType>
Foam::ConstantCdDragForce<CloudType>::ConstantCdDragForce
(
    const ConstantCdDragForce<CloudType>& df
)
:
    ParticleForce<CloudType>(df),
    Cd_(df.Cd_),
    feedback_(df.feedback_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::ConstantCdDragForce<CloudType>::Sp
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar mass
) const
{
    return
        mass
       *dragCorrelations::constantCdK(Cd_, mag(td.Uc() - p.U()), p.d(), td.rhoc())
       /p.rho();
}


template<class CloudType>
Foam::forceSuSp Foam::ConstantCdDragForce<CloudType>::calcNonCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    // OpenFOAM integrates only the explicit part of non-coupled forces
    // (KinematicParcel::calcVelocity): the drag as Su = Sp*(u_g - u_p)
    if (feedback_)
    {
        return forceSuSp(Zero, 0);
    }
    return forceSuSp(Sp(p, td, mass)*(td.Uc() - p.U()), 0);
}


template<class CloudType>
Foam::forceSuSp Foam::ConstantCdDragForce<CloudType>::calcCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    return forceSuSp(Zero, feedback_ ? Sp(p, td, mass) : 0);
}


// ************************************************************************* //
