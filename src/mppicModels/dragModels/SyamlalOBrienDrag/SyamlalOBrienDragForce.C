/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "SyamlalOBrienDragForce.H"
#include "dragCorrelations.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::SyamlalOBrienDragForce<CloudType>::SyamlalOBrienDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    DenseDragForce<CloudType>(owner, mesh, dict, typeName),
    c1_
    (
        mppicCoefficients::read
        (
            this->coeffs(),
            "c1",
            0.8,
            mppicCoefficients::bounds::above(0)
        )
    ),
    d1_
    (
        mppicCoefficients::read
        (
            this->coeffs(),
            "d1",
            2.65,
            mppicCoefficients::bounds::above(0)
        )
    )
{}


template<class CloudType>
Foam::SyamlalOBrienDragForce<CloudType>::SyamlalOBrienDragForce
(
    const SyamlalOBrienDragForce<CloudType>& df
)
:
    DenseDragForce<CloudType>(df),
    c1_(df.c1_),
    d1_(df.d1_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::SyamlalOBrienDragForce<CloudType>::K
(
    const scalar alphag,
    const scalar slip,
    const scalar d,
    const scalar rhog,
    const scalar mug
) const
{
    return
        dragCorrelations::syamlalOBrienK
        (
            alphag, slip, d, rhog, mug, c1_, d1_
        );
}


// ************************************************************************* //
