/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Application
    Test-packingRules

Description
    The parcel-velocity rules of the packing models against hand-computed
    velocities, and their coefficient checks.

    coloringFunctionRules, alpha_cp = 0.6, e1 = 0.5, e2 = 0.9,
    g = (0 -9.81 0); U intermediate velocity, us mean solids velocity,
    dV impulse direction -grad(chi):
      eq 18: chi(0.59) = 0, chi(0.6) = 0.6, chi(0.65) = 0.65; a cell at
          close pack to 1e-9 is a pack:
          chi(0.6/(1 + 1e-10)) = 0.6/(1 + 1e-10), chi(0.6*(1 - 1e-8)) = 0
      approach, eq 20: dV = (1 0 0), U = (-2 0.3 0), us = (0.5 0 0):
          Urel = (-2.5 0.3 0), U' = us - 0.5*Urel = (1.75 -0.15 0)
      separation: U = (2 0 0), same us, dV: unchanged
      Case 1a: dV = (0 1 0), U = (0.2 -1 0), us = (0 -0.1 0):
          eq 20 gives (-0.1 0.35 0); on: y = -e1*U.gHat*gHat_y = +0.5
          -> (-0.1 0.5 0); off -> (-0.1 0.35 0)
      Case 1b: dV = (1 0 0), U = (-0.5 0 0), us = (-1 0 0) (pack faster):
          on -> 0.9*U = (-0.45 0 0); off -> unchanged
      Case 1b then 1a: dV = (0 1 0), U = (0 -0.5 0), us = (0 -1 0):
          1b gives (0 -0.45 0), 1a then sets y = +0.25 -> (0 0.25 0);
          1a off -> (0 -0.45 0)
      no pack near, dV = 0: unchanged
      a cell full to the nearest parcel below close pack (closePacked
      false): only eq 20. Case 1a input gives the eq 20 value
      (-0.1 0.35 0); Case 1b input (-0.5 0 0) is unchanged; Case 1b then
      1a input (0 -0.5 0) is unchanged; approach as above (1.75 -0.15 0)
      reflection component: componentReflectionChecks.C
      reflection normal (only the component along dHat = dV/|dV|):
        approach as above: U' = U - 1.5*(Urel.x)x = (1.75 0.3 0)
        Case 1b: U = (-0.5 0.2 0), us = (-1 0 0), dV = (1 0 0):
          U' = U - 0.1*(U.x)x = (-0.45 0.2 0)
        Case 1a: U = (0.2 -1 0), us = (0 -0.1 0), dV = (0 1 0): eq 20 on
          the y component gives 0.35, Case 1a then 0.5 -> (0.2 0.5 0)

    sniderStressRules, alpha_cp = 0.6, Ps = 100, gamma = 3, eps = 1e-7:
      tau(0.3)  = 100*0.027/0.3                  = 9
      tau(0.59) = 100*0.205379/0.01              = 2053.79
      tau(0.65) = 100*0.274625/(1e-7*0.35)       = 7.846428571e8
      tau(0.8)  capped at 1.15*0.6 = 0.69:
                  100*0.328509/(1e-7*0.31)       = 1.059706452e9
      dU = -dt*grad(tau)/(rho*alpha): grad = (0 -1000 0), rho 2500,
          alpha 0.5, dt 1e-3 -> (0 8e-4 0); alpha 0 -> 0
      limiter, e1 = 0.85: U = (0 -1 0), us = (0 -0.2 0), grad (0 -1000 0):
          slip 0.8, (1 + e1)*slip = 1.48
          dU = (0 2 0)   -> U'_y = -1 + min(2, 1.48)   = 0.48
          dU = (0 0.5 0) -> U'_y = -1 + 0.5            = -0.5
        separating U = (0 0.5 0): (1+e1)*slip = -1.295 -> unchanged 0.5
        grad (500 0 0), U = (0.3 0 0), us = 0, dU = (-0.1 0 0):
          U'_x = 0.3 + min(0, max(-0.1, -0.555)) = 0.2
        slipVelocityFactor 0.5, first case with dU = (0 2 0):
          slip = 0.5*(-0.2) + 1 = 0.9 -> U'_y = -1 + 1.665 = 0.665

    Bad input: e1, e2 outside [0, 1], closePackFraction outside (0, 1) or
    missing, pSolid < 0, gamma < 0, eps outside (0, 1),
    slipVelocityFactor > 1: each a FatalIOError naming the keyword.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "IOstreams.H"
