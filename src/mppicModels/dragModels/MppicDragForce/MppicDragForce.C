/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "MppicDragForce.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::MppicDragForce<CloudType>::MppicDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict,
    const word& forceType
)
:
    ParticleForce<CloudType>(owner, mesh, dict, forceType, true),
    feedback_(this->coeffs().lookupOrDefault("feedback", true))
{}


template<class CloudType>
Foam::MppicDragForce<CloudType>::MppicDragForce
(
    const MppicDragForce<CloudType>& df
)
:
    ParticleForce<CloudType>(df),
    feedback_(df.feedback_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::forceSuSp Foam::MppicDragForce<CloudType>::calcNonCoupled
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
    return forceSuSp(Sp(p, td, mass, muc)*(td.Uc() - p.U()), 0);
}


template<class CloudType>
Foam::forceSuSp Foam::MppicDragForce<CloudType>::calcCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    return forceSuSp(Zero, feedback_ ? Sp(p, td, mass, muc) : 0);
}


// ************************************************************************* //
