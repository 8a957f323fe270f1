/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    What the models ask of the cached fields at a parcel: the cell values,
    the solids fraction and mean velocity, the packing field's gradient (by
    the averaging, from the cell's faces or through its corners) and the
    cell the parcel moves toward.

\*---------------------------------------------------------------------------*/

#include "DensePackingModel.H"
#include "packingFaceGradient.H"
#include "wallPolyPatch.H"
#include "cellFaceGeometry.H"

// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::PackingModels::DensePackingModel<CloudType>::cellValue
(
    const label celli
) const
{
    return cellValues_[celli];
}


template<class CloudType>
Foam::vector Foam::PackingModels::DensePackingModel<CloudType>::cellUMean
(
    const label celli
) const
{
    return cellUMean_[celli];
}


template<class CloudType>
Foam::scalar Foam::PackingModels::DensePackingModel<CloudType>::alphaAt
(
    const typename CloudType::parcelType& p
) const
{
    return volumeAverage_->interpolate(p.coordinates(), p.currentTetIndices());
}


template<class CloudType>
Foam::vector Foam::PackingModels::DensePackingModel<CloudType>::uMeanAt
(
    const typename CloudType::parcelType& p
) const
{
    return uAverage_->interpolate(p.coordinates(), p.currentTetIndices());
}


template<class CloudType>
Foam::vector Foam::PackingModels::DensePackingModel<CloudType>::packingGradAt
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
Foam::PackingModels::neighbourState
Foam::PackingModels::DensePackingModel<CloudType>::neighbourAhead
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
Foam::vector Foam::PackingModels::DensePackingModel<CloudType>::faceGradientAt
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
Foam::PackingModels::DensePackingModel<CloudType>::cornerNodeFaceGradientAt
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


// ************************************************************************* //
