/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    See sniderRuleChecks.H.

\*---------------------------------------------------------------------------*/

#include "sniderStressRules.H"
#include "unitTest.H"
#include "sniderRuleChecks.H"

using namespace Foam;
using namespace Foam::unitTest;

// * * * * * * * * * * * * * * * * Test groups * * * * * * * * * * * * * * //

void testMeanFreePathCap()
{
    dictionary coeffs;
    coeffs.add("closePackFraction", 0.6);
    coeffs.add("meanFreePathCap", true);
    const sniderStressRules capped(coeffs);
    coeffs.set("meanFreePathCap", false);
    const sniderStressRules uncapped(coeffs);

    const scalar l = 3.7*0.005/(3*Foam::sqrt(2.0)*0.65);
    const vector up(0, 10, 0);
    const vector grad(0, 1, 0);
    checkClose
    (
        "mean-free-path cap: up the gradient in a packed cell",
        capped.meanFreePathCapped(up, grad, 0.65, 0.005, 1e-3).y(),
        10*l/0.01, 1e-12
    );
    checkClose
    (
        "mean-free-path cap: down the gradient, unchanged",
        capped.meanFreePathCapped(-up, grad, 0.65, 0.005, 1e-3).y(),
        -10, 1e-12
    );
    checkClose
    (
        "mean-free-path cap: below 0.62, unchanged",
        capped.meanFreePathCapped(up, grad, 0.6, 0.005, 1e-3).y(),
        10, 1e-12
    );
    checkClose
    (
        "mean-free-path cap off: unchanged",
        uncapped.meanFreePathCapped(up, grad, 0.65, 0.005, 1e-3).y(),
        10, 1e-12
    );
}


void testRestWhereConverging()
{
    dictionary coeffs;
    coeffs.add("closePackFraction", 0.6);
    coeffs.add("restWhereConverging", true);
    const sniderStressRules rest(coeffs);
    coeffs.set("restWhereConverging", false);
    const sniderStressRules mean(coeffs);

    const vector U(0, -1, 0);
    const vector dU(0, 100, 0);
    const vector grad(0, -10, 0);
    const vector converging(0, -0.5, 0);
    const vector diverging(0, 0.5, 0);

    checkClose
    (
        "converging mean, about rest",
        rest.correctedVelocity(U, converging, dU, grad).y(), 0.85, 1e-12
    );
    checkClose
    (
        "converging mean, option off: about the mean",
        mean.correctedVelocity(U, converging, dU, grad).y(), -0.075, 1e-12
    );
    checkClose
    (
        "diverging mean, about the mean either way",
        rest.correctedVelocity(U, diverging, dU, grad).y(), 1.775, 1e-12
    );
    checkClose
    (
        "diverging mean, option off",
        mean.correctedVelocity(U, diverging, dU, grad).y(), 1.775, 1e-12
    );
}



// ************************************************************************* //
