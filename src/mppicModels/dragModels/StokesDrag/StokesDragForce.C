/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "StokesDragForce.H"
#include "dragCorrelations.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::StokesDragForce<CloudType>::StokesDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    DenseDragForce<CloudType>(owner, mesh, dict, typeName),
    voidageExponent_
    (
        mppicCoefficients::read
        (
            this->coeffs(),
            "voidageExponent",
            2.65,
            mppicCoefficients::bounds::atLeast(0)
        )
    )
{}


template<class CloudType>
Foam::StokesDragForce<CloudType>::StokesDragForce
(
    const StokesDragForce<CloudType>& df
)
:
    DenseDragForce<CloudType>(df),
    voidageExponent_(df.voidageExponent_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::StokesDragForce<CloudType>::K
(
    const scalar alphag,
    const scalar slip,
    const scalar d,
    const scalar rhog,
    const scalar mug
) const
{
    return dragCorrelations::stokesK(alphag, d, mug, voidageExponent_);
}


// ************************************************************************* //
