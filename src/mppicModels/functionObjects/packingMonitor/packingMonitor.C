/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "packingMonitor.H"
#include "solidsFractionDeposition.H"
#include "DensePackingModel.H"
#include "closePack.H"
#include "wallPolyPatch.H"
#include "volFields.H"
#include "extrapolatedCalculatedFvPatchFields.H"
#include "boundedCoefficient.H"
#include "addToRunTimeSelectionTable.H"
#include "packingMonitorTemplates.C"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(packingMonitor, 0);
    addToRunTimeSelectionTable(functionObject, packingMonitor, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::functionObjects::packingMonitor::readClosePackFraction
(
    const dictionary& dict
) const
{
    if (dict.found("closePackFraction"))
    {
        return
            mppicCoefficients::read
            (
                dict, "closePackFraction", mppicCoefficients::bounds::open(0, 1)
            );
    }

    // The packing family reads it from the model's coefficients: ours
    // keep closePackFraction, the stock ones their particle stress
    // model's alphaPacked
    const dictionary& subModels = cloudProperties().subDict("subModels");
    const scalar fromModel = PackingModels::closePackFractionOf(subModels);

    if (fromModel <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ": keyword closePackFraction"
            << " is missing and packing model "
            << subModels.get<word>("packingModel") << " of cloud "
            << cloudName_ << " does not give one; allowed range (0, 1)"
            << exit(FatalIOError);
    }

    return fromModel;
}


const Foam::dictionary&
Foam::functionObjects::packingMonitor::cloudProperties() const
{
    if (const basicKinematicMPPICCloud* c = cloudAs<basicKinematicMPPICCloud>())
    {
        return c->particleProperties();
    }
    if (const basicReactingMPPICCloud* c = cloudAs<basicReactingMPPICCloud>())
    {
        return c->particleProperties();
    }

    FatalErrorInFunction
        << "Cloud " << cloudName_ << " is not an MPPIC cloud"
        << " (basicKinematicMPPICCloud, basicReactingMPPICCloud)"
        << exit(FatalError);

    return dictionary::null;
}


void Foam::functionObjects::packingMonitor::markWallCells()
{
    wallCells_.setSize(mesh_.nCells());
    wallCells_ = false;

    for (const polyPatch& patch : mesh_.boundaryMesh())
    {
        if (isA<wallPolyPatch>(patch))
        {
            for (const label celli : patch.faceCells())
            {
                wallCells_[celli] = true;
            }
        }
    }
}


bool Foam::functionObjects::packingMonitor::readWritePackingForce
(
    const dictionary& dict
) const
{
    const bool wanted = dict.lookupOrDefault<bool>("writePackingForce", false);
    if (!wanted)
    {
        return false;
    }

    // The field sums every step's momentum: the monitor must see each step
    const word control =
        dict.lookupOrDefault<word>("writeControl", "timeStep");
    if (control != "timeStep")
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ": writePackingForce true"
            << " needs the monitor at every time step, but keyword"
            << " writeControl is " << control << "; allowed: timeStep"
            << exit(FatalIOError);
    }

    const scalar interval = dict.lookupOrDefault<scalar>("writeInterval", 1);
    if (interval != 1)
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ": writePackingForce true"
            << " needs the monitor at every time step, but keyword"
            << " writeInterval is " << interval << "; allowed: 1"
            << exit(FatalIOError);
    }

    return true;
}


