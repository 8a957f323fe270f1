/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "StokesDrag.H"
#include "dragCorrelations.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dragLaws::StokesDrag::StokesDrag(const dictionary& coeffs)
:
    voidageExponent_
    (
        mppicCoefficients::read
        (
            coeffs,
            "voidageExponent",
            2.65,
            mppicCoefficients::bounds::atLeast(0)
        )
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dragLaws::StokesDrag::K
(
    const scalar alphag,
    const scalar slip,
    const scalar d,
    const scalar rhog,
    const scalar mug
) const
{
    return dragCorrelations::stokesK(alphag, d, mug, voidageExponent_);
}


// ************************************************************************* //
