/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "uniform.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePrescribedGasFlow(uniform);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::prescribedGasFlows::uniform::uniform(const dictionary& dict)
:
    prescribedGasFlow(dict),
    U_(dict.get<vector>("U"))
{
    Info<< "    U " << U_ << " m/s" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::vectorField> Foam::prescribedGasFlows::uniform::velocity
(
    const vectorField& x,
    const scalar
) const
{
    return tmp<vectorField>::New(x.size(), U_);
}


// ************************************************************************* //
