/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "packingMonitor.H"
#include "closePack.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
const CloudType* Foam::functionObjects::packingMonitor::cloudAs() const
{
    // Looked up through its abstract base: the cloud's own typeName is
    // ambiguous (kinematicCloud and Cloud both declare one)
    return dynamic_cast<const CloudType*>
    (
        &lookupObject<kinematicCloud>(cloudName_)
    );
}


template<class CloudType>
const Foam::PackingModels::DensePackingModel
<
    typename CloudType::MPPICCloudType
>*
Foam::functionObjects::packingMonitor::ourPackingModel(const CloudType& cloud)
{
    return dynamic_cast
    <
        const PackingModels::DensePackingModel
        <
            typename CloudType::MPPICCloudType
        >*
    >(&cloud.packingModel());
}


template<class CloudType>
Foam::scalar
Foam::functionObjects::packingMonitor::maxAveragedSolidsFraction
(
    const CloudType& cloud
) const
{
    const autoPtr<AveragingMethod<scalar>> average
    (
        solidsFractionDeposition::averagedSolidsFraction
        (
            cloud, cloudName_ + ":packingMonitorAverage"
        )
    );

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


template<class CloudType>
Foam::tmp<Foam::vectorField>
Foam::functionObjects::packingMonitor::cellPackingMomentum
(
    const CloudType& cloud
) const
{
    // Our packing models record the velocity change they gave, which can
    // differ from UCorrect (a move back out of a full cell is a
    // displacement, not a velocity: ColoringFunction)
    const auto* ours = ourPackingModel(cloud);

    if (ours && ours->cellAddedMomentum().size() == mesh_.nCells())
    {
        // The model's own field, not a copy
        return tmp<vectorField>(ours->cellAddedMomentum());
    }

    auto tmomentum = tmp<vectorField>::New(mesh_.nCells(), Zero);
    vectorField& momentum = tmomentum.ref();

    for (const typename CloudType::parcelType& p : cloud)
    {
        momentum[p.cell()] += p.nParticle()*p.mass()*p.UCorrect();
    }

    return tmomentum;
}


template<class CloudType>
Foam::functionObjects::packingMonitor::sample
Foam::functionObjects::packingMonitor::evaluate(const CloudType& cloud) const
{
    const scalar deltaT = time_.deltaTValue();
    const scalarField& V = mesh_.V();

    sample s;
    scalarField solidsVolume(mesh_.nCells(), Zero);

    for (const typename CloudType::parcelType& p : cloud)
    {
        const label celli = p.cell();

        ++s.nParcels;
        s.mass += p.nParticle()*p.mass();
        solidsVolume[celli] += p.nParticle()*p.volume();

        if (mag(p.U())*deltaT > cbrt(V[celli]))
        {
            ++s.nFastParcels;
        }
    }

    const scalarField alphaCell(solidsVolume/V);
    forAll(alphaCell, celli)
    {
        s.maxAlphaCell = max(s.maxAlphaCell, alphaCell[celli]);
        if
        (
            PackingModels::aboveClosePack(alphaCell[celli], closePackFraction_)
        )
        {
            ++s.nCellsAboveClosePack;
        }
    }

    const tmp<vectorField> tmomentum(cellPackingMomentum(cloud));
    forAll(wallCells_, celli)
    {
        const vector& momentum = tmomentum()[celli];
        s.packingMomentum += momentum;
        if (wallCells_[celli])
        {
            s.wallPackingMomentum += momentum;
        }
    }

    // The packs' reactions our models handed the gas instead
    const auto* ours = ourPackingModel(cloud);
    if (ours && ours->cellGasMomentum().size() == mesh_.nCells())
    {
        s.gasPackingMomentum = sum(ours->cellGasMomentum());
    }

    reduce(s.nParcels, sumOp<label>());
    reduce(s.mass, sumOp<scalar>());
    reduce(s.maxAlphaCell, maxOp<scalar>());
    reduce(s.nCellsAboveClosePack, sumOp<label>());
    reduce(s.nFastParcels, sumOp<label>());
    reduce(s.packingMomentum, sumOp<vector>());
    reduce(s.wallPackingMomentum, sumOp<vector>());
    reduce(s.gasPackingMomentum, sumOp<vector>());

    s.maxAlphaAveraged = maxAveragedSolidsFraction(cloud);

    return s;
}


// ************************************************************************* //
