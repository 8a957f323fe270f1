/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "closePack.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::PackingModels::readClosePackFraction
(
    const dictionary& coeffs
)
{
    return mppicCoefficients::read
    (
        coeffs, "closePackFraction", mppicCoefficients::bounds::open(0, 1)
    );
}


Foam::scalar Foam::PackingModels::closePackFractionOf
(
    const dictionary& subModels
)
{
    const word model(subModels.get<word>("packingModel"));
    const dictionary& coeffs = subModels.subOrEmptyDict(model + "Coeffs");

    if (coeffs.found("closePackFraction"))
    {
        return readClosePackFraction(coeffs);
    }
    if (coeffs.isDict("particleStressModel"))
    {
        return mppicCoefficients::read
        (
            coeffs.subDict("particleStressModel"),
            "alphaPacked",
            mppicCoefficients::bounds::open(0, 1)
        );
    }
    return 0;
}


// ************************************************************************* //
