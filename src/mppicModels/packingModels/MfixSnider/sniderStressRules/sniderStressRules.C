/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "sniderStressRules.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::sniderStressRules::sniderStressRules
(
    const dictionary& coeffs,
    const scalar closePackFraction
)
:
    closePackFraction_(closePackFraction),
    pSolid_
    (
        mppicCoefficients::read
        (
            coeffs, "pSolid", 100, mppicCoefficients::bounds::atLeast(0)
        )
    ),
    gamma_
    (
        mppicCoefficients::read
        (
            coeffs, "gamma", 3, mppicCoefficients::bounds::atLeast(0)
        )
    ),
    eps_
    (
        mppicCoefficients::read
        (
            coeffs, "eps", 1e-7, mppicCoefficients::bounds::open(0, 1)
        )
    ),
    e1_
    (
        mppicCoefficients::read
        (
            coeffs, "e1", 0.85, mppicCoefficients::bounds::closed(0, 1)
        )
    ),
    slipVelocityFactor_
    (
        mppicCoefficients::read
        (
            coeffs,
            "slipVelocityFactor",
            1,
            mppicCoefficients::bounds::closed(0, 1)
        )
    ),
    releaseAbove_
    (
        mppicCoefficients::read
        (
            coeffs,
            "releaseAbove",
            1,
            mppicCoefficients::bounds::openClosed(closePackFraction_, 1)
        )
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::sniderStressRules::cappedFraction(const scalar alpha) const
{
    return min(max(alpha, scalar(0)), min(0.995, capFactor*closePackFraction_));
}


Foam::scalar Foam::sniderStressRules::tau(const scalar alpha) const
{
    // Capped as in MFiX, so that the denominator stays positive when an
    // averaged solids fraction overshoots
    const scalar alphaCapped = cappedFraction(alpha);

    return
        pSolid_*pow(alphaCapped, gamma_)
       /max(closePackFraction_ - alphaCapped, eps_*(1 - alphaCapped));
}


Foam::vector Foam::sniderStressRules::impulseVelocity
(
    const vector& tauGrad,
    const scalar rhoParcel,
    const scalar alpha,
    const scalar deltaT
) const
{
    if (alpha <= VSMALL)
    {
        return Zero;
    }

    return -deltaT*tauGrad/(rhoParcel*alpha);
}


Foam::vector Foam::sniderStressRules::correctedVelocity
(
    const vector& U,
    const vector& uMean,
    const vector& dU,
    const vector& tauGrad
) const
{
    vector Unew = U;

    for (direction k = 0; k < vector::nComponents; ++k)
    {
        const scalar reflection =
            (1 + e1_)*(slipVelocityFactor_*uMean[k] - U[k]);

        if (tauGrad[k] <= 0)
        {
            Unew[k] += max(scalar(0), min(dU[k], reflection));
        }
        else
        {
            Unew[k] += min(scalar(0), max(dU[k], reflection));
        }
    }

    return Unew;
}


Foam::scalar Foam::sniderStressRules::meanFreePath
(
    const scalar alpha,
    const scalar radius
) const
{
    return 3.7*radius/(3*sqrt(2.0)*max(alpha, SMALL));
}


Foam::vector Foam::sniderStressRules::releaseVelocity
(
    const vector& tauGrad,
    const scalar alpha,
    const scalar radius,
    const scalar deltaT
) const
{
    const scalar magGrad = mag(tauGrad);
    if (alpha <= releaseAbove_ || magGrad <= VSMALL)
    {
        return Zero;
    }
    return -tauGrad/magGrad*meanFreePath(alpha, radius)/deltaT;
}


// ************************************************************************* //
