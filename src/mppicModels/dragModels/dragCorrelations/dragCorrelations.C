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


Foam::scalar Foam::dragCorrelations::wenYuK(const dragState& s)
{
    const scalar Re = s.alphag*s.rhog*s.slip*s.d/s.mug;

    // 0.75*Cd*ag*rhog*w/d written with Cd*Re, finite as w -> 0
    const scalar CdRe =
        Re >= 1000 ? 0.44*Re : 24*(1 + 0.15*pow(Re, 0.687));

    return 0.75*CdRe*s.mug/sqr(s.d)*pow(s.alphag, -2.65);
}


Foam::scalar Foam::dragCorrelations::ergunK(const dragState& s)
{
    return
        150*(1 - s.alphag)*s.mug/(s.alphag*sqr(s.d))
      + 1.75*s.rhog*s.slip/s.d;
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


namespace Foam
{
namespace dragCorrelations
{
namespace
{

// Hill-Koch-Ladd zero-Re and high-Re fits F0 and F2, below phi = 0.4
// a blend (weight w) of the dilute fit and the dense 10*phi/(1 - phi)^3
scalar hillKochLaddFit
(
    const scalar phi,
    const scalar a,
    const scalar b,
    const scalar c
)
{
    const scalar dense = 10*phi/pow3(1 - phi);
    if (phi >= 0.4)
    {
        return dense;
    }
    if (phi <= 0)
    {
        return 1;
    }

    const scalar w = exp(-10*(0.4 - phi)/phi);
    const scalar dilute =
        (1 + 3*sqrt(phi/2) + 135.0/64.0*phi*log(phi) + a*phi)
       /(1 + 0.681*phi + b*sqr(phi) + c*pow3(phi));

    return (1 - w)*dilute + w*dense;
}


// Beetstra et al.'s polydisperse f(y) = ag*y + phi*y^2 + 0.064*ag*y^3
scalar beetstraF(const scalar alphag, const scalar y)
{
    return y*(alphag + y*((1 - alphag) + 0.064*alphag*y));
}

} // End anonymous namespace
} // End namespace dragCorrelations
} // End namespace Foam


Foam::scalar Foam::dragCorrelations::hillKochLaddF
(
    const scalar phi,
    const scalar ReRadius
)
{
    const scalar F2 = hillKochLaddFit(phi, 17.89, -11.03, 15.41);
    const scalar F3 =
        phi < 0.0953
      ? 0.9351*phi + 0.03667
      : 0.0673 + 0.212*phi + 0.0232/pow5(1 - phi);

    if (phi <= 0.01)
    {
        const scalar ReTransition = (F2 - 1)/(3.0/8.0 - F3);
        return
            ReRadius <= ReTransition
          ? 1 + 3.0/8.0*ReRadius
          : F2 + F3*ReRadius;
    }

    const scalar F0 = hillKochLaddFit(phi, 17.14, -8.48, 8.16);
    const scalar F1 =
        phi <= 0.1 ? sqrt(2/phi)/40 : 0.11 + 5.1e-4*exp(11.6*phi);
    const scalar ReTransition =
        (F3 + sqrt(sqr(F3) - 4*F1*(F0 - F2)))/(2*F1);

    return
        ReRadius <= ReTransition
      ? F0 + F1*sqr(ReRadius)
      : F2 + F3*ReRadius;
}


Foam::scalar Foam::dragCorrelations::hillKochLaddK(const dragState& s)
{
    const scalar ReRadius = 0.5*s.alphag*s.rhog*s.slip*s.d/s.mug;

    return
        18*s.mug*sqr(s.alphag)/sqr(s.d)
       *hillKochLaddF(1 - s.alphag, ReRadius);
}


Foam::scalar Foam::dragCorrelations::bvkF(const scalar phi, const scalar Re)
{
    const scalar alphag = 1 - phi;
    const scalar stokes =
        10*phi/sqr(alphag) + sqr(alphag)*(1 + 1.5*sqrt(phi));

    if (Re < VSMALL)
    {
        return stokes;
    }

    const scalar inertial =
        0.413*Re/(24*sqr(alphag))
       *(1/alphag + 3*alphag*phi + 8.4*pow(Re, -0.343))
       /(1 + pow(10, 3*phi)*pow(Re, -(0.5 + 2*phi)));

    return stokes + inertial;
}


Foam::scalar Foam::dragCorrelations::bvkK(const dragState& s)
{
    const scalar Re = s.alphag*s.rhog*s.slip*s.d/s.mug;

    return 18*s.mug*s.alphag/sqr(s.d)*bvkF(1 - s.alphag, Re);
}


Foam::scalar Foam::dragCorrelations::syamlalOBrienK
(
    const dragState& s,
    const scalar c1,
    const scalar d1
)
{
    const scalar ReSingle = s.rhog*s.slip*s.d/s.mug;

    const scalar A = pow(s.alphag, 4.14);
    const scalar B =
        s.alphag <= 0.85 ? c1*pow(s.alphag, 1.28) : pow(s.alphag, d1);

    // Ratio of the terminal velocity of the suspension to a single sphere's
    const scalar Vr =
        0.5
       *(
            A - 0.06*ReSingle
          + sqrt(sqr(0.06*ReSingle) + 0.12*ReSingle*(2*B - A) + sqr(A))
        );

    // Dalla Valle's Cd*Re at Re_s/V_r is (0.63*sqrt(Re_s/V_r) + 4.8)^2
    return
        0.75*s.mug*s.alphag/(Vr*sqr(s.d))*sqr(0.63*sqrt(ReSingle/Vr) + 4.8);
}


Foam::scalar Foam::dragCorrelations::stokesK
(
    const dragState& s,
    const scalar voidageExponent
)
{
    return 18*s.mug/sqr(s.d)*pow(s.alphag, -voidageExponent);
}


Foam::scalar Foam::dragCorrelations::constantCdK
(
    const dragState& s,
    const scalar Cd
)
{
    return 0.75*Cd*s.rhog*s.slip/s.d;
}


Foam::scalar Foam::dragCorrelations::beetstraPolydisperseScale
(
    const scalar alphag,
    const scalar y
)
{
    return beetstraF(alphag, y)/(beetstraF(alphag, 1)*sqr(y));
}


// ************************************************************************* //
