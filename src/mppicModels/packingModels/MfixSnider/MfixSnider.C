/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "MfixSnider.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

template<class CloudType>
const Foam::wordList
Foam::PackingModels::MfixSnider<CloudType>::keywords
({
    "closePackFraction", "pSolid", "gamma", "eps", "e1",
    "slipVelocityFactor", "capFactor", "meanFreePathCap",
    "restWhereConverging", "collisionDamping", "capacityLimit",
    "holdSupportedPacks", "supportPatches", "supportAngle"
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
const Foam::dictionary&
Foam::PackingModels::MfixSnider<CloudType>::checkedCoeffs
(
    const dictionary& coeffs
)
{
    for (const entry& e : coeffs)
    {
        if (!keywords.found(e.keyword()))
        {
            FatalIOErrorInFunction(coeffs)
                << "Unknown keyword " << e.keyword() << " in "
                << coeffs.name() << nl
                << "mfixSnider reads " << keywords
                << exit(FatalIOError);
        }
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
    MfixPackingModel<CloudType>(dict, owner, typeName),
    rules_(checkedCoeffs(this->coeffs())),
    collisionDamping_
    (
        this->coeffs().template lookupOrDefault<bool>("collisionDamping", false)
    ),
    capacityLimit_
    (
        this->coeffs().template lookupOrDefault<bool>("capacityLimit", true)
    ),
    stressGradient_(owner.mesh()),
    cellAlpha_(),
    damping_(rules_.e1(), rules_.closePackFraction()),
    previousMeanVelocity_(nullptr),
    limit_
    (
        owner.mesh(),
        this->coeffs(),
        capacityLimit_
     && this->coeffs().lookupOrDefault("holdSupportedPacks", true)
    )
{
    meanVelocity();
}


template<class CloudType>
Foam::PackingModels::MfixSnider<CloudType>::MfixSnider
(
    const MfixSnider<CloudType>& cm
)
:
    MfixPackingModel<CloudType>(cm),
    rules_(cm.rules_),
    collisionDamping_(cm.collisionDamping_),
    capacityLimit_(cm.capacityLimit_),
    stressGradient_(cm.owner().mesh()),
    cellAlpha_(),
    damping_(rules_.e1(), rules_.closePackFraction()),
    previousMeanVelocity_(nullptr),
    limit_(cm.limit_)
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

    scalarField mass(mesh.nCells(), Zero);
    vectorField momentum(mesh.nCells(), Zero);

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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::PackingModels::MfixSnider<CloudType>::beforeMotion()
{
    // On a restart: record where the parcels read from the written time
    // are, which is where the uninterrupted run's last step left them
    if (capacityLimit_)
    {
        limit_.beforeMotion(this->owner());
    }
}


template<class CloudType>
void Foam::PackingModels::MfixSnider<CloudType>::cacheFields(const bool store)
{
    MfixPackingModel<CloudType>::cacheFields(store);

    if (capacityLimit_)
    {
        if (store)
        {
            limit_.startStep
            (
                this->owner(),
                rules_.closePackFraction(),
                this->owner().db().time().deltaTValue()
            );
        }
        else
        {
            limit_.endStep(this->owner());
        }
    }

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


template<class CloudType>
Foam::vector Foam::PackingModels::MfixSnider<CloudType>::velocityCorrection
(
    typename CloudType::parcelType& p,
    const scalar deltaT
) const
{
    const label celli = p.cell();

    const vector tauGrad = stressGradient_.at(p.position(), celli);

    const vector dU =
        rules_.impulseVelocity(tauGrad, p.rho(), cellAlpha_[celli], deltaT);

    vector Unew =
        rules_.correctedVelocity
        (
            p.U(), (*previousMeanVelocity_)[celli], dU, tauGrad
        );

    Unew =
        rules_.meanFreePathCapped
        (
            Unew, tauGrad, cellAlpha_[celli], 0.5*p.d(), deltaT
        );

    if (collisionDamping_)
    {
        Unew = damping_.damped(Unew, celli, deltaT);
    }

    if (capacityLimit_)
    {
        // As coloringFunction's capacity limit (CapacityLimit): the
        // parcel keeps no velocity into a cell that refused it relative to
        // that cell's parcels (their mean of the previous step)
        vector kept;
        const vector move =
            limit_.move
            (
                this->owner().mesh(),
                p,
                Unew - p.U(),
                (*previousMeanVelocity_)[celli],
                deltaT,
                kept
            );

        this->recordVelocityChange(p, kept - p.U());
        p.U() = kept - move;
        return move;
    }

    const vector correction = Unew - p.U();

    this->recordVelocityChange(p, correction);
    return correction;
}


// ************************************************************************* //
