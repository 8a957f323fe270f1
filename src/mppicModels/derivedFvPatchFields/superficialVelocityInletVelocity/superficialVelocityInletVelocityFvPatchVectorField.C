/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "superficialVelocityInletVelocityFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::word
Foam::superficialVelocityInletVelocityFvPatchVectorField::defaultAlphaName()
const
{
    return IOobject::groupName("alpha", internalField().group());
}


const Foam::fvPatchScalarField&
Foam::superficialVelocityInletVelocityFvPatchVectorField::patchGasFraction()
const
{
    if (!db().foundObject<volScalarField>(alphaName_))
    {
        FatalIOErrorInFunction(dict_)
            << "Patch " << patch().name() << " of " << internalField().name()
            << ", keyword alpha: no volScalarField " << alphaName_
            << " is registered; available: "
            << db().sortedNames<volScalarField>()
            << exit(FatalIOError);
    }

    const fvPatchScalarField& alphap =
        patch().lookupPatchField<volScalarField, scalar>(alphaName_);

    if (alphap.size() && !(min(alphap) > 0))
    {
        FatalIOErrorInFunction(dict_)
            << "Patch " << patch().name() << " of " << internalField().name()
            << ", keyword alpha: gas fraction " << alphaName_
            << " on the patch is " << min(alphap)
            << "; the allowed range is (0, 1]" << exit(FatalIOError);
    }

    return alphap;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::superficialVelocityInletVelocityFvPatchVectorField::
superficialVelocityInletVelocityFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    fixedValueFvPatchVectorField(p, iF),
    superficialVelocity_(),
    alphaName_(defaultAlphaName()),
    dict_()
{}


Foam::superficialVelocityInletVelocityFvPatchVectorField::
superficialVelocityInletVelocityFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    fixedValueFvPatchVectorField(p, iF, dict, false),
    superficialVelocity_
    (
        Function1<vector>::New("superficialVelocity", dict)
    ),
    alphaName_(dict.lookupOrDefault<word>("alpha", defaultAlphaName())),
    dict_(dict)
{
    if (dict.found("value"))
    {
        fvPatchVectorField::operator=
        (
            vectorField("value", dict, p.size())
        );
    }
    else
    {
        fvPatchVectorField::operator=(superficialVelocity());
    }
}


Foam::superficialVelocityInletVelocityFvPatchVectorField::
superficialVelocityInletVelocityFvPatchVectorField
(
    const superficialVelocityInletVelocityFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    fixedValueFvPatchVectorField(ptf, p, iF, mapper),
    superficialVelocity_(ptf.superficialVelocity_.clone()),
    alphaName_(ptf.alphaName_),
    dict_(ptf.dict_)
{}


Foam::superficialVelocityInletVelocityFvPatchVectorField::
superficialVelocityInletVelocityFvPatchVectorField
(
    const superficialVelocityInletVelocityFvPatchVectorField& ptf
)
:
    fixedValueFvPatchVectorField(ptf),
    superficialVelocity_(ptf.superficialVelocity_.clone()),
    alphaName_(ptf.alphaName_),
    dict_(ptf.dict_)
{}


Foam::superficialVelocityInletVelocityFvPatchVectorField::
superficialVelocityInletVelocityFvPatchVectorField
(
    const superficialVelocityInletVelocityFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    fixedValueFvPatchVectorField(ptf, iF),
    superficialVelocity_(ptf.superficialVelocity_.clone()),
    alphaName_(ptf.alphaName_),
    dict_(ptf.dict_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector
Foam::superficialVelocityInletVelocityFvPatchVectorField::superficialVelocity()
const
{
    return superficialVelocity_->value(db().time().timeOutputValue());
}


void Foam::superficialVelocityInletVelocityFvPatchVectorField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    const scalarField& gasFraction = patchGasFraction();

    operator==(vectorField(size(), superficialVelocity())/gasFraction);

    fixedValueFvPatchVectorField::updateCoeffs();
}


void Foam::superficialVelocityInletVelocityFvPatchVectorField::write
(
    Ostream& os
) const
{
    fvPatchVectorField::write(os);
    superficialVelocity_->writeData(os);
    os.writeEntry("alpha", alphaName_);
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchVectorField,
        superficialVelocityInletVelocityFvPatchVectorField
    );
}

// ************************************************************************* //
