/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "LeanMPPICCloud.H"
#include "DensePackingModel.H"
#include "DynamicList.H"
#include <algorithm>
#include <type_traits>

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

template<class CloudType>
const Foam::Enum<typename Foam::LeanMPPICCloud<CloudType>::stepType>
Foam::LeanMPPICCloud<CloudType>::stepTypeNames
({
    { stepType::lean, "lean" },
    { stepType::MPPICCloud, "MPPICCloud" },
});


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
typename Foam::LeanMPPICCloud<CloudType>::stepType
Foam::LeanMPPICCloud<CloudType>::readStep() const
{
    const dictionary& dict = this->particleProperties();
    const word name(dict.getOrDefault<word>("cloudStep", "lean"));
    if (!stepTypeNames.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "cloudStep " << name << " in " << dict.name()
            << ": allowed values " << flatOutput(stepTypeNames.sortedToc())
            << exit(FatalIOError);
    }
    return stepTypeNames.get(name);
}


template<class CloudType>
Foam::label Foam::LeanMPPICCloud<CloudType>::readSortParcelsEvery() const
{
    const dictionary& dict = this->particleProperties();
    const label n = dict.getOrDefault<label>("sortParcelsEvery", 0);
    if (n < 0)
    {
        FatalIOErrorInFunction(dict)
            << "sortParcelsEvery " << n << " in " << dict.name()
            << ": allowed range integer >= 0 (0: never)"
            << exit(FatalIOError);
    }
    return n;
}


template<class CloudType>
void Foam::LeanMPPICCloud<CloudType>::sortParcels()
{
    const label timeIndex = this->db().time().timeIndex();
    if
    (
        sortParcelsEvery_ == 0
     || timeIndex % sortParcelsEvery_ != 0
     || timeIndex == sortedIndex_
    )
    {
        return;
    }
    sortedIndex_ = timeIndex;

    const label n = this->size();
    List<parcelType*> parcels(n);
    label i = 0;
    for (parcelType& p : *this)
    {
        parcels[i++] = &p;
    }

    labelList order(identity(n));
    std::stable_sort
    (
        order.begin(),
        order.end(),
        [&parcels](const label a, const label b)
        {
            return parcels[a]->cell() < parcels[b]->cell();
        }
    );

    // All copies first, so that they take consecutive allocations rather
    // than the places of the parcels they replace
    List<parcelType*> copies(n);
    forAll(order, j)
    {
        copies[j] = new parcelType(*parcels[order[j]]);
    }
    for (parcelType* p : parcels)
    {
        delete this->remove(p);
    }
    for (parcelType* p : copies)
    {
        this->append(p);
    }
}


template<class CloudType>
typename Foam::LeanMPPICCloud<CloudType>::densePackingModelType*
Foam::LeanMPPICCloud<CloudType>::ourPackingModel()
{
    return dynamic_cast<densePackingModelType*>(&this->packingModel());
}


template<class CloudType>
template<class TrackCloudType>
void Foam::LeanMPPICCloud<CloudType>::updateAverages
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td
)
{
    if (this->dampingModel().active() || this->isotropyModel().active())
    {
        td.updateAverages(cloud);
        return;
    }

    // The packing models of this library read the volume and velocity
    // averages only; OpenFOAM's also the density and the squared velocity
    // deviation (Explicit, Implicit)
    const bool stockPacking = !ourPackingModel();

    const fvMesh& mesh = this->mesh();
    const word& name = this->name();

    AveragingMethod<scalar>& volumeAverage =
        mesh.lookupObjectRef<AveragingMethod<scalar>>(name + ":volumeAverage");
    AveragingMethod<scalar>& rhoAverage =
        mesh.lookupObjectRef<AveragingMethod<scalar>>(name + ":rhoAverage");
    AveragingMethod<vector>& uAverage =
        mesh.lookupObjectRef<AveragingMethod<vector>>(name + ":uAverage");
    AveragingMethod<scalar>& uSqrAverage =
        mesh.lookupObjectRef<AveragingMethod<scalar>>(name + ":uSqrAverage");
    AveragingMethod<scalar>& massAverage =
        mesh.lookupObjectRef<AveragingMethod<scalar>>(name + ":massAverage");

    // The same sums, in the same order, as trackingData::updateAverages
    volumeAverage = 0;
    uAverage = Zero;
    massAverage = 0;
    rhoAverage = 0;
    uSqrAverage = 0;

    for (const parcelType& p : *this)
    {
        const tetIndices tetIs = p.currentTetIndices();

        const scalar m = p.nParticle()*p.mass();

        volumeAverage.add(p.coordinates(), tetIs, p.nParticle()*p.volume());
        if (stockPacking)
        {
            rhoAverage.add(p.coordinates(), tetIs, m*p.rho());
        }
        uAverage.add(p.coordinates(), tetIs, m*p.U());
        massAverage.add(p.coordinates(), tetIs, m);
    }
    volumeAverage.average();
    massAverage.average();
    if (stockPacking)
    {
        rhoAverage.average(massAverage);
    }
    uAverage.average(massAverage);

    if (stockPacking)
    {
        for (const parcelType& p : *this)
        {
            const tetIndices tetIs = p.currentTetIndices();

            const vector u = uAverage.interpolate(p.coordinates(), tetIs);

            uSqrAverage.add
            (
                p.coordinates(),
                tetIs,
                p.nParticle()*p.mass()*magSqr(p.U() - u)
            );
        }
        uSqrAverage.average(massAverage);
    }
}


