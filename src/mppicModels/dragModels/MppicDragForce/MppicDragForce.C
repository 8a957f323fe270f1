/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "MppicDragForce.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

template<class CloudType>
const Foam::Enum
<
    typename Foam::MppicDragForce<CloudType>::slipSource
>
Foam::MppicDragForce<CloudType>::slipSourceNames
({
    { slipSource::parcel, "parcel" },
    { slipSource::cellMean, "cellMean" },
});


template<class CloudType>
const Foam::wordList Foam::MppicDragForce<CloudType>::keywords
({
    "feedback", "slipFrom"
});


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
typename Foam::MppicDragForce<CloudType>::slipSource
Foam::MppicDragForce<CloudType>::readSlipSource(const dictionary& coeffs)
{
    const word name
    (
        coeffs.lookupOrDefault<word>
        (
            "slipFrom",
            slipSourceNames[slipSource::parcel]
        )
    );

    if (!slipSourceNames.found(name))
    {
        FatalIOErrorInFunction(coeffs)
            << "Dictionary " << coeffs.name() << ", keyword slipFrom: value "
            << name << " is not one of " << slipSourceNames.toc()
            << exit(FatalIOError);
    }
    return slipSourceNames[name];
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::MppicDragForce<CloudType>::MppicDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict,
    const word& forceType
)
:
    ParticleForce<CloudType>(owner, mesh, dict, forceType, true),
    feedback_(this->coeffs().lookupOrDefault("feedback", true)),
    slipFrom_(readSlipSource(this->coeffs())),
    cellMeanU_(),
    cellHasMean_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::MppicDragForce<CloudType>::cacheFields(const bool store)
{
    ParticleForce<CloudType>::cacheFields(store);

    if (!store || slipFrom_ != slipSource::cellMean)
    {
        return;
    }

    const label nCells = this->mesh().nCells();
    List<scalar> cellMass(nCells, Zero);
    cellMeanU_.setSize(nCells);
    cellMeanU_ = Zero;

    for (const typename CloudType::parcelType& p : this->owner())
    {
        const scalar m = p.nParticle()*p.mass();
        cellMass[p.cell()] += m;
        cellMeanU_[p.cell()] += m*p.U();
    }

    cellHasMean_.setSize(nCells);
    forAll(cellMass, celli)
    {
        cellHasMean_[celli] = cellMass[celli] > 0;
        if (cellHasMean_[celli])
        {
            cellMeanU_[celli] /= cellMass[celli];
        }
    }
}


// ************************************************************************* //
