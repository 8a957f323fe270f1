/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Application
    Test-dragCorrelations

Description
    The drag correlations K = beta/alpha_s of dragCorrelations against the
    formulas written out here, in their textbook form (Cd and the
    superficial Reynolds number, not the Cd*Re form of the library), at a
    dilute, an intermediate and a dense gas fraction:
        d = 1e-4 m, rho_g = 1.2 kg/m3, mu_g = 1.8e-5 Pa s, slip w = 0.5 m/s
        ag = 0.99, 0.85, 0.45;  Re = ag*rho_g*w*d/mu_g
        Wen-Yu:  Cd = 24/Re*(1 + 0.15*Re^0.687) (0.44 above Re = 1000)
                 K = 0.75*Cd*ag*rho_g*w/d*ag^-2.65
        Ergun:   K = 150*(1 - ag)*mu_g/(ag*d^2) + 1.75*rho_g*w/d
        constant Cd = 1: K = 0.75*Cd*rho_g*w/d = 4500
    the dilute, creeping-flow limits of the resolved-simulation laws
    (Stokes drag, K = 18*mu_g/d^2 at ag = 1, Re = 0, for Hill-Koch-Ladd
    and BVK; Dalla Valle's 0.75*4.8^2*mu_g/d^2 for Syamlal-O'Brien, whose
    V_r is 1 there) and Hill-Koch-Ladd's dense limit F = 10*phi/(1-phi)^3
    at Re = 0 for phi >= 0.4,
    plus Wen-Yu above Re = 1000 (w = 200 m/s, ag = 0.9: Re = 1200) and the
    Gidaspow blend weight: 0.5 at the switch, atan(+-262.5*0.01)/pi + 0.5
    one hundredth either side, so that the blended K is continuous,
    and Beetstra et al.'s polydisperse factor of K(<d>), y = d/<d>,
        f(y)/(f(1)*y^2),  f(y) = ag*y + (1 - ag)*y^2 + 0.064*ag*y^3
    exactly 1 at y = 1, and at (ag, y) = (0.6, 0.75), (0.6, 1.5),
    (0.45, 0.5), (0.99, 3) the values of python on this formula.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "IOstreams.H"
#include "mathematicalConstants.H"
#include "dragCorrelations.H"
#include "unitTest.H"

using namespace Foam;
using namespace Foam::unitTest;

const scalar d = 1e-4;
const scalar rhog = 1.2;
const scalar mug = 1.8e-5;
const scalar w = 0.5;


//- The state of a parcel of this gas at a gas fraction and slip
dragCorrelations::dragState state(const scalar ag, const scalar slip)
{
    dragCorrelations::dragState s;
    s.mass = 0;
    s.rhop = 0;
    s.alphag = ag;
    s.slip = slip;
    s.d = d;
    s.rhog = rhog;
    s.mug = mug;
    return s;
}


scalar handWenYu(const scalar ag, const scalar slip)
{
    const scalar Re = ag*rhog*slip*d/mug;
    const scalar Cd = Re < 1000 ? 24/Re*(1 + 0.15*std::pow(Re, 0.687)) : 0.44;
    return 0.75*Cd*ag*rhog*slip/d*std::pow(ag, -2.65);
}


