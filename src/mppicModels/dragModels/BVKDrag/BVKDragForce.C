/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "BVKDragForce.H"
#include "dragCorrelations.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::BVKDragForce<CloudType>::BVKDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    DenseDragForce<CloudType>(owner, mesh, dict, typeName)
{}


template<class CloudType>
Foam::BVKDragForce<CloudType>::BVKDragForce
(
    const BVKDragForce<CloudType>& df
)
:
    DenseDragForce<CloudType>(df)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::BVKDragForce<CloudType>::K
(
    const scalar alphag,
    const scalar slip,
    const scalar d,
    const scalar rhog,
    const scalar mug
) const
{
    return dragCorrelations::bvkK(alphag, slip, d, rhog, mug);
}


// ************************************************************************* //
