/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "DensePackingModel.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PackingModels::DensePackingModel<CloudType>::DensePackingModel
(
    const dictionary& dict,
    CloudType& owner,
    const word& type,
    const wordList& modelKeywords
)
:
    // The base's dictionary constructor would require a stock
    // particleStressModel entry, which these models do not use
    PackingModel<CloudType>(owner),
    coeffs_(checkedCoeffs(dict, type, modelKeywords)),
    closePackFraction_(readClosePackFraction(coeffs_)),
    conserveMomentum_(readConserveMomentum(coeffs_) != "none"),
    freePackReactionsToGas_(readConserveMomentum(coeffs_) == "gas"),
    capacityLimit_(CapacityLimit<CloudType>::mode(coeffs_) != "none"),
    limit_
    (
        owner.mesh(),
        coeffs_,
        closePackFraction_,
        capacityLimit_ && coeffs_.lookupOrDefault("holdSupportedPacks", true)
    )
{}


template<class CloudType>
Foam::PackingModels::DensePackingModel<CloudType>::DensePackingModel
(
    const DensePackingModel<CloudType>& cm
)
:
    PackingModel<CloudType>(cm),
    coeffs_(cm.coeffs_),
    closePackFraction_(cm.closePackFraction_),
    conserveMomentum_(cm.conserveMomentum_),
    freePackReactionsToGas_(cm.freePackReactionsToGas_),
    capacityLimit_(cm.capacityLimit_),
    limit_(cm.limit_)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

namespace Foam
{
    //- Cell values of a field and the neighbouring values across coupled
    //  patches (processor, cyclic)
    template<class Type>
    void cacheWithCoupledNeighbours
    (
        const fvMesh& mesh,
        const Field<Type>& values,
        Field<Type>& cellValues,
        PtrList<Field<Type>>& coupledValues
    )
    {
        GeometricField<Type, fvPatchField, volMesh> field
        (
            IOobject
            (
                "densePackingModel:cellValues",
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh,
            dimensioned<Type>(dimless, Zero),
            calculatedFvPatchField<Type>::typeName
        );
        field.primitiveFieldRef() = values;
        field.correctBoundaryConditions();

        cellValues = field.primitiveField();

        coupledValues.clear();
        coupledValues.setSize(mesh.boundary().size());
        forAll(field.boundaryField(), patchi)
        {
            const fvPatchField<Type>& pf = field.boundaryField()[patchi];
            if (pf.coupled())
            {
                coupledValues.set(patchi, pf.patchNeighbourField().ptr());
            }
        }
    }
}


template<class CloudType>
void Foam::PackingModels::DensePackingModel<CloudType>::cacheCellValues()
{
    const fvMesh& mesh = this->owner().mesh();

    cacheWithCoupledNeighbours
    (
        mesh, cellPackingValues()(), cellValues_, coupledValues_
    );
    cacheWithCoupledNeighbours
    (
        mesh, uAverage_->primitiveField()(), cellUMean_, coupledUMean_
    );

    if (needsCornerNodeGradient())
    {
        // Collective: every processor sends its cells' values
        kernel_ = &linearHatKernel::New(mesh);
        kernel_->ghostValues(cellValues_, ghostValues_);

        cellBeyond_.setSize(cellValues_.size());
        forAll(cellValues_, celli)
        {
            cellBeyond_[celli] = wallValue(cellValues_[celli]);
        }
        ghostBeyond_.setSize(ghostValues_.size());
        forAll(ghostValues_, ghosti)
        {
            ghostBeyond_[ghosti] = wallValue(ghostValues_[ghosti]);
        }
    }
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::tmp<Foam::scalarField>
Foam::PackingModels::DensePackingModel<CloudType>::cellPackingValues() const
{
    return packingField_->primitiveField();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::PackingModels::DensePackingModel<CloudType>::beforeMotion()
{
    // Nothing recorded yet while parcels that have moved before (age > 0)
    // are in the cloud: they were read from a written time. Record where
    // they are, which is where the uninterrupted run's last step left them
    if (tracksEntries())
    {
        limit_.beforeMotion(this->owner());
    }
}


template<class CloudType>
void Foam::PackingModels::DensePackingModel<CloudType>::cacheFields
(
    const bool store
)
{
    PackingModel<CloudType>::cacheFields(store);

    if (store && tracksEntries())
    {
        // Decide the step's entries (and the held cells) first: a model's
        // cell values may depend on them (cellPackingValues)
        limit_.startStep
        (
            this->owner(),
            this->owner().db().time().deltaTValue()
        );
    }

    if (!store)
    {
        // End of the packing step: the packs take their impulses back,
        // then the limit records where each parcel now is
        if (conserveMomentum_)
        {
            applyReactions();
        }
        if (tracksEntries())
        {
            limit_.endStep(this->owner());
        }

        volumeAverage_ = nullptr;
        uAverage_ = nullptr;
        packingField_.clear();
        cellValues_.clear();
        cellUMean_.clear();
        coupledValues_.clear();
        coupledUMean_.clear();
        ghostValues_.clear();
        cellBeyond_.clear();
        ghostBeyond_.clear();
        return;
    }

    const fvMesh& mesh = this->owner().mesh();
    const word& cloudName = this->owner().name();

    // Constructed here, by every processor together (it exchanges the
    // cells across processor faces), before any parcel asks for it
    cellNeighbours_ = &coupledCellNeighbours::New(mesh);

    // Reset at the first (sub-)step of a gas step; the solids sub-steps
    // (subCycleTime) share the gas step's index in prevTimeState()
    const Time& runTime = mesh.time();
    const label gasStep =
        runTime.subCycling()
      ? runTime.prevTimeState().timeIndex()
      : runTime.timeIndex();

    if
    (
        gasStep != addedMomentumStep_
     || cellAddedMomentum_.size() != mesh.nCells()
    )
    {
        cellAddedMomentum_.setSize(mesh.nCells());
        cellAddedMomentum_ = Zero;
        cellGasMomentum_.setSize(mesh.nCells());
        cellGasMomentum_ = Zero;
        addedMomentumStep_ = gasStep;
    }

    volumeAverage_ =
        &mesh.lookupObject<AveragingMethod<scalar>>(cloudName + ":volumeAverage");
    uAverage_ =
        &mesh.lookupObject<AveragingMethod<vector>>(cloudName + ":uAverage");

    if (needsPackingField())
    {
        packingField_ =
            AveragingMethod<scalar>::New
            (
                IOobject
                (
                    cloudName + ":packingField",
                    mesh.time().timeName(),
                    mesh
                ),
                this->owner().solution().dict(),
                mesh
            );

        // f(alpha) at every averaging datum (cells or points)
        tmp<FieldField<Field, scalar>> tvalues
        (
            new FieldField<Field, scalar>(*volumeAverage_)
        );
        for (Field<scalar>& values : tvalues.ref())
        {
            for (scalar& value : values)
            {
                value = packingFieldValue(value);
            }
        }

        // Assignment also updates the gradient used by interpolateGrad
        packingField_() = tvalues;
    }

    if (needsCellValues())
    {
        cacheCellValues();
    }
}


// ************************************************************************* //