#include "coloringFunctionRules.H"
#include "sniderStressRules.H"
#include "closePack.H"
#include "unitTest.H"
#include "packingRulesChecks.H"

using namespace Foam;
using namespace Foam::unitTest;

void checkVector
(
    const string& what,
    const vector& value,
    const vector& expected
)
{
    for (direction k = 0; k < vector::nComponents; ++k)
    {
        checkClose
        (
            what + " [" + Foam::name(label(k)) + "]",
            value[k],
            expected[k],
            1e-12,
            1
        );
    }
}


template<class Rules>
bool rejects(const dictionary& dict, const word& keyword)
{
    return unitTest::raisesError
    (
        [&]() { Rules rules(dict, PackingModels::readClosePackFraction(dict)); },
        {keyword}
    );
}


dictionary colouringCoeffs
(
    const bool case1a,
    const bool case1b,
    const word& reflection
)
{
    dictionary dict;
    dict.add("reflection", reflection);
    dict.add("closePackFraction", 0.6);
    dict.add("e1", 0.5);
    dict.add("e2", 0.9);
    dict.add("case1a", case1a);
    dict.add("case1b", case1b);
    return dict;
}


//- One hand case of coloringFunctionRules::correctedVelocity: the rules,
//  the intermediate velocity U, the mean solids velocity us, the impulse
//  direction dV, whether the cell is at close pack and the velocity
//  expected (Description)
struct colouringCase
{
    const char* what;
    const coloringFunctionRules& rules;
    vector U;
    vector us;
    vector dV;
    bool closePacked;
    vector expected;
};


