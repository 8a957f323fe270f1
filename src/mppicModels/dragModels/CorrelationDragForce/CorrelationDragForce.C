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
    alphacPtr_(lookupAlphac(mesh, this->coeffs()))
{
    wordList valid(MppicDragForce<CloudType>::keywords);
    valid.append(Law::keywords);
    if (Law::gasFraction)
    {
        valid.append("alphac");
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

    return law_.Sp(s);
}


// ************************************************************************* //