template<class CloudType>
template<class TrackCloudType>
void Foam::LeanMPPICCloud<CloudType>::correctionPass
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td,
    const scalar trackTime
)
{
    // The list as it is, each parcel's identity (its address can be
    // re-used by a parcel received from another processor) and whether it
    // has a correction
    const label n = this->size();
    DynamicList<parcelType*> order(n);
    DynamicList<labelPair> identity(n);
    DynamicList<bool> corrected(n);
    for (parcelType& p : *this)
    {
        order.append(&p);
        identity.append(labelPair(p.origProc(), p.origId()));
        corrected.append(p.UCorrect() != vector::zero);
    }

    // Set aside the parcels without a correction
    IDLList<parcelType> resting;
    forAll(order, i)
    {
        if (!corrected[i])
        {
            resting.append(this->remove(order[i]));
        }
    }

    nCorrected_ = returnReduce(this->size(), sumOp<label>());

    td.part() = parcelType::trackingData::tpCorrectTrack;
    nCrossed_ = trackCorrections(cloud, td, trackTime);

    Info<< "    correction pass: " << nCorrected_ << " of "
        << returnReduce(n, sumOp<label>()) << " parcels";
    if (Pstream::parRun())
    {
        Info<< ", " << nCrossed_ << " processor crossings";
    }
    Info<< endl;

    // Back in the stock order: the survivors of the pass (in their order),
    // the resting parcels in their places, then the parcels received.
    // (remove(first()), not v1912's removeHead, which leaves a one-parcel
    // list with a dangling head)
    IDLList<parcelType> tracked;
    while (this->size())
    {
        tracked.append(this->remove(this->first()));
    }
    forAll(order, i)
    {
        if (!corrected[i])
        {
            this->append(resting.remove(resting.first()));
        }
        else if
        (
            tracked.size()
         && tracked.first() == order[i]
         && tracked.first()->origProc() == identity[i].first()
         && tracked.first()->origId() == identity[i].second()
        )
        {
            this->append(tracked.remove(tracked.first()));
        }
    }
    while (tracked.size())
    {
        this->append(tracked.remove(tracked.first()));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::LeanMPPICCloud<CloudType>::evolve()
{
    if (this->solution().canEvolve())
    {
        typename parcelType::trackingData td(*this);

        this->solve(*this, td);
    }
}


template<class CloudType>
template<class TrackCloudType>
void Foam::LeanMPPICCloud<CloudType>::motion
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td
)
{
    sortParcels();

    if (step_ == stepType::MPPICCloud)
    {
        CloudType::motion(cloud, td);
        return;
    }

    const scalar deltaT = this->db().time().deltaTValue();

    if (this->packingModel().active() && ourPackingModel())
    {
        ourPackingModel()->beforeMotion();
    }

    // Forces and tracking
    td.part() = parcelType::trackingData::tpLinearTrack;
    this->move(cloud, td, deltaT);

    // No forces in the correction pass
    this->forces().setCalcNonCoupled(false);
    this->forces().setCalcCoupled(false);

    const bool damping = this->dampingModel().active();
    const bool packing = this->packingModel().active();

    if (damping || packing)
    {
        if (this->mesh().moving())
        {
            FatalErrorInFunction
                << "MPPIC damping and packing models do not support moving"
                << " meshes." << exit(FatalError);
        }

        updateAverages(cloud, td);

        if (damping)
        {
            this->dampingModel().cacheFields(true);
        }
        if (packing)
        {
            this->packingModel().cacheFields(true);
        }

        for (parcelType& p : *this)
        {
            if (damping && packing)
            {
                p.UCorrect() =
                    this->dampingModel().velocityCorrection(p, deltaT)
                  + this->packingModel().velocityCorrection(p, deltaT);
            }
            else if (damping)
            {
                p.UCorrect() =
                    this->dampingModel().velocityCorrection(p, deltaT);
            }
            else
            {
                p.UCorrect() =
                    this->packingModel().velocityCorrection(p, deltaT);
            }
        }

        correctionPass(cloud, td, deltaT);

        if (packing)
        {
            this->packingModel().cacheFields(false);
        }
        if (damping)
        {
            this->dampingModel().cacheFields(false);
        }
    }

    if (this->isotropyModel().active())
    {
        td.updateAverages(cloud);
        this->isotropyModel().calculate();
    }

    this->updateCellOccupancy();

    this->forces().setCalcNonCoupled(true);
    this->forces().setCalcCoupled(this->solution().coupled());
}


// ************************************************************************* //
