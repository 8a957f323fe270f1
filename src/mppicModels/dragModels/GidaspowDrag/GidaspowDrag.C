/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "GidaspowDrag.H"
#include "dragCorrelations.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dragLaws::GidaspowDrag::GidaspowDrag(const dictionary& coeffs)
:
    switchFraction_
    (
        mppicCoefficients::read
        (
            coeffs,
            "switchFraction",
            0.8,
            mppicCoefficients::bounds::open(0, 1)
        )
    ),
    blend_(coeffs.lookupOrDefault("blend", false))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dragLaws::GidaspowDrag::K
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
