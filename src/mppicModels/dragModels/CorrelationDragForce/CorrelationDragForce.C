/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "CorrelationDragForce.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType, class Law>
const Foam::volScalarField*
Foam::CorrelationDragForce<CloudType, Law>::lookupAlphac
(
    const fvMesh& mesh,
    const dictionary& coeffs
)
{
    if (!Law::gasFraction)
    {
        return nullptr;
    }

    const word name(coeffs.getWord("alphac"));

    if (!mesh.foundObject<volScalarField>(name))
    {
        FatalIOErrorInFunction(coeffs)
            << "Dictionary " << coeffs.name() << ", keyword alphac: no gas"
            << " volume-fraction field " << name << "; volScalarFields: "
            << mesh.sortedNames<volScalarField>() << exit(FatalIOError);
    }

    return &mesh.lookupObject<volScalarField>(name);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType, class Law>
Foam::CorrelationDragForce<CloudType, Law>::CorrelationDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    MppicDragForce<CloudType>(owner, mesh, dict, typeName),
    law_(this->coeffs()),
    alphacPtr_(lookupAlphac(mesh, this->coeffs())),
    polydisperse_(Law::gasFraction ? this->coeffs() : dictionary::null)
{
    wordList valid(MppicDragForce<CloudType>::keywords);
    valid.append(Law::keywords);
    if (Law::gasFraction)
    {
        valid.append("alphac");
        valid.append(polydisperseCorrection::keyword);
    }
    mppicCoefficients::checkKeywords(this->coeffs(), valid, typeName);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType, class Law>
Foam::scalar Foam::CorrelationDragForce<CloudType, Law>::Sp
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar mass,
    const scalar muc
) const
{
    dragLaws::dragState s;
    s.mass = mass;
    s.rhop = p.rho();
    s.alphag = alphacPtr_ ? (*alphacPtr_)[p.cell()] : 1;
    s.slip = this->slip(p, td);
    s.d = p.d();
    s.rhog = td.rhoc();
    s.mug = muc;

    if (polydisperse_.active())
    {
        const scalar scale = polydisperse_.toMeanDiameter(s, p.cell());
        return scale*law_.Sp(s);
    }
    return law_.Sp(s);
}


template<class CloudType, class Law>
void Foam::CorrelationDragForce<CloudType, Law>::cacheFields(const bool store)
{
    MppicDragForce<CloudType>::cacheFields(store);

    if (!store || !polydisperse_.active())
    {
        return;
    }

    polydisperse_.reset(this->mesh().nCells());
    for (const typename CloudType::parcelType& p : this->owner())
    {
        polydisperse_.add(p.cell(), p.nParticle(), p.d());
    }
}


// ************************************************************************* //
