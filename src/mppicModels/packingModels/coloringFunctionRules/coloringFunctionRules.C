/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "coloringFunctionRules.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coloringFunctionRules::coloringFunctionRules(const dictionary& coeffs)
:
    closePackFraction_
    (
        mppicCoefficients::read
        (
            coeffs, "closePackFraction", mppicCoefficients::bounds::open(0, 1)
        )
    ),
    e1_
    (
        mppicCoefficients::read
        (
            coeffs, "e1", 0.4, mppicCoefficients::bounds::closed(0, 1)
        )
    ),
    e2_
    (
        mppicCoefficients::read
        (
            coeffs, "e2", 0.9, mppicCoefficients::bounds::closed(0, 1)
        )
    ),
    case1a_(coeffs.lookupOrDefault<bool>("case1a", true)),
    case1b_(coeffs.lookupOrDefault<bool>("case1b", true))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::coloringFunctionRules::correctedVelocity
(
    const vector& U,
    const vector& uMean,
    const vector& impulse,
    const vector& g
) const
{
    const vector Urel = U - uMean;

    vector Unew = U;

    if ((Urel & impulse) < 0)
    {
        // Approaching the pack: reflect the relative velocity (eq 20)
        Unew = uMean - e1_*Urel;
    }
    else if (case1b_ && (U & impulse) < 0)
    {
        // Case 1b (eq 23): moving into the pack, but slower than the pack
        Unew = e2_*U;
    }

    // Case 1a (eq 22): moving along gravity onto a pack that lies along
    // gravity, the gravity component always bounces back
    if (case1a_ && (impulse & g) < 0 && (U & g) > 0)
    {
        const vector gHat = g/mag(g);
        Unew += (-e1_*(U & gHat) - (Unew & gHat))*gHat;
    }

    return Unew;
}


// ************************************************************************* //
