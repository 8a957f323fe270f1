/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "mfixCollisionDamping.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mfixCollisionDamping::mfixCollisionDamping
(
    const scalar e1,
    const scalar closePackFraction
)
:
    e1_(e1),
    closePackFraction_(closePackFraction),
    meanVelocity_(),
    oneByTau_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::mfixCollisionDamping::oneByTau
(
    const scalar alpha,
    const scalar sigma,
    const scalar r32
) const
{
    if (r32 <= VSMALL)
    {
        return 0;
    }

    // Radial distribution function, 1 at and above close pack
    const scalar gap = closePackFraction_ - alpha;
    const scalar g0 = gap > 0 ? max(closePackFraction_/gap, scalar(1)) : 1;

    return
        16/sqrt(3*constant::mathematical::pi)
       *alpha*sigma/r32*g0
       *0.25*(1 - sqr(e1_));
}


Foam::vector Foam::mfixCollisionDamping::damped
(
    const vector& U,
    const label celli,
    const scalar deltaT
) const
{
    vector result = U;
    for (direction k = 0; k < vector::nComponents; ++k)
    {
        const scalar ratio = 0.5*deltaT*oneByTau_[celli][k];
        if (ratio > 0)
        {
            result[k] =
                (U[k] + ratio*meanVelocity_[celli][k])/(1 + ratio);
        }
    }
    return result;
}


void Foam::mfixCollisionDamping::clear()
{
    meanVelocity_.clear();
    oneByTau_.clear();
}


// ************************************************************************* //
