/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "HillKochLaddDragForce.H"
#include "dragCorrelations.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::HillKochLaddDragForce<CloudType>::HillKochLaddDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    DenseDragForce<CloudType>(owner, mesh, dict, typeName)
{}


template<class CloudType>
Foam::HillKochLaddDragForce<CloudType>::HillKochLaddDragForce
(
    const HillKochLaddDragForce<CloudType>& df
)
:
    DenseDragForce<CloudType>(df)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::HillKochLaddDragForce<CloudType>::K
(
    const scalar alphag,
    const scalar slip,
    const scalar d,
    const scalar rhog,
    const scalar mug
) const
{
    return dragCorrelations::hillKochLaddK(alphag, slip, d, rhog, mug);
}


// ************************************************************************* //
