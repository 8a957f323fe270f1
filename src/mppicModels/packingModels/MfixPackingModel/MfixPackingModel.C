/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "MfixPackingModel.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PackingModels::MfixPackingModel<CloudType>::MfixPackingModel
(
    const dictionary& dict,
    CloudType& owner,
    const word& type
)
:
    // The base's dictionary constructor would require a stock
    // particleStressModel entry, which these models do not use
    PackingModel<CloudType>(owner),
    coeffs_(dict.subDict(type + "Coeffs")),
    volumeAverage_(nullptr),
    uAverage_(nullptr),
    packingField_(nullptr)
{}


template<class CloudType>
Foam::PackingModels::MfixPackingModel<CloudType>::MfixPackingModel
(
    const MfixPackingModel<CloudType>& cm
)
:
    PackingModel<CloudType>(cm),
    coeffs_(cm.coeffs_),
    volumeAverage_(nullptr),
    uAverage_(nullptr),
    packingField_(nullptr)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

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
        return;
    }

    const fvMesh& mesh = this->owner().mesh();
    const word& cloudName = this->owner().name();

    volumeAverage_ =
        &mesh.lookupObject<AveragingMethod<scalar>>(cloudName + ":volumeAverage");
    uAverage_ =
        &mesh.lookupObject<AveragingMethod<vector>>(cloudName + ":uAverage");

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
    FieldField<Field, scalar>& values = tvalues.ref();
    forAll(values, i)
    {
        forAll(values[i], j)
        {
            values[i][j] = packingFieldValue(values[i][j]);
        }
    }

    // Assignment also updates the gradient used by interpolateGrad
    packingField_() = tvalues;
}


// ************************************************************************* //
