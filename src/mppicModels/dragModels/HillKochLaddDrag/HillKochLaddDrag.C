/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "HillKochLaddDrag.H"
#include "dragCorrelations.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dragLaws::HillKochLaddDrag::HillKochLaddDrag(const dictionary& /*coeffs*/)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dragLaws::HillKochLaddDrag::K
(
    const scalar alphag,
    const scalar slip,
    const scalar d,
    const scalar rhog,
    const scalar mug
) const
{
    return dragCorrelations::hillKochLaddK(alphag, slip, d, rhog, mug);
}


// ************************************************************************* //
