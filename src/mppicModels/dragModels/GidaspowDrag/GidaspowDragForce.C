/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "GidaspowDragForce.H"
#include "dragCorrelations.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::GidaspowDragForce<CloudType>::GidaspowDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    DenseDragForce<CloudType>(owner, mesh, dict, typeName),
    switchFraction_
    (
        mppicCoefficients::read
        (
            this->coeffs(),
            "switchFraction",
            0.8,
            mppicCoefficients::bounds::open(0, 1)
        )
    ),
    blend_(this->coeffs().lookupOrDefault("blend", false))
{}


template<class CloudType>
Foam::GidaspowDragForce<CloudType>::GidaspowDragForce
(
    const GidaspowDragForce<CloudType>& df
)
:
    DenseDragForce<CloudType>(df),
    switchFraction_(df.switchFraction_),
    blend_(df.blend_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::GidaspowDragForce<CloudType>::K
(
    const scalar alphag,
    const scalar slip,
    const scalar d,
    const scalar rhog,
    const scalar mug
) const
{
    const scalar phi =
        blend_
      ? dragCorrelations::gidaspowBlendWeight(alphag, switchFraction_)
      : scalar(alphag >= switchFraction_ ? 1 : 0);

    scalar K = 0;
    if (phi > 0)
    {
        K += phi*dragCorrelations::wenYuK(alphag, slip, d, rhog, mug);
    }
    if (phi < 1)
    {
        K += (1 - phi)*dragCorrelations::ergunK(alphag, slip, d, rhog, mug);
    }
    return K;
}


// ************************************************************************* //
