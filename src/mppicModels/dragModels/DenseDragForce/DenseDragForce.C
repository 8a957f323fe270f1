/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "DenseDragForce.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
const Foam::volScalarField& Foam::DenseDragForce<CloudType>::lookupAlphac
(
    const fvMesh& mesh,
    const dictionary& coeffs
)
{
    const word name(coeffs.getWord("alphac"));

    if (!mesh.foundObject<volScalarField>(name))
    {
        FatalIOErrorInFunction(coeffs)
            << "Dictionary " << coeffs.name() << ", keyword alphac: no gas"
            << " volume-fraction field " << name << "; volScalarFields: "
            << mesh.sortedNames<volScalarField>() << exit(FatalIOError);
    }

    return mesh.lookupObject<volScalarField>(name);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::DenseDragForce<CloudType>::DenseDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict,
    const word& forceType
)
:
    MppicDragForce<CloudType>(owner, mesh, dict, forceType),
    alphac_(lookupAlphac(mesh, this->coeffs()))
{}


template<class CloudType>
Foam::DenseDragForce<CloudType>::DenseDragForce
(
    const DenseDragForce<CloudType>& df
)
:
    MppicDragForce<CloudType>(df),
    alphac_(df.alphac_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::DenseDragForce<CloudType>::Sp
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar mass,
    const scalar muc
) const
{
    const scalar alphag = alphac(p);

    return
        mass*K(alphag, this->slip(p, td), p.d(), td.rhoc(), muc)
       /(p.rho()*alphag);
}


// ************************************************************************* //
