/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "MfixSnider.H"
#include "cellFaceGeometry.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

template<class CloudType>
const Foam::wordList
Foam::PackingModels::MfixSnider<CloudType>::keywords
({
    "pSolid", "gamma", "eps", "e1", "slipVelocityFactor", "releaseAbove",
    "collisionDamping"
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
const Foam::dictionary&
Foam::PackingModels::MfixSnider<CloudType>::checkedCoeffs
(
    const dictionary& coeffs
)
{
    // The gas cannot take the limiter's reactions at once: its solution
    // diverges
    if (coeffs.lookupOrDefault<word>("conserveMomentum", "none") == "gas")
    {
        FatalIOErrorInFunction(coeffs)
            << "Dictionary " << coeffs.name()
            << ", keyword conserveMomentum: value gas is not"
            << " available with mfixSnider (allowed: none, packs)"
            << exit(FatalIOError);
    }
    return coeffs;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PackingModels::MfixSnider<CloudType>::MfixSnider
(
    const dictionary& dict,
    CloudType& owner
)
:
    DensePackingModel<CloudType>(dict, owner, typeName, keywords),
    rules_(checkedCoeffs(this->coeffs()), this->closePackFraction()),
    collisionDamping_
    (
        this->coeffs().template lookupOrDefault<bool>("collisionDamping", false)
    ),
    stressGradient_(owner.mesh()),
    cellAlpha_(),
    damping_(rules_.e1(), this->closePackFraction()),
    previousMeanVelocity_(nullptr)
{
    meanVelocity();
}


template<class CloudType>
Foam::PackingModels::MfixSnider<CloudType>::MfixSnider
(
    const MfixSnider<CloudType>& cm
)
:
    DensePackingModel<CloudType>(cm),
    rules_(cm.rules_),
    collisionDamping_(cm.collisionDamping_),
    stressGradient_(cm.owner().mesh()),
    cellAlpha_(),
    damping_(rules_.e1(), this->closePackFraction()),
    previousMeanVelocity_(nullptr)
{}


template<class CloudType>
Foam::volVectorField&
Foam::PackingModels::MfixSnider<CloudType>::meanVelocity()
{
    const fvMesh& mesh = this->owner().mesh();
    const word name(meanVelocityName(this->owner().name()));

    volVectorField* fieldPtr = mesh.getObjectPtr<volVectorField>(name);
    if (!fieldPtr)
    {
        // Read on a restart; else zero, the mean of parcels at rest
        fieldPtr = new volVectorField
        (
            IOobject
            (
                name,
                mesh.time().timeName(),
                mesh,
                IOobject::READ_IF_PRESENT,
                IOobject::AUTO_WRITE
            ),
            mesh,
            dimensionedVector(dimVelocity, Zero),
            zeroGradientFvPatchVectorField::typeName
        );
        fieldPtr->store();

        if (fieldPtr->headerOk())
        {
            Info<< "mfixSnider: mean solids velocity of the previous step "
                << "read from " << fieldPtr->objectPath() << endl;
        }
    }
    return *fieldPtr;
}


template<class CloudType>
void Foam::PackingModels::MfixSnider<CloudType>::storeMeanVelocity()
{
    const fvMesh& mesh = this->owner().mesh();
    const linearHatKernel& kernel = linearHatKernel::New(mesh);

    // Cells, then the ghosts across processor faces
    const label nCells = mesh.nCells();
    scalarField mass(nCells + kernel.nGhosts(), Zero);
    vectorField momentum(nCells + kernel.nGhosts(), Zero);

    // One kernel evaluation per parcel for both sums; the ratio needs no
    // division by the cell volumes
    linearHatKernel::weights w;
    for (const typename CloudType::parcelType& p : this->owner())
    {
        const scalar m = p.nParticle()*p.mass();
        kernel.evaluate(p.position(), p.cell(), w);
        for (label k = 0; k < 8; ++k)
        {
            const scalar mk = w.values[k]*m;
            mass[w.cells[k]] += mk;
            momentum[w.cells[k]] += mk*p.U();
        }
    }

    // The sums in the neighbouring processors' cells go to their owners
    SubField<scalar> ghostMass(mass, kernel.nGhosts(), nCells);
    SubField<vector> ghostMomentum(momentum, kernel.nGhosts(), nCells);
    kernel.addGhostDeposits(mass, ghostMass);
    kernel.addGhostDeposits(momentum, ghostMomentum);

    volVectorField& Us = meanVelocity();
    vectorField& UsCells = Us.primitiveFieldRef();
    forAll(UsCells, celli)
    {
        UsCells[celli] =
            mass[celli] > 0
          ? momentum[celli]/mass[celli]
          : Zero;
    }
    Us.correctBoundaryConditions();
}


template<class CloudType>
Foam::label Foam::PackingModels::MfixSnider<CloudType>::packCell
(
    const typename CloudType::parcelType& p,
    const vector& tauGrad
) const
{
    // The neighbour across the face of the parcel's cell that the stress
    // gradient points at most directly: where the denser solids are
    const fvMesh& mesh = this->owner().mesh();
    const label celli = p.cell();
    const label facei = cellFaceGeometry::faceToward(mesh, celli, tauGrad);

    return
        facei >= 0
      ? this->cellNeighbours().across(celli, facei)
      : -1;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::PackingModels::MfixSnider<CloudType>::cacheFields(const bool store)
{
    // The base takes the step's entries and, at the end, gives the packs
    // their reactions, before the mean of the final velocities is taken
    DensePackingModel<CloudType>::cacheFields(store);

    if (!store)
    {
        storeMeanVelocity();
        previousMeanVelocity_ = nullptr;
        stressGradient_.clear();
        cellAlpha_.clear();
        damping_.clear();
        return;
    }

    const tmp<scalarField> talpha(this->volumeAverage().primitiveField());
    const scalarField& alpha = talpha();

    cellAlpha_.setSize(alpha.size());
    scalarField stress(alpha.size());
    forAll(alpha, celli)
    {
        cellAlpha_[celli] = rules_.cappedFraction(alpha[celli]);
        stress[celli] = rules_.tau(alpha[celli]);
    }
    stressGradient_.update(stress);
    previousMeanVelocity_ = &meanVelocity().primitiveField();

    if (collisionDamping_)
    {
        damping_.update(this->owner(), cellAlpha_);
    }
}


// ************************************************************************* //