scalar handErgun(const scalar ag)
{
    return 150*(1 - ag)*mug/(ag*d*d) + 1.75*rhog*w/d;
}


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList args(argc, argv, false, false, false);

    for (const scalar ag : {0.99, 0.85, 0.45})
    {
        const string at = " at ag = " + Foam::name(ag);
        checkClose
        (
            "Wen-Yu K" + at,
            dragCorrelations::wenYuK(state(ag, w)),
            handWenYu(ag, w)
        );
        checkClose
        (
            "Ergun K" + at,
            dragCorrelations::ergunK(state(ag, w)),
            handErgun(ag)
        );
    }

    checkClose
    (
        "Wen-Yu K above Re = 1000 (Cd = 0.44)",
        dragCorrelations::wenYuK(state(0.9, 200)),
        handWenYu(0.9, 200)
    );
    checkClose
    (
        "Wen-Yu Cd(1200) = 0.44",
        dragCorrelations::wenYuCd(1200),
        0.44
    );
    checkClose
    (
        "Wen-Yu Cd(1) = 24*1.15",
        dragCorrelations::wenYuCd(1),
        27.6
    );
    checkClose
    (
        "constant Cd = 1: K = 0.75*1.2*0.5/1e-4",
        dragCorrelations::constantCdK(state(1, w), 1),
        4500
    );

    const scalar stokesK = 18*mug/(d*d);
    checkClose
    (
        "Hill-Koch-Ladd K at ag = 1, zero slip: Stokes 18*mu/d^2",
        dragCorrelations::hillKochLaddK(state(1, 0)),
        stokesK
    );
    checkClose
    (
        "BVK K at ag = 1, zero slip: Stokes 18*mu/d^2",
        dragCorrelations::bvkK(state(1, 0)),
        stokesK
    );
    checkClose
    (
        "Syamlal-O'Brien K at ag = 1, zero slip: 0.75*4.8^2*mu/d^2",
        dragCorrelations::syamlalOBrienK(state(1, 0), 0.8, 2.65),
        17.28*mug/(d*d)
    );
    checkClose
    (
        "Hill-Koch-Ladd F(0.5, 0) = 10*0.5/0.5^3 = 40",
        dragCorrelations::hillKochLaddF(0.5, 0),
        40
    );

    const scalar pi = constant::mathematical::pi;
    checkClose
    (
        "blend weight at the switch",
        dragCorrelations::gidaspowBlendWeight(0.8, 0.8),
        0.5
    );
    checkClose
    (
        "blend weight 0.01 above the switch",
        dragCorrelations::gidaspowBlendWeight(0.81, 0.8),
        std::atan(2.625)/pi + 0.5,
        1e-10
    );
    checkClose
    (
        "blend weight 0.01 below the switch",
        dragCorrelations::gidaspowBlendWeight(0.79, 0.8),
        std::atan(-2.625)/pi + 0.5,
        1e-10
    );

    // Continuity of the blended K across the switch
    auto blended = [&](const scalar ag)
    {
        const scalar phi = dragCorrelations::gidaspowBlendWeight(ag, 0.8);
        return
            (1 - phi)*dragCorrelations::ergunK(state(ag, w))
          + phi*dragCorrelations::wenYuK(state(ag, w));
    };
    const scalar jump = mag(blended(0.8 + 1e-9) - blended(0.8 - 1e-9));
    checkTrue
    (
        "blended K continuous at the switch (jump "
      + Foam::name(jump) + " < 1e-6 of K)",
        jump < 1e-6*blended(0.8)
    );
    const scalar rawJump =
        mag(handWenYu(0.8, w) - handErgun(0.8))/handErgun(0.8);
    checkTrue
    (
        "unblended Ergun/Wen-Yu differ at the switch (relative "
      + Foam::name(rawJump) + " > 0.01)",
        rawJump > 0.01
    );

    for (const scalar ag : {0.99, 0.6, 0.45})
    {
        checkClose
        (
            "polydisperse factor exactly 1 at y = 1, ag = " + Foam::name(ag),
            dragCorrelations::beetstraPolydisperseScale(ag, 1),
            1,
            0
        );
    }
    const scalar agYFactor[4][3] =
    {
        {0.6, 0.75, 1.1833590138674883},
        {0.6, 1.5, 0.8258859784283513},
        {0.45, 0.5, 1.4234059097978229},
        {0.99, 3, 0.4984953355401745}
    };
    for (const auto& c : agYFactor)
    {
        checkClose
        (
            "polydisperse factor at ag = " + Foam::name(c[0]) + ", y = "
          + Foam::name(c[1]),
            dragCorrelations::beetstraPolydisperseScale(c[0], c[1]),
            c[2]
        );
    }

    return summary();
}


// ************************************************************************* //