void testColoringFunction()
{
    const vector g(0, -9.81, 0);
    const coloringFunctionRules rules(colouringCoeffs(), 0.6);
    const coloringFunctionRules no1a(colouringCoeffs(false, true), 0.6);
    const coloringFunctionRules no1b(colouringCoeffs(true, false), 0.6);
    const coloringFunctionRules normal
    (
        colouringCoeffs(true, true, "normal"), 0.6
    );

    checkClose("chi(0.59)", rules.colour(0.59), 0, 0, 1);
    checkClose("chi(0.6)", rules.colour(0.6), 0.6);
    checkClose("chi(0.65)", rules.colour(0.65), 0.65);
    // a full cell at close pack: 5 parcels of 0.12 in a cell 1e-10 larger
    // than theirs (gmsh's points) make 0.6/(1 + 1e-10), a pack; 1e-8 below
    // close pack is not
    checkClose
    (
        "chi(0.6/(1 + 1e-10))", rules.colour(0.6/(1 + 1e-10)),
        0.6/(1 + 1e-10)
    );
    checkClose("chi(0.6*(1 - 1e-8))", rules.colour(0.6*(1 - 1e-8)), 0, 0, 1);

    const colouringCase cases[] =
    {
        {"approach, eq 20", rules,
            {-2, 0.3, 0}, {0.5, 0, 0}, {1, 0, 0}, true, {1.75, -0.15, 0}},
        {"separation, unchanged", rules,
            {2, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, true, {2, 0, 0}},
        {"Case 1a on", rules,
            {0.2, -1, 0}, {0, -0.1, 0}, {0, 1, 0}, true, {-0.1, 0.5, 0}},
        {"Case 1a off", no1a,
            {0.2, -1, 0}, {0, -0.1, 0}, {0, 1, 0}, true, {-0.1, 0.35, 0}},
        {"Case 1b on", rules,
            {-0.5, 0, 0}, {-1, 0, 0}, {1, 0, 0}, true, {-0.45, 0, 0}},
        {"Case 1b off", no1b,
            {-0.5, 0, 0}, {-1, 0, 0}, {1, 0, 0}, true, {-0.5, 0, 0}},
        {"Case 1b then Case 1a along gravity", rules,
            {0, -0.5, 0}, {0, -1, 0}, {0, 1, 0}, true, {0, 0.25, 0}},
        {"Case 1b along gravity, Case 1a off", no1a,
            {0, -0.5, 0}, {0, -1, 0}, {0, 1, 0}, true, {0, -0.45, 0}},
        {"below close pack: Case 1a not applied", rules,
            {0.2, -1, 0}, {0, -0.1, 0}, {0, 1, 0}, false, {-0.1, 0.35, 0}},
        {"below close pack: Case 1b not applied", rules,
            {-0.5, 0, 0}, {-1, 0, 0}, {1, 0, 0}, false, {-0.5, 0, 0}},
        {"below close pack: neither Case 1b nor 1a along gravity", rules,
            {0, -0.5, 0}, {0, -1, 0}, {0, 1, 0}, false, {0, -0.5, 0}},
        {"below close pack: approach, eq 20", rules,
            {-2, 0.3, 0}, {0.5, 0, 0}, {1, 0, 0}, false, {1.75, -0.15, 0}},
        {"approach, normal component only", normal,
            {-2, 0.3, 0}, {0.5, 0, 0}, {1, 0, 0}, true, {1.75, 0.3, 0}},
        {"Case 1b, normal component only", normal,
            {-0.5, 0.2, 0}, {-1, 0, 0}, {1, 0, 0}, true, {-0.45, 0.2, 0}},
        {"Case 1a, normal reflection (impulse along g)", normal,
            {0.2, -1, 0}, {0, -0.1, 0}, {0, 1, 0}, true, {0.2, 0.5, 0}},
        {"no close pack near (zero gradient), unchanged", rules,
            {0.3, -2, 0.1}, {0, -0.1, 0}, vector::zero, true, {0.3, -2, 0.1}}
    };

    for (const colouringCase& c : cases)
    {
        checkVector
        (
            c.what,
            c.rules.correctedVelocity(c.U, c.us, c.dV, g, c.closePacked),
            c.expected
        );
    }
}


template<class Rules>
void testBadValue
(
    const word& rulesName,
    const dictionary& good,
    const word& keyword,
    const scalar value
)
{
    dictionary dict(good);
    dict.set(keyword, value);
    checkTrue
    (
        rulesName + ": " + keyword + " = " + Foam::name(value)
      + " rejected",
        rejects<Rules>(dict, keyword)
    );
}


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList args(argc, argv, false, false, false);

    testColoringFunction();
    testComponentReflection();
    testSnider();

    testBadValue<coloringFunctionRules>("coloringFunctionRules", colouringCoeffs(), "e1", 1.5);
    testBadValue<coloringFunctionRules>("coloringFunctionRules", colouringCoeffs(), "e1", -0.1);
    testBadValue<coloringFunctionRules>("coloringFunctionRules", colouringCoeffs(), "e2", 1.2);
    testBadValue<coloringFunctionRules>("coloringFunctionRules", colouringCoeffs(), "e2", -1);
    testBadValue<coloringFunctionRules>
    (
        "coloringFunctionRules", colouringCoeffs(), "closePackFraction", 0
    );
    testBadValue<coloringFunctionRules>
    (
        "coloringFunctionRules", colouringCoeffs(), "closePackFraction", 1
    );
    testBadValue<sniderStressRules>("sniderStressRules", sniderCoeffs(), "pSolid", -1);
    testBadValue<sniderStressRules>("sniderStressRules", sniderCoeffs(), "gamma", -1);
    testBadValue<sniderStressRules>("sniderStressRules", sniderCoeffs(), "eps", 0);
    testBadValue<sniderStressRules>("sniderStressRules", sniderCoeffs(), "e1", 1.01);
    testBadValue<sniderStressRules>("sniderStressRules", sniderCoeffs(), "slipVelocityFactor", 2);

    {
        dictionary dict(colouringCoeffs());
        dict.set("reflection", "sideways");
        checkTrue
        (
            "coloringFunctionRules: reflection sideways rejected",
            rejects<coloringFunctionRules>(dict, "reflection")
        );
    }
    {
        dictionary dict(colouringCoeffs());
        dict.remove("closePackFraction");
        checkTrue
        (
            "coloringFunctionRules: missing closePackFraction rejected",
            rejects<coloringFunctionRules>(dict, "closePackFraction")
        );
    }
    {
        dictionary dict(sniderCoeffs());
        dict.remove("closePackFraction");
        checkTrue
        (
            "sniderStressRules: missing closePackFraction rejected",
            rejects<sniderStressRules>(dict, "closePackFraction")
        );
    }

    return summary();
}


// ************************************************************************* //
