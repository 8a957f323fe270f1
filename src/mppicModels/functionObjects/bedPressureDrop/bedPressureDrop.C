/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "bedPressureDrop.H"
#include "volFields.H"
#include "kinematicCloud.H"
#include "gravityMeshObject.H"
#include "addToRunTimeSelectionTable.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(bedPressureDrop, 0);
    addToRunTimeSelectionTable(functionObject, bedPressureDrop, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::functionObjects::bedPressureDrop::patchIndex
(
    const dictionary& dict,
    const word& keyword
) const
{
    const word patchName(dict.get<word>(keyword));
    const label patchi = mesh_.boundaryMesh().findPatchID(patchName);

    if (patchi < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ", keyword " << keyword
            << ": unknown patch " << patchName << nl
            << "Valid patches: " << mesh_.boundaryMesh().names()
            << exit(FatalIOError);
    }

    return patchi;
}


Foam::scalar Foam::functionObjects::bedPressureDrop::patchMeanDensity
(
    const label patchi
) const
{
    if (rhoName_ == "rhoInf")
    {
        return rhoInf_;
    }

    const volScalarField& rho = lookupObject<volScalarField>(rhoName_);

    return patchAverage(patchi, rho.boundaryField()[patchi]);
}


void Foam::functionObjects::bedPressureDrop::checkRhoInf
(
    const dictionary& dict
) const
{
    // Before the solver's fields exist (e.g. a function object constructed
    // on its own) there is nothing to compare with
    const volScalarField* pPtr = findObject<volScalarField>(pName_);
    if (!pPtr || pPtr->dimensions() == dimPressure)
    {
        return;
    }

    const HashTable<const volScalarField*> fields
    (
        mesh_.lookupClass<volScalarField>()
    );
    forAllConstIters(fields, iter)
    {
        const volScalarField& rho = *iter();
        if (rho.dimensions() != dimDensity)
        {
            continue;
        }
        const scalar rhoMin = gMin(rho.primitiveField());
        const scalar rhoMax = gMax(rho.primitiveField());
        if
        (
            rhoMax - rhoMin <= 1e-12*rhoMax
         && mag(rhoInf_ - rhoMax) > 1e-6*rhoMax
        )
        {
            FatalIOErrorInFunction(dict)
                << "Dictionary " << dict.name() << ", keyword rhoInf: value "
                << rhoInf_ << " differs from the gas density field "
                << rho.name() << " (" << rhoMax << " kg/m3) that the "
                << "kinematic pressure " << pName_ << " is converted to Pa with;"
                << " it must equal it (to 1e-6), or set rho " << rho.name()
                << exit(FatalIOError);
        }
    }
}


Foam::scalar Foam::functionObjects::bedPressureDrop::patchMeanPressure
(
    const label patchi
) const
{
    const volScalarField& p = lookupObject<volScalarField>(pName_);

    const scalar meanP = patchAverage(patchi, p.boundaryField()[patchi]);

    if (p.dimensions() == dimPressure)
    {
        return meanP;
    }

    return patchMeanDensity(patchi)*meanP;
}


void Foam::functionObjects::bedPressureDrop::writeFileHeader(Ostream& os)
{
    writeHeader(os, "Bed pressure drop [Pa]");
    writeHeaderValue(os, "lowerPatch", mesh_.boundaryMesh()[lowerPatchi_].name());
    writeHeaderValue(os, "upperPatch", mesh_.boundaryMesh()[upperPatchi_].name());
    writeCommented(os, "Time");
    writeTabbed(os, "pLower");
    writeTabbed(os, "pUpper");
    writeTabbed(os, "deltaP");
    writeTabbed(os, "gasHead");
    if (!cloudName_.empty())
    {
        writeTabbed(os, "weightPerArea");
        writeTabbed(os, "deltaPByWeight");
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::bedPressureDrop::bedPressureDrop
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    lowerPatchi_(-1),
    upperPatchi_(-1),
    pName_("p"),
    rhoName_("rhoInf"),
    rhoInf_(0),
    cloudName_(),
    crossSection_(0)
{
    read(dict);

    if (writeToFile())
    {
        writeFileHeader(file());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::bedPressureDrop::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    lowerPatchi_ = patchIndex(dict, "lowerPatch");
    upperPatchi_ = patchIndex(dict, "upperPatch");

    if (lowerPatchi_ == upperPatchi_)
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ": lowerPatch and upperPatch"
            << " are the same patch "
            << mesh_.boundaryMesh()[lowerPatchi_].name()
            << exit(FatalIOError);
    }

    pName_ = dict.lookupOrDefault<word>("p", "p");
    rhoName_ = dict.lookupOrDefault<word>("rho", "rhoInf");

    if (rhoName_ == "rhoInf")
    {
        rhoInf_ = dict.get<scalar>("rhoInf");

        if (rhoInf_ <= 0)
        {
            FatalIOErrorInFunction(dict)
                << "Dictionary " << dict.name() << ", keyword rhoInf: value "
                << rhoInf_ << " out of range; it must be > 0 [kg/m3]"
                << exit(FatalIOError);
        }

        checkRhoInf(dict);
    }

    cloudName_ = dict.lookupOrDefault<word>("cloud", word::null);
    phases_.clear();
    if (!cloudName_.empty())
    {
        phases_.reset
        (
            new cloudPhases(mesh_, name(), cloudName_, writeToFile())
        );
    }

    crossSection_ = 0;
    if (dict.found("crossSection"))
    {
        crossSection_ =
            mppicCoefficients::read
            (
                dict,
                "crossSection",
                mppicCoefficients::bounds::above(0)
            );
    }

    return true;
}


Foam::scalar Foam::functionObjects::bedPressureDrop::deltaP() const
{
    return patchMeanPressure(lowerPatchi_) - patchMeanPressure(upperPatchi_);
}


Foam::scalar Foam::functionObjects::bedPressureDrop::gasHead() const
{
    const vector& g = meshObjects::gravity::New(time_).value();

    const vector lowerCentre =
        patchAverage(lowerPatchi_, mesh_.boundary()[lowerPatchi_].Cf());
    const vector upperCentre =
        patchAverage(upperPatchi_, mesh_.boundary()[upperPatchi_].Cf());

    return patchMeanDensity(lowerPatchi_)*(g & (lowerCentre - upperCentre));
}


Foam::scalar Foam::functionObjects::bedPressureDrop::bedWeightPerArea() const
{
    if (cloudName_.empty())
    {
        return 0;
    }

    const kinematicCloud& cloud = lookupObject<kinematicCloud>(cloudName_);
    const scalar magG = mag(meshObjects::gravity::New(time_).value());
    const scalar area =
        crossSection_ > 0
      ? crossSection_
      : gSum(mesh_.boundary()[lowerPatchi_].magSf());

    // massInSystem() sums this processor's parcels only
    const scalar mass = returnReduce(cloud.massInSystem(), sumOp<scalar>());

    return mass*magG/max(area, VSMALL);
}


bool Foam::functionObjects::bedPressureDrop::execute()
{
    return true;
}


bool Foam::functionObjects::bedPressureDrop::write()
{
    const scalar pLower = patchMeanPressure(lowerPatchi_);
    const scalar pUpper = patchMeanPressure(upperPatchi_);
    const scalar dP = pLower - pUpper;
    // Collective (reductions): evaluated on every processor, not only on
    // the master that writes the file
    const scalar head = gasHead();
    const scalar weight = bedWeightPerArea();

    Log << type() << " " << name() << ": deltaP = " << dP << " Pa";
    if (!cloudName_.empty())
    {
        Log << ", bed weight/area = " << weight << " Pa"
            << ", deltaP/weight = " << dP/max(weight, VSMALL);
    }
    Log << endl;
    if (phases_.valid())
    {
        phases_->evaluate();
    }

    if (writeToFile())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        os  << tab << pLower << tab << pUpper << tab << dP
            << tab << head;
        if (!cloudName_.empty())
        {
            os  << tab << weight << tab << dP/max(weight, VSMALL);
        }
        os  << endl;
    }

    return true;
}


// ************************************************************************* //
