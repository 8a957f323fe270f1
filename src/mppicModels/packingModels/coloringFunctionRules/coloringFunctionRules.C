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
    case1b_(coeffs.lookupOrDefault<bool>("case1b", true)),
    normalOnly_(readReflection(coeffs))
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::coloringFunctionRules::readReflection(const dictionary& coeffs)
{
    const word reflection(coeffs.lookupOrDefault<word>("reflection", "normal"));

    if (reflection != "normal" && reflection != "vector")
    {
        FatalIOErrorInFunction(coeffs)
            << "Dictionary " << coeffs.name() << ", keyword reflection: "
            << "value " << reflection << " is not one of (normal vector)"
            << exit(FatalIOError);
    }

    return reflection == "normal";
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::coloringFunctionRules::correctedVelocity
(
    const vector& U,
    const vector& uMean,
    const vector& impulse,
    const vector& g,
    const bool closePacked
) const
{
    const vector Urel = U - uMean;

    // The part of a velocity that the rules change: all of it (eqs 20, 23
    // as written) or its component along the impulse direction
    const vector dHat = impulse/max(mag(impulse), VSMALL);
    auto changed = [&](const vector& v)
    {
        return normalOnly_ ? (v & dHat)*dHat : v;
    };

    vector Unew = U;

    if ((Urel & impulse) < 0)
    {
        // Approaching the pack: reflect the relative velocity (eq 20)
        Unew = U - (1 + e1_)*changed(Urel);
    }
    else if (case1b_ && closePacked && (U & impulse) < 0)
    {
        // Case 1b (eq 23): moving into the pack, but slower than the pack
        Unew = U - (1 - e2_)*changed(U);
    }

    // Case 1a (eq 22): moving along gravity onto a pack that lies along
    // gravity, the gravity component always bounces back
    if (case1a_ && closePacked && (impulse & g) < 0 && (U & g) > 0)
    {
        const vector gHat = g/mag(g);
        Unew += (-e1_*(U & gHat) - (Unew & gHat))*gHat;
    }

    return Unew;
}


// ************************************************************************* //
