/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Description
    coloringFunctionRules with reflection component (MFiX's cases 1-4, 1b
    and 1a tested on each Cartesian component k with dV_k != 0),
    alpha_cp = 0.6, e1 = 0.5, e2 = 0.9, g = (0 -9.81 0); v = U_k,
    u = us_k, d = dV_k:
      case 2, head on: dV (1 0 0), U (-2 0.3 0), us (0.5 0 0):
          x: v*u < 0, u*d > 0 -> 0.5 - 0.5*(-2 - 0.5) = 1.75; y: d = 0,
          unchanged -> (1.75 0.3 0)
      case 1, the parcel catches up: dV (1 0 0), U (-2 0 0), us (-0.5 0 0):
          -0.5 - 0.5*(-2 + 0.5) = 0.25
      Case 1b: U (-0.5 0 0), us (-1 0 0): 0.9*(-0.5) = -0.45
      case 4, the pack catches up: U (0.5 0 0), us (2 0 0):
          2 - 0.5*(0.5 - 2) = 2.75
      case 3: U (0.5 0 0), us (-1 0 0): unchanged 0.5
      pack at rest (u = 0): U (-1 0 0), us 0: unchanged (eq 20 as a
          vector would give 0.5)
      oblique dV (1 1 0), U (-2 -1 0), us (0.5 -0.2 0): x head on 1.75;
          y case 1: -0.2 - 0.5*(-1 + 0.2) = 0.2, then Case 1a
          (d*g < 0, v*g > 0): -0.5*(-1) = 0.5 -> (1.75 0.5 0)
      the same with case1a off: (1.75 0.2 0)
      round-off: dV (100 1e-11 0), U (-2 -0.3 0), us (0.5 0.4 0): x head
          on 1.75; y (1e-13 of x, at most componentRoundOff 1e-9 of it)
          counts as zero -> -0.3 unchanged, where its sign would give head
          on 0.4 - 0.5*(-0.3 - 0.4) = 0.75, then Case 1a (d*g < 0,
          v*g > 0): -0.5*(-0.3) = 0.15; with dV (100 1e-4 0) (1e-6 of x, a
          real component) y takes those rules: (1.75 0.15 0)

\*---------------------------------------------------------------------------*/

#include "coloringFunctionRules.H"
#include "packingRulesChecks.H"

using namespace Foam;

void testComponentReflection()
{
    const vector g(0, -9.81, 0);
    const coloringFunctionRules rules
    (
        colouringCoeffs(true, true, "component"), 0.6
    );
    const coloringFunctionRules no1a
    (
        colouringCoeffs(false, true, "component"), 0.6
    );
    const vector dx(1, 0, 0);

    checkVector
    (
        "component: case 2, head on",
        rules.correctedVelocity(vector(-2, 0.3, 0), vector(0.5, 0, 0), dx, g),
        vector(1.75, 0.3, 0)
    );
    checkVector
    (
        "component: case 1, the parcel catches up",
        rules.correctedVelocity(vector(-2, 0, 0), vector(-0.5, 0, 0), dx, g),
        vector(0.25, 0, 0)
    );
    checkVector
    (
        "component: Case 1b",
        rules.correctedVelocity(vector(-0.5, 0, 0), vector(-1, 0, 0), dx, g),
        vector(-0.45, 0, 0)
    );
    checkVector
    (
        "component: case 4, the pack catches up",
        rules.correctedVelocity(vector(0.5, 0, 0), vector(2, 0, 0), dx, g),
        vector(2.75, 0, 0)
    );
    checkVector
    (
        "component: case 3, unchanged",
        rules.correctedVelocity(vector(0.5, 0, 0), vector(-1, 0, 0), dx, g),
        vector(0.5, 0, 0)
    );
    checkVector
    (
        "component: pack at rest, unchanged",
        rules.correctedVelocity(vector(-1, 0, 0), vector::zero, dx, g),
        vector(-1, 0, 0)
    );
    checkVector
    (
        "component: oblique, x head on, y case 1 then Case 1a",
        rules.correctedVelocity
        (
            vector(-2, -1, 0), vector(0.5, -0.2, 0), vector(1, 1, 0), g
        ),
        vector(1.75, 0.5, 0)
    );
    checkVector
    (
        "component: oblique, Case 1a off",
        no1a.correctedVelocity
        (
            vector(-2, -1, 0), vector(0.5, -0.2, 0), vector(1, 1, 0), g
        ),
        vector(1.75, 0.2, 0)
    );
    checkVector
    (
        "component: a round-off component counts as zero",
        rules.correctedVelocity
        (
            vector(-2, -0.3, 0), vector(0.5, 0.4, 0), vector(100, 1e-11, 0), g
        ),
        vector(1.75, -0.3, 0)
    );
    checkVector
    (
        "component: a small real component is reflected",
        rules.correctedVelocity
        (
            vector(-2, -0.3, 0), vector(0.5, 0.4, 0), vector(100, 1e-4, 0), g
        ),
        vector(1.75, 0.15, 0)
    );
}


// ************************************************************************* //