void Foam::functionObjects::packingMonitor::sumPackingForce()
{
    const tmp<vectorField> tmomentum
    (
        cloudAs<basicKinematicMPPICCloud>()
      ? cellPackingMomentum(*cloudAs<basicKinematicMPPICCloud>())
      : cellPackingMomentum(*cloudAs<basicReactingMPPICCloud>())
    );

    if (addedMomentum_.size() != mesh_.nCells())
    {
        addedMomentum_.setSize(mesh_.nCells());
        addedMomentum_ = Zero;
        addedTime_ = 0;
    }
    addedMomentum_ += tmomentum();
    addedTime_ += time_.deltaTValue();

    if (!time_.writeTime())
    {
        return;
    }

    volVectorField packingForce
    (
        IOobject
        (
            "packingForce",
            time_.timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh_,
        dimensionedVector(dimForce/dimVolume, Zero),
        extrapolatedCalculatedFvPatchVectorField::typeName
    );
    packingForce.primitiveFieldRef() = addedMomentum_/(mesh_.V()*addedTime_);
    packingForce.correctBoundaryConditions();
    packingForce.write();

    addedMomentum_ = Zero;
    addedTime_ = 0;
}


void Foam::functionObjects::packingMonitor::writeFileHeader(Ostream& os)
{
    writeHeader(os, "Packing monitor of cloud " + cloudName_);
    writeHeaderValue(os, "closePackFraction", closePackFraction_);
    writeHeaderValue(os, "averagingMethod", word
    (
        cloudProperties().subDict("solution").get<word>("averagingMethod")
    ));
    writeCommented(os, "Time");
    for
    (
        const char* column :
        {
            "nParcels", "mass", "maxAlphaAveraged", "maxAlphaCell",
            "nCellsAboveClosePack", "minGasFraction", "nFastParcels",
            "packingMomentumX", "packingMomentumY", "packingMomentumZ",
            "wallPackingMomentumX", "wallPackingMomentumY",
            "wallPackingMomentumZ", "gasPackingMomentumX",
            "gasPackingMomentumY", "gasPackingMomentumZ"
        }
    )
    {
        writeTabbed(os, column);
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::packingMonitor::packingMonitor
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    cloudName_("kinematicCloud"),
    closePackFraction_(0),
    wallCells_()
{
    read(dict);
    markWallCells();

    if (writeToFile())
    {
        writeFileHeader(file());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::packingMonitor::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    cloudName_ = dict.lookupOrDefault<word>("cloud", "kinematicCloud");

    if
    (
        !foundObject<kinematicCloud>(cloudName_)
     || (
            !cloudAs<basicKinematicMPPICCloud>()
         && !cloudAs<basicReactingMPPICCloud>()
        )
    )
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ", keyword cloud: no MPPIC"
            << " cloud (basicKinematicMPPICCloud, basicReactingMPPICCloud)"
            << " named " << cloudName_ << exit(FatalIOError);
    }

    closePackFraction_ = readClosePackFraction(dict);
    writePackingForce_ = readWritePackingForce(dict);
    phases_.reset(new cloudPhases(mesh_, name(), cloudName_, writeToFile()));

    return true;
}


Foam::functionObjects::packingMonitor::sample
Foam::functionObjects::packingMonitor::evaluate() const
{
    if (const basicKinematicMPPICCloud* c = cloudAs<basicKinematicMPPICCloud>())
    {
        return evaluate(*c);
    }
    return evaluate(*cloudAs<basicReactingMPPICCloud>());
}


bool Foam::functionObjects::packingMonitor::execute()
{
    return true;
}


bool Foam::functionObjects::packingMonitor::write()
{
    const sample s = evaluate();

    if (writePackingForce_)
    {
        sumPackingForce();
    }

    Log << type() << " " << name() << ": max solids fraction "
        << s.maxAlphaAveraged << " (averaged), " << s.maxAlphaCell
        << " (cell); cells above close pack " << s.nCellsAboveClosePack
        << "; parcels crossing > 1 cell " << s.nFastParcels << endl;
    phases_->evaluate();

    if (writeToFile())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        os  << tab << s.nParcels << tab << s.mass
            << tab << s.maxAlphaAveraged << tab << s.maxAlphaCell
            << tab << s.nCellsAboveClosePack << tab << 1 - s.maxAlphaCell
            << tab << s.nFastParcels;
        for
        (
            const vector& v
          : {s.packingMomentum, s.wallPackingMomentum, s.gasPackingMomentum}
        )
        {
            os  << tab << v.x() << tab << v.y() << tab << v.z();
        }
        os  << endl;
    }

    return true;
}


// ************************************************************************* //
