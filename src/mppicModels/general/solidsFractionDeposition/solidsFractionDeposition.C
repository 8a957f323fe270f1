/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "solidsFractionDeposition.H"
#include "AveragingMethod.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::Enum<Foam::solidsFractionDeposition::method>
Foam::solidsFractionDeposition::methodNames
({
    { method::cell, "cell" },
    { method::averaging, "averaging" },
});


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::solidsFractionDeposition::method
Foam::solidsFractionDeposition::readMethod(const dictionary& dict)
{
    const word name
    (
        dict.lookupOrDefault<word>("solidsFractionFrom", methodNames[method::cell])
    );

    if (!methodNames.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ", keyword solidsFractionFrom:"
            << " value " << name << " is not one of " << methodNames.toc()
            << exit(FatalIOError);
    }
    return methodNames[name];
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidsFractionDeposition::solidsFractionDeposition
(
    const basicKinematicMPPICCloud& cloud
)
:
    cloud_(cloud),
    method_(readMethod(cloud.particleProperties()))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField>
Foam::solidsFractionDeposition::cellFraction() const
{
    if (method_ == method::cell)
    {
        return tmp<scalarField>::New(cloud_.theta()().primitiveField());
    }

    const fvMesh& mesh = cloud_.mesh();

    autoPtr<AveragingMethod<scalar>> deposit
    (
        AveragingMethod<scalar>::New
        (
            IOobject
            (
                cloud_.name() + ":solidsFractionDeposition",
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            cloud_.solution().dict(),
            mesh
        )
    );

    for (const basicKinematicMPPICCloud::parcelType& p : cloud_)
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
