/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "reactingCloudBalance.H"
#include "rhoReactionThermo.H"
#include "fvc.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(reactingCloudBalance, 0);
    addToRunTimeSelectionTable
    (
        functionObject,
        reactingCloudBalance,
        dictionary
    );
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

const Foam::basicReactingMPPICCloud&
Foam::functionObjects::reactingCloudBalance::cloud() const
{
    return dynamic_cast<const basicReactingMPPICCloud&>
    (
        lookupObject<kinematicCloud>(cloudName_)
    );
}


void Foam::functionObjects::reactingCloudBalance::addGas(sample& s) const
{
    const rhoReactionThermo& thermo =
        lookupObject<rhoReactionThermo>(basicThermo::dictName);
    const basicSpecieMixture& composition = thermo.composition();
    const volScalarField& alpha = lookupObject<volScalarField>(alphaName_);
    const volVectorField& U = lookupObject<volVectorField>(UName_);
    const volScalarField& rho = lookupObject<volScalarField>("rho");

    const volScalarField alphaRho(alpha*rho);

    volScalarField h(thermo.he() + 0.5*magSqr(U));
    forAll(composition.Y(), i)
    {
        h += dimensionedScalar("Hc", h.dimensions(), composition.Hc(i))
           *composition.Y(i);
    }

    s.gasMass = fvc::domainIntegrate(alphaRho).value();
    s.gasEnthalpy = fvc::domainIntegrate(alphaRho*h).value();

    s.gasSpecies.setSize(species_.size());
    forAll(species_, k)
    {
        s.gasSpecies[k] =
            fvc::domainIntegrate(alphaRho*composition.Y(species_[k])).value();
    }
}


void Foam::functionObjects::reactingCloudBalance::addCloud(sample& s) const
{
    const basicReactingMPPICCloud& c = cloud();
    const liquidMixtureProperties& liquids = c.thermo().liquids();
    const wordList& components = c.composition().componentNames(0);
    const bool liquidPhase = (c.composition().idLiquid() == 0);
    const volScalarField& p = c.p();

    // Liquid-properties index of each component, -1 when not a liquid
    labelList liquidId(components.size(), -1);
    forAll(components, j)
    {
        if (liquidPhase)
        {
            liquidId[j] = c.thermo().liquidId(components[j]);
        }
    }

    s.cloudSpecies.setSize(species_.size(), Zero);
    for (const basicReactingMPPICParcel& parcel : c)
    {
        const scalar nm = parcel.nParticle()*parcel.mass();
        s.cloudMass += nm;
        s.cloudEnthalpy += 0.5*nm*magSqr(parcel.U());

        forAll(components, j)
        {
            const scalar mj = nm*parcel.Y()[j];
            if (liquidId[j] >= 0)
            {
                s.cloudEnthalpy +=
                    mj*liquids.properties()[liquidId[j]]
                      .h(p[parcel.cell()], parcel.T());
            }
            const label k = species_.find(components[j]);
            if (k >= 0)
            {
                s.cloudSpecies[k] += mj;
            }
        }
    }

    reduce(s.cloudMass, sumOp<scalar>());
    reduce(s.cloudEnthalpy, sumOp<scalar>());
    forAll(s.cloudSpecies, k)
    {
        reduce(s.cloudSpecies[k], sumOp<scalar>());
    }
}


void Foam::functionObjects::reactingCloudBalance::writeFileHeader(Ostream& os)
{
    writeHeader(os, "Mass and enthalpy of the gas and cloud " + cloudName_);
    writeCommented(os, "Time");
    writeTabbed(os, "gasMass");
    writeTabbed(os, "cloudMass");
    for (const word& name : species_)
    {
        writeTabbed(os, "gas:" + name);
        writeTabbed(os, "cloud:" + name);
        writeTabbed(os, "total:" + name);
    }
    writeTabbed(os, "gasEnthalpy");
    writeTabbed(os, "cloudEnthalpy");
    writeTabbed(os, "totalEnthalpy");
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::reactingCloudBalance::reactingCloudBalance
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    cloudName_("reactingCloud"),
    species_(),
    alphaName_("alpha.gas"),
    UName_("U")
{
    read(dict);

    if (writeToFile())
    {
        writeFileHeader(file());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::reactingCloudBalance::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    cloudName_ = dict.lookupOrDefault<word>("cloud", "reactingCloud");
    species_ = dict.lookupOrDefault<wordList>("species", wordList());
    alphaName_ = dict.lookupOrDefault<word>("alpha", "alpha.gas");
    UName_ = dict.lookupOrDefault<word>("U", "U");

    if
    (
        !foundObject<kinematicCloud>(cloudName_)
     || !dynamic_cast<const basicReactingMPPICCloud*>
        (
            &lookupObject<kinematicCloud>(cloudName_)
        )
    )
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ", keyword cloud: no reacting"
            << " MPPIC cloud (basicReactingMPPICCloud) named " << cloudName_
            << exit(FatalIOError);
    }

    const basicSpecieMixture& composition =
        lookupObject<rhoReactionThermo>(basicThermo::dictName).composition();
    for (const word& name : species_)
    {
        if (!composition.species().found(name))
        {
            FatalIOErrorInFunction(dict)
                << "Dictionary " << dict.name() << ", keyword species: "
                << name << " is not one of the gas species "
                << composition.species() << exit(FatalIOError);
        }
    }

    return true;
}


Foam::functionObjects::reactingCloudBalance::sample
Foam::functionObjects::reactingCloudBalance::evaluate() const
{
    sample s;
    addGas(s);
    addCloud(s);
    return s;
}


bool Foam::functionObjects::reactingCloudBalance::execute()
{
    return true;
}


bool Foam::functionObjects::reactingCloudBalance::write()
{
    const sample s = evaluate();

    if (writeToFile())
    {
        OFstream& os = file();
        os.precision(16);
        writeCurrentTime(os);
        os  << tab << s.gasMass << tab << s.cloudMass;
        forAll(species_, k)
        {
            os  << tab << s.gasSpecies[k] << tab << s.cloudSpecies[k]
                << tab << s.gasSpecies[k] + s.cloudSpecies[k];
        }
        os  << tab << s.gasEnthalpy << tab << s.cloudEnthalpy
            << tab << s.gasEnthalpy + s.cloudEnthalpy << endl;
    }

    return true;
}


// ************************************************************************* //
