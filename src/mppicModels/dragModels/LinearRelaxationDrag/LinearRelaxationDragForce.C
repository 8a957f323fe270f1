/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "LinearRelaxationDragForce.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::LinearRelaxationDragForce<CloudType>::LinearRelaxationDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    ParticleForce<CloudType>(owner, mesh, dict, typeName, true),
    C_
    (
        mppicCoefficients::read
        (
            this->coeffs(),
            "C",
            mppicCoefficients::bounds::atLeast(0)
        )
    )
{}


template<class CloudType>
Foam::LinearRelaxationDragForce<CloudType>::LinearRelaxationDragForce
(
    const LinearRelaxationDragForce<CloudType>& df
)
:
    ParticleForce<CloudType>(df),
    C_(df.C_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::forceSuSp Foam::LinearRelaxationDragForce<CloudType>::calcCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    return forceSuSp(Zero, C_*mass);
}


// ************************************************************************* //
