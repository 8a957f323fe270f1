/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Description
    sniderStressRules against the hand values of Test-packingRules.C's
    header (tau, the impulse velocity, the limiter).

\*---------------------------------------------------------------------------*/

#include "sniderStressRules.H"
#include "unitTest.H"
#include "packingRulesChecks.H"

using namespace Foam;
using namespace Foam::unitTest;

void testSnider()
{
    const sniderStressRules rules(sniderCoeffs(), 0.6);

    checkClose("tau(0.3) [Pa]", rules.tau(0.3), 9, 1e-12);
    checkClose("tau(0.59) [Pa]", rules.tau(0.59), 2053.79, 1e-12);
    checkClose("tau(0.65) [Pa]", rules.tau(0.65), 27.4625/3.5e-8, 1e-12);
    checkClose("tau(0.8), capped [Pa]", rules.tau(0.8), 32.8509/3.1e-8, 1e-12);

    checkVector
    (
        "impulse velocity, eq 14",
        rules.impulseVelocity(vector(0, -1000, 0), 2500, 0.5, 1e-3),
        vector(0, 8e-4, 0)
    );
    checkVector
    (
        "impulse velocity where alpha = 0",
        rules.impulseVelocity(vector(0, -1000, 0), 2500, 0, 1e-3),
        vector::zero
    );

    const vector gradDown(0, -1000, 0);
    checkVector
    (
        "limiter caps at the reflection (1 + e1)*slip",
        rules.correctedVelocity
        (
            vector(0, -1, 0), vector(0, -0.2, 0), vector(0, 2, 0), gradDown
        ),
        vector(0, 0.48, 0)
    );
    checkVector
    (
        "limiter keeps a small impulse",
        rules.correctedVelocity
        (
            vector(0, -1, 0), vector(0, -0.2, 0), vector(0, 0.5, 0), gradDown
        ),
        vector(0, -0.5, 0)
    );
    checkVector
    (
        "limiter: separating parcel unchanged",
        rules.correctedVelocity
        (
            vector(0, 0.5, 0), vector(0, -0.2, 0), vector(0, 2, 0), gradDown
        ),
        vector(0, 0.5, 0)
    );
    checkVector
    (
        "limiter, positive gradient",
        rules.correctedVelocity
        (
            vector(0.3, 0, 0), vector::zero, vector(-0.1, 0, 0),
            vector(500, 0, 0)
        ),
        vector(0.2, 0, 0)
    );

    dictionary halfSlip(sniderCoeffs());
    halfSlip.add("slipVelocityFactor", 0.5);
    checkVector
    (
        "slipVelocityFactor 0.5",
        sniderStressRules(halfSlip, 0.6).correctedVelocity
        (
            vector(0, -1, 0), vector(0, -0.2, 0), vector(0, 2, 0), gradDown
        ),
        vector(0, 0.665, 0)
    );
}


// ************************************************************************* //
