/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "solidsFractionDeposition.H"
#include "AveragingMethod.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::Enum<Foam::solidsFractionDeposition::method>
Foam::solidsFractionDeposition::methodNames
({
    { method::cell, "cell" },
    { method::averaging, "averaging" },
});


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::solidsFractionDeposition::method
Foam::solidsFractionDeposition::readMethod(const dictionary& dict)
{
    const word name
    (
        dict.lookupOrDefault<word>("solidsFractionFrom", methodNames[method::cell])
    );

    if (!methodNames.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ", keyword solidsFractionFrom:"
            << " value " << name << " is not one of " << methodNames.toc()
            << exit(FatalIOError);
    }
    return methodNames[name];
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidsFractionDeposition::solidsFractionDeposition
(
    const dictionary& cloudProperties
)
:
    method_(readMethod(cloudProperties))
{}


// ************************************************************************* //
