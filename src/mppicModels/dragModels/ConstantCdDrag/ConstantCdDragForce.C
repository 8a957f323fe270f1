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
    MppicDragForce<CloudType>(owner, mesh, dict, typeName),
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
    MppicDragForce<CloudType>(df),
    Cd_(df.Cd_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::ConstantCdDragForce<CloudType>::Sp
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar mass,
    const scalar muc
) const
{
    return
        mass
       *dragCorrelations::constantCdK(Cd_, this->slip(p, td), p.d(), td.rhoc())
       /p.rho();
}


// ************************************************************************* //
