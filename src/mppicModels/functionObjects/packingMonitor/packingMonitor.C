/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "packingMonitor.H"
#include "AveragingMethod.H"
#include "MfixPackingModel.H"
#include "wallPolyPatch.H"
#include "boundedCoefficient.H"
#include "addToRunTimeSelectionTable.H"

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
    const mppicCoefficients::interval range =
        mppicCoefficients::bounds::open(0, 1);

    if (dict.found("closePackFraction"))
    {
        return mppicCoefficients::read(dict, "closePackFraction", range);
    }

    // From the cloud's packing model
    const dictionary& subModels =
        cloud().particleProperties().subDict("subModels");

    const word model(subModels.get<word>("packingModel"));
    const dictionary& coeffs = subModels.subOrEmptyDict(model + "Coeffs");

    if (coeffs.found("closePackFraction"))
    {
        return mppicCoefficients::read(coeffs, "closePackFraction", range);
    }
    if (coeffs.isDict("particleStressModel"))
    {
        return
            mppicCoefficients::read
            (
                coeffs.subDict("particleStressModel"), "alphaPacked", range
            );
    }

    FatalIOErrorInFunction(dict)
        << "Dictionary " << dict.name() << ": keyword closePackFraction"
        << " is missing and packing model " << model << " of cloud "
        << cloudName_ << " does not give one; allowed range " << range
        << exit(FatalIOError);

    return 0;
}


const Foam::basicKinematicMPPICCloud&
Foam::functionObjects::packingMonitor::cloud() const
{
    // Looked up through its abstract base: the cloud's own typeName is
    // ambiguous (kinematicCloud and Cloud both declare one)
    const basicKinematicMPPICCloud* cloudPtr =
        dynamic_cast<const basicKinematicMPPICCloud*>
        (
            &lookupObject<kinematicCloud>(cloudName_)
        );

    if (!cloudPtr)
    {
        FatalErrorInFunction
            << "Cloud " << cloudName_ << " is not a basicKinematicMPPICCloud"
            << exit(FatalError);
    }

    return *cloudPtr;
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


Foam::scalar
Foam::functionObjects::packingMonitor::maxAveragedSolidsFraction
(
    const basicKinematicMPPICCloud& cloud
) const
{
    autoPtr<AveragingMethod<scalar>> average
    (
        AveragingMethod<scalar>::New
        (
            IOobject
            (
                cloudName_ + ":packingMonitorAverage",
                time_.timeName(),
                mesh_,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            cloud.solution().dict(),
            mesh_
        )
    );

    for (const basicKinematicMPPICCloud::parcelType& p : cloud)
    {
        average->add
        (
            p.coordinates(),
            p.currentTetIndices(),
            p.nParticle()*p.volume()
        );
    }
    average->average();

    scalar maxAlpha = 0;
    for (const Field<scalar>& values : average())
    {
        for (const scalar alpha : values)
        {
            maxAlpha = max(maxAlpha, alpha);
        }
    }

    return returnReduce(maxAlpha, maxOp<scalar>());
}


void Foam::functionObjects::packingMonitor::writeFileHeader(Ostream& os)
{
    writeHeader(os, "Packing monitor of cloud " + cloudName_);
    writeHeaderValue(os, "closePackFraction", closePackFraction_);
    writeHeaderValue(os, "averagingMethod", word
    (
        cloud().solution().dict().get<word>("averagingMethod")
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
            "wallPackingMomentumZ"
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
     || !dynamic_cast<const basicKinematicMPPICCloud*>
        (
            &lookupObject<kinematicCloud>(cloudName_)
        )
    )
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ", keyword cloud: no MPPIC"
            << " cloud (basicKinematicMPPICCloud) named " << cloudName_
            << exit(FatalIOError);
    }

    closePackFraction_ = readClosePackFraction(dict);

    return true;
}


Foam::functionObjects::packingMonitor::sample
Foam::functionObjects::packingMonitor::evaluate() const
{
    const basicKinematicMPPICCloud& cloud = this->cloud();

    const scalar deltaT = time_.deltaTValue();
    const scalarField& V = mesh_.V();

    sample s;
    scalarField solidsVolume(mesh_.nCells(), Zero);

    for (const basicKinematicMPPICCloud::parcelType& p : cloud)
    {
        const label celli = p.cell();
        const scalar m = p.nParticle()*p.mass();
        const vector momentum = m*p.UCorrect();

        ++s.nParcels;
        s.mass += m;
        solidsVolume[celli] += p.nParticle()*p.volume();
        s.packingMomentum += momentum;

        if (wallCells_[celli])
        {
            s.wallPackingMomentum += momentum;
        }
        if (mag(p.U())*deltaT > cbrt(V[celli]))
        {
            ++s.nFastParcels;
        }
    }

    const scalarField alphaCell(solidsVolume/V);
    forAll(alphaCell, celli)
    {
        s.maxAlphaCell = max(s.maxAlphaCell, alphaCell[celli]);
        if (alphaCell[celli] > closePackFraction_)
        {
            ++s.nCellsAboveClosePack;
        }
    }

    // Our packing models record the velocity change they gave, which can
    // differ from UCorrect (a move back out of a full cell is a
    // displacement, not a velocity: ColoringFunction)
    typedef PackingModels::MfixPackingModel
    <
        basicKinematicMPPICCloud::MPPICCloudType
    > mfixModel;

    const mfixModel* ours =
        dynamic_cast<const mfixModel*>(&cloud.packingModel());

    if (ours && ours->cellAddedMomentum().size() == mesh_.nCells())
    {
        s.packingMomentum = Zero;
        s.wallPackingMomentum = Zero;
        forAll(wallCells_, celli)
        {
            const vector& momentum = ours->cellAddedMomentum()[celli];
            s.packingMomentum += momentum;
            if (wallCells_[celli])
            {
                s.wallPackingMomentum += momentum;
            }
        }
    }

    reduce(s.nParcels, sumOp<label>());
    reduce(s.mass, sumOp<scalar>());
    reduce(s.maxAlphaCell, maxOp<scalar>());
    reduce(s.nCellsAboveClosePack, sumOp<label>());
    reduce(s.nFastParcels, sumOp<label>());
    reduce(s.packingMomentum, sumOp<vector>());
    reduce(s.wallPackingMomentum, sumOp<vector>());

    s.maxAlphaAveraged = maxAveragedSolidsFraction(cloud);

    return s;
}


bool Foam::functionObjects::packingMonitor::execute()
{
    return true;
}


bool Foam::functionObjects::packingMonitor::write()
{
    const sample s = evaluate();

    Log << type() << " " << name() << ": max solids fraction "
        << s.maxAlphaAveraged << " (averaged), " << s.maxAlphaCell
        << " (cell); cells above close pack " << s.nCellsAboveClosePack
        << "; parcels crossing > 1 cell " << s.nFastParcels << endl;

    if (writeToFile())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        os  << tab << s.nParcels << tab << s.mass
            << tab << s.maxAlphaAveraged << tab << s.maxAlphaCell
            << tab << s.nCellsAboveClosePack << tab << 1 - s.maxAlphaCell
            << tab << s.nFastParcels;
        for (const vector& v : {s.packingMomentum, s.wallPackingMomentum})
        {
            os  << tab << v.x() << tab << v.y() << tab << v.z();
        }
        os  << endl;
    }

    return true;
}


// ************************************************************************* //
