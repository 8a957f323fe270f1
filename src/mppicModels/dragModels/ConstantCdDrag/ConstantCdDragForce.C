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
    )
{}


template<class CloudType>
Foam::ConstantCdDragForce<CloudType>::ConstantCdDragForce
(
    const ConstantCdDragForce<CloudType>& df
)
:
    ParticleForce<CloudType>(df),
    Cd_(df.Cd_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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
    return forceSuSp(Zero, mass*dragCorrelations::constantCdK(Cd_, mag(td.Uc() - p.U()), p.d(), td.rhoc())/p.rho());
}


// ************************************************************************* //
