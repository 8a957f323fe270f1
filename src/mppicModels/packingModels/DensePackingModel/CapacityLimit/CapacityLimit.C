/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "CapacityLimit.H"
#include "cellRoom.H"
#include "processorPolyPatch.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

template<class CloudType>
const Foam::wordList Foam::CapacityLimit<CloudType>::keywords
({
    "supportPatches", "capacityLimit"
});


template<class CloudType>
Foam::word Foam::CapacityLimit<CloudType>::mode(const dictionary& coeffs)
{
    return mppicCoefficients::readChoice
    (
        coeffs, "capacityLimit", "refuse", {"push", "refuse", "none"}
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::CapacityLimit<CloudType>::CapacityLimit
(
    const fvMesh& mesh,
    const dictionary& coeffs,
    const scalar closePackFraction,
    const bool holdSupportedPacks
)
:
    mesh_(mesh),
    closePackFraction_(closePackFraction),
    holdSupportedPacks_(holdSupportedPacks),
    entries_(),
    support_(mesh, coeffs),
    resting_()
{
    entries_.setPushThrough(mode(coeffs) == "push");
}


template<class CloudType>
Foam::CapacityLimit<CloudType>::CapacityLimit
(
    const CapacityLimit<CloudType>& cl
)
:
    mesh_(cl.mesh_),
    closePackFraction_(cl.closePackFraction_),
    holdSupportedPacks_(cl.holdSupportedPacks_),
    entries_(),
    support_(cl.support_),
    resting_()
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::CapacityLimit<CloudType>::warnOfCutsAcrossGravity
(
    const fvMesh& mesh,
    const vector& g
)
{
    const vector down = g/max(mag(g), VSMALL);

    // Processor faces within 45 degrees of horizontal, by area
    scalar across = 0;
    scalar total = 0;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (!isA<processorPolyPatch>(pp))
        {
            continue;
        }
        forAll(pp, i)
        {
            const scalar area = mag(pp.faceAreas()[i]);
            total += area;
            if (mag(pp.faceAreas()[i] & down) > sqrt(0.5)*area)
            {
                across += area;
            }
        }
    }
    reduce(across, sumOp<scalar>());
    reduce(total, sumOp<scalar>());

    if (across > 0)
    {
        WarningInFunction
            << "pushThrough: " << across/max(total, VSMALL)
            << " of the processor faces' area lies across gravity. The"
            << " chains do not cross processor faces, so such a cut"
            << " through a bed blocks those that run to its surface;"
            << " decompose along gravity (e.g. simple (2 1 1))" << endl;
    }
}


template<class CloudType>
void Foam::CapacityLimit<CloudType>::reportFullCell
(
    const CloudType& cloud
) const
{
    const scalar closePackFraction = closePackFraction_;
    const fvMesh& mesh = cloud.mesh();

    boolList occupied(mesh.nCells(), false);
    scalar parcelVolume = 0;
    label nParcels = 0;
    for (const parcelType& p : cloud)
    {
        parcelVolume += p.nParticle()*p.volume();
        ++nParcels;
        occupied[p.cell()] = true;
    }
    scalar cellVolume = 0;
    label nCells = 0;
    forAll(occupied, celli)
    {
        if (occupied[celli])
        {
            cellVolume += mesh.V()[celli];
            ++nCells;
        }
    }
    reduce(parcelVolume, sumOp<scalar>());
    reduce(nParcels, sumOp<label>());
    reduce(cellVolume, sumOp<scalar>());
    reduce(nCells, sumOp<label>());
    if (nParcels == 0)
    {
        return;
    }

    // As many parcels as fit, one after another
    const scalar v = parcelVolume/nParcels;
    const scalar V = cellVolume/nCells;
    label n = 0;
    while (cellRoom::fits(v, closePackFraction*V - n*v))
    {
        ++n;
    }
    const scalar full = n*v/V;

    Info<< "    capacity: a full cell holds " << n << " parcels, "
        << full << " of the cell (close pack " << closePackFraction
        << "; one parcel " << v/V << " of the cell)" << endl;

    if (full < closePackFraction - 0.01)
    {
        WarningInFunction
            << "A full cell holds " << n << " parcels, " << full
            << " of the cell, below close pack " << closePackFraction
            << ": its gas needs more than a packed bed's minimum"
            << " fluidization. Seed so that a whole number of parcels"
            << " makes close pack (kuipersJet README, \"A full cell at"
            << " close pack\")" << endl;
    }
}


template<class CloudType>
Foam::boolList Foam::CapacityLimit<CloudType>::fullCells
(
    const CloudType& cloud
) const
{
    const fvMesh& mesh = cloud.mesh();

    scalarField volume(mesh.nCells(), Zero);
    scalarField largest(mesh.nCells(), Zero);

    for (const parcelType& p : cloud)
    {
        const label celli = entries_.finalCell(p);
        if (celli >= 0)
        {
            const scalar v = p.nParticle()*p.volume();
            volume[celli] += v;
            largest[celli] = max(largest[celli], v);
        }
    }

    // The refused parcels that go back to cells here from other processors
    const scalarField& returned = entries_.returnedVolume();
    if (returned.size())
    {
        volume += returned;
        largest = max(largest, entries_.returnedLargest());
    }

    // No room for half of its largest parcel, as the entries are admitted
    boolList full(mesh.nCells());
    forAll(full, celli)
    {
        const scalar room = closePackFraction_*mesh.V()[celli] - volume[celli];
        full[celli] =
            largest[celli] > 0
         && !cellRoom::fits(largest[celli], room);
    }
    return full;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::CapacityLimit<CloudType>::beforeMotion(const CloudType& cloud)
{
    entries_.setExactTracks();

    if (!entries_.hasRecords())
    {
        entries_.recordCells(cloud, true);
    }
}


template<class CloudType>
void Foam::CapacityLimit<CloudType>::startStep
(
    const CloudType& cloud,
    const scalar deltaT
)
{
    entries_.update(cloud, closePackFraction_, deltaT);
    deltaT_ = deltaT;

    if (!fullCellReported_)
    {
        reportFullCell(cloud);
        fullCellReported_ = true;
    }

    if (entries_.pushThrough())
    {
        if (Pstream::parRun() && !cutsChecked_)
        {
            warnOfCutsAcrossGravity(cloud.mesh(), cloud.g().value());
            cutsChecked_ = true;
        }
        FixedList<label, 6> toward(entries_.nPushedToward());
        forAll(toward, i)
        {
            reduce(toward[i], sumOp<label>());
        }
        Info<< "    pushThrough: "
            << returnReduce(entries_.nPushed(), sumOp<label>())
            << " refused entrants admitted (rooms toward -x " << toward[0]
            << " +x " << toward[1] << " -y " << toward[2] << " +y "
            << toward[3] << " -z " << toward[4] << " +z " << toward[5]
            << ")" << endl;
    }

    if (!holdSupportedPacks_)
    {
        return;
    }

    support_.update(cloud.g().value(), fullCells(cloud));

    resting_.setSize(cloud.mesh().nCells());
    resting_ = false;

    if (Pstream::parRun())
    {
        boolList heldCells(cloud.mesh().nCells());
        forAll(heldCells, celli)
        {
            heldCells[celli] = support_.held(celli);
        }
        entries_.shareHeld(heldCells);
    }
}


template<class CloudType>
void Foam::CapacityLimit<CloudType>::endStep(const CloudType& cloud)
{
    entries_.clear();
    entries_.recordCells(cloud);
}


template<class CloudType>
Foam::vector Foam::CapacityLimit<CloudType>::move
(
    const parcelType& p,
    const vector& dU,
    const vector& uPack,
    const scalar deltaT,
    vector& kept,
    const vector& displacement
) const
{
    const vector dX =
        entries_.limitedCorrection(mesh_, p, dU + displacement, deltaT);

    kept = entries_.keptVelocity(p, p.U() + dU, uPack);

    if
    (
        holdSupportedPacks_
     && (
            support_.held(entries_.finalCell(p))
         || entries_.returnsToHeldCell(p)
        )
    )
    {
        const label celli = entries_.finalCell(p);
        const vector held =
            support_.heldVelocity(p.U(), kept);

        // The support stopped a fall: the cell rests on it this step
        if
        (
            magSqr(held - kept) > 0
         && celli >= 0
         && celli < resting_.size()
        )
        {
            resting_[celli] = true;
        }
        kept = held;
    }

    return dX;
}


// ************************************************************************* //
