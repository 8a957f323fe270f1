/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "solidsFractionDeposition.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::autoPtr<Foam::AveragingMethod<Foam::scalar>>
Foam::solidsFractionDeposition::averagedSolidsFraction
(
    const CloudType& cloud,
    const word& name
)
{
    const fvMesh& mesh = cloud.mesh();

    autoPtr<AveragingMethod<scalar>> deposit
    (
        AveragingMethod<scalar>::New
        (
            IOobject
            (
                name,
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            cloud.solution().dict(),
            mesh
        )
    );

    for (const typename CloudType::parcelType& p : cloud)
    {
        deposit->add
        (
            p.coordinates(),
            p.currentTetIndices(),
            p.nParticle()*p.volume()
        );
    }
    deposit->average();

    return deposit;
}


template<class CloudType>
Foam::tmp<Foam::scalarField>
Foam::solidsFractionDeposition::cellFraction(const CloudType& cloud) const
{
    if (method_ == method::cell)
    {
        return tmp<scalarField>::New(cloud.theta()().primitiveField());
    }

    return tmp<scalarField>::New
    (
        averagedSolidsFraction
        (
            cloud, cloud.name() + ":solidsFractionDeposition"
        )->primitiveField()
    );
}


// ************************************************************************* //
