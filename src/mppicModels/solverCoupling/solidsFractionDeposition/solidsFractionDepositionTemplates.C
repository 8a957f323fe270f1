/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "solidsFractionDeposition.H"
#include "tetIndices.H"
#include "polyMeshTetDecomposition.H"
#include "AveragingMethod.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::tmp<Foam::scalarField>
Foam::solidsFractionDeposition::cellFraction(const CloudType& cloud) const
{
    if (method_ == method::cell)
    {
        return tmp<scalarField>::New(cloud.theta()().primitiveField());
    }

    const fvMesh& mesh = cloud.mesh();

    autoPtr<AveragingMethod<scalar>> deposit
    (
        AveragingMethod<scalar>::New
        (
            IOobject
            (
                cloud.name() + ":solidsFractionDeposition",
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

    return tmp<scalarField>::New(deposit->primitiveField());
}


// ************************************************************************* //
