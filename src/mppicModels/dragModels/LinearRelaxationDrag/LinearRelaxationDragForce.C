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
    MppicDragForce<CloudType>(owner, mesh, dict, typeName),
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
    MppicDragForce<CloudType>(df),
    C_(df.C_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::LinearRelaxationDragForce<CloudType>::Sp
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar mass,
    const scalar muc
) const
{
    return C_*mass;
}


// ************************************************************************* //
