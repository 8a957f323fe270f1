/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "MfixPackingModel.H"
#include "packingFaceGradient.H"
#include "wallPolyPatch.H"
#include "cellFaceGeometry.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PackingModels::MfixPackingModel<CloudType>::MfixPackingModel
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
    conserveMomentum_(readConserveMomentum(coeffs_) != "none"),
    freePackReactionsToGas_(readConserveMomentum(coeffs_) == "gas")
{}


template<class CloudType>
Foam::PackingModels::MfixPackingModel<CloudType>::MfixPackingModel
(
    const MfixPackingModel<CloudType>& cm
)
:
    PackingModel<CloudType>(cm),
    coeffs_(cm.coeffs_),
    conserveMomentum_(cm.conserveMomentum_),
    freePackReactionsToGas_(cm.freePackReactionsToGas_)
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
                "mfixPackingModel:cellValues",
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
void Foam::PackingModels::MfixPackingModel<CloudType>::cacheCellValues()
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
Foam::PackingModels::MfixPackingModel<CloudType>::cellPackingValues() const
{
    return packingField_->primitiveField();
}


template<class CloudType>
Foam::scalar Foam::PackingModels::MfixPackingModel<CloudType>::cellValue
(
    const label celli
) const
{
    return cellValues_[celli];
}


template<class CloudType>
Foam::vector Foam::PackingModels::MfixPackingModel<CloudType>::cellUMean
(
    const label celli
) const
{
    return cellUMean_[celli];
}


template<class CloudType>
Foam::scalar Foam::PackingModels::MfixPackingModel<CloudType>::alphaAt
(
    const typename CloudType::parcelType& p
) const
{
    return volumeAverage_->interpolate(p.coordinates(), p.currentTetIndices());
}


template<class CloudType>
Foam::vector Foam::PackingModels::MfixPackingModel<CloudType>::uMeanAt
(
    const typename CloudType::parcelType& p
) const
{
    return uAverage_->interpolate(p.coordinates(), p.currentTetIndices());
}


template<class CloudType>
Foam::vector Foam::PackingModels::MfixPackingModel<CloudType>::packingGradAt
(
    const typename CloudType::parcelType& p
) const
{
    return
        packingField_->interpolateGrad
        (
            p.coordinates(),
            p.currentTetIndices()
        );
}


template<class CloudType>
typename Foam::PackingModels::MfixPackingModel<CloudType>::neighbourState
Foam::PackingModels::MfixPackingModel<CloudType>::neighbourAhead
(
    const typename CloudType::parcelType& p
) const
{
    const fvMesh& mesh = this->owner().mesh();
    const label celli = p.cell();

    // The face the parcel moves toward most directly
    neighbourState ahead;
    const label towardFace = cellFaceGeometry::faceToward(mesh, celli, p.U());

    if (towardFace < 0)
    {
        return ahead;
    }
    ahead.normal = cellFaceGeometry::outwardNormal(mesh, celli, towardFace);

    if (mesh.isInternalFace(towardFace))
    {
        const label nbr =
            cellFaceGeometry::cellAcross(mesh, celli, towardFace);

        ahead.found = true;
        ahead.value = cellValues_[nbr];
        ahead.uMean = cellUMean_[nbr];
        ahead.cell = cellNeighbours_->toGlobal(nbr);
        return ahead;
    }

    const label patchi = mesh.boundaryMesh().whichPatch(towardFace);
    const polyPatch& patch = mesh.boundaryMesh()[patchi];

    if (coupledValues_.set(patchi))
    {
        const label patchFacei = patch.whichFace(towardFace);
        ahead.found = true;
        ahead.value = coupledValues_[patchi][patchFacei];
        ahead.uMean = coupledUMean_[patchi][patchFacei];
        ahead.cell = cellNeighbours_->across(celli, towardFace);
    }
    else if (isA<wallPolyPatch>(patch))
    {
        ahead.found = true;
        ahead.value = wallValue(cellValues_[celli]);
        ahead.uMean = Zero;
    }

    return ahead;
}


template<class CloudType>
Foam::vector Foam::PackingModels::MfixPackingModel<CloudType>::faceGradientAt
(
    const typename CloudType::parcelType& p
) const
{
    return
        packingFaceGradient::at
        (
            this->owner().mesh(),
            p.cell(),
            p.position(),
            cellValues_,
            coupledValues_,
            wallValue(cellValues_[p.cell()])
        );
}


template<class CloudType>
Foam::vector
Foam::PackingModels::MfixPackingModel<CloudType>::cornerNodeFaceGradientAt
(
    const typename CloudType::parcelType& p
) const
{
    if (!kernel_->hexahedral(p.cell()))
    {
        return faceGradientAt(p);
    }

    return
        kernel_->cornerNodeFaceGradient
        (
            cellValues_, ghostValues_, cellBeyond_, ghostBeyond_,
            p.position(), p.cell()
        );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::PackingModels::MfixPackingModel<CloudType>::cacheFields
(
    const bool store
)
{
    PackingModel<CloudType>::cacheFields(store);

    if (!store)
    {
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
