/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "dragCorrelations.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dragCorrelations::wenYuCd(const scalar Re)
{
    if (Re >= 1000)
    {
        return 0.44;
    }

    return 24/max(Re, VSMALL)*(1 + 0.15*pow(Re, 0.687));
}


Foam::scalar Foam::dragCorrelations::wenYuK
(
    const scalar alphag,
    const scalar slip,
    const scalar d,
    const scalar rhog,
    const scalar mug
)
{
    const scalar Re = alphag*rhog*slip*d/mug;

    // 0.75*Cd*ag*rhog*w/d written with Cd*Re, finite as w -> 0
    const scalar CdRe =
        Re >= 1000 ? 0.44*Re : 24*(1 + 0.15*pow(Re, 0.687));

    return 0.75*CdRe*mug/sqr(d)*pow(alphag, -2.65);
}


Foam::scalar Foam::dragCorrelations::ergunK
(
    const scalar alphag,
    const scalar slip,
    const scalar d,
    const scalar rhog,
    const scalar mug
)
{
    return 150*(1 - alphag)*mug/(alphag*sqr(d)) + 1.75*rhog*slip/d;
}


Foam::scalar Foam::dragCorrelations::gidaspowBlendWeight
(
    const scalar alphag,
    const scalar switchFraction
)
{
    return
        atan(150*1.75*(alphag - switchFraction))
       /constant::mathematical::pi
      + 0.5;
}


Foam::scalar Foam::dragCorrelations::constantCdK
(
    const scalar Cd,
    const scalar slip,
    const scalar d,
    const scalar rhog
)
{
    return 0.75*Cd*rhog*slip/d;
}


// ************************************************************************* //
