/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "SyamlalOBrienDrag.H"
#include "dragCorrelations.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dragLaws::SyamlalOBrienDrag::SyamlalOBrienDrag(const dictionary& coeffs)
:
    c1_
    (
        mppicCoefficients::read
        (
            coeffs,
            "c1",
            0.8,
            mppicCoefficients::bounds::above(0)
        )
    ),
    d1_
    (
        mppicCoefficients::read
        (
            coeffs,
            "d1",
            2.65,
            mppicCoefficients::bounds::above(0)
        )
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dragLaws::SyamlalOBrienDrag::K
(
    const scalar alphag,
    const scalar slip,
    const scalar d,
    const scalar rhog,
    const scalar mug
) const
{
    return
        dragCorrelations::syamlalOBrienK
        (
            alphag, slip, d, rhog, mug, c1_, d1_
        );
}


// ************************************************************************* //
