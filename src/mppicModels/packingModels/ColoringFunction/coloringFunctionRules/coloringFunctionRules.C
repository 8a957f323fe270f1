/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "coloringFunctionRules.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coloringFunctionRules::coloringFunctionRules
(
    const dictionary& coeffs,
    const scalar closePackFraction
)
:
    closePackFraction_(closePackFraction),
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
    reflection_(readReflection(coeffs))
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::coloringFunctionRules::reflectionType
Foam::coloringFunctionRules::readReflection(const dictionary& coeffs)
{
    const word reflection(coeffs.lookupOrDefault<word>("reflection", "normal"));

    if (reflection == "normal")
    {
        return reflectionType::normal;
    }
    if (reflection == "vector")
    {
        return reflectionType::vector;
    }
    if (reflection != "component")
    {
        FatalIOErrorInFunction(coeffs)
            << "Dictionary " << coeffs.name() << ", keyword reflection: "
            << "value " << reflection << " is not one of "
            << "(normal vector component)" << exit(FatalIOError);
    }
    return reflectionType::component;
}


Foam::scalar Foam::coloringFunctionRules::componentVelocity
(
    const scalar v,
    const scalar u,
    const scalar d,
    const scalar g,
    const bool closePacked
) const
{
    scalar vNew = v;

    if (v*u > 0)
    {
        // Parcel and pack move the same way: one catches up with the other
        const bool catchesUp = v*d > 0 ? mag(u) > mag(v) : mag(v) > mag(u);

        if (catchesUp)
        {
            vNew = u - e1_*(v - u);
        }
        else if (case1b_ && closePacked && v*d < 0)
        {
            vNew = e2_*v;
        }
    }
    else if (u*d > 0)
    {
        // Head on
        vNew = u - e1_*(v - u);
    }

    if (case1a_ && closePacked && d*g < 0 && v*g > 0)
    {
        vNew = -e1_*v;
    }

    return vNew;
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
    if (reflection_ == reflectionType::component)
    {
        // A component at round-off of the impulse is taken as none: on a
        // mesh whose faces are axis-aligned to round-off it is noise,
        // whose sign would reflect a velocity component at random
        const scalar roundOff = componentRoundOff*cmptMax(cmptMag(impulse));

        vector Unew = U;
        for (direction k = 0; k < vector::nComponents; ++k)
        {
            if (mag(impulse[k]) > roundOff)
            {
                Unew[k] =
                    componentVelocity
                    (
                        U[k], uMean[k], impulse[k], g[k], closePacked
                    );
            }
        }
        return Unew;
    }

    const vector Urel = U - uMean;

    // The part of a velocity that the rules change: all of it (eqs 20, 23
    // as written) or its component along the impulse direction
    const vector dHat = impulse/max(mag(impulse), VSMALL);
    auto changed = [&](const vector& v)
    {
        return reflection_ == reflectionType::normal ? (v & dHat)*dHat : v;
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
