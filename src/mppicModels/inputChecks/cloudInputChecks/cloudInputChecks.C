/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "cloudInputChecks.H"
#include "boundedCoefficient.H"
#include "liquidProperties.H"
#include "fvMesh.H"
#include "volFields.H"
#include "interpolation.H"
#include "polyMeshTetDecomposition.H"
#include "pointFields.H"
#include "AveragingMethod.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * //

void Foam::cloudInputChecks::checkName
(
    const dictionary& dict,
    const word& keyword,
    const word& value,
    const wordList& allowed,
    const string& what
)
{
    if (!allowed.found(value))
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ", keyword " << keyword
            << ": value " << value << " is not " << what.c_str()
            << "; allowed names " << allowed << exit(FatalIOError);
    }
}


void Foam::cloudInputChecks::cloudProperties
(
    const dictionary& cloudProperties,
    const fvMesh& mesh
)
{
    solutionControls(cloudProperties, mesh);
    constantProperties(cloudProperties);
    statisticalWeights(cloudProperties);
    injectionAmounts(cloudProperties);
    sizeDistributions(cloudProperties);
    injectionPositions(cloudProperties, mesh);
}


void Foam::cloudInputChecks::statisticalWeights
(
    const dictionary& cloudProperties
)
{
    const dictionary& injectors =
        cloudProperties.subOrEmptyDict("subModels")
       .subOrEmptyDict("injectionModels");

    for (const entry& e : injectors)
    {
        if (e.isDict() && e.dict().found("nParticle"))
        {
            mppicCoefficients::read
            (
                e.dict(),
                "nParticle",
                mppicCoefficients::bounds::above(0)
            );
        }
    }
}


void Foam::cloudInputChecks::injectionAmounts
(
    const dictionary& cloudProperties
)
{
    const dictionary& injectors =
        cloudProperties.subOrEmptyDict("subModels")
       .subOrEmptyDict("injectionModels");

    for (const entry& e : injectors)
    {
        if (!e.isDict())
        {
            continue;
        }

        for (const word keyword : {"massTotal", "parcelsPerSecond"})
        {
            mppicCoefficients::read
            (
                e.dict(),
                keyword,
                0,
                mppicCoefficients::bounds::atLeast(0)
            );
        }
    }
}


void Foam::cloudInputChecks::constantProperties
(
    const dictionary& cloudProperties
)
{
    if (!cloudProperties.found("constantProperties"))
    {
        FatalIOErrorInFunction(cloudProperties)
            << "Dictionary " << cloudProperties.name()
            << ": required sub-dictionary constantProperties is missing"
            << exit(FatalIOError);
    }

    const dictionary& props = cloudProperties.subDict("constantProperties");

    // Particle density
    mppicCoefficients::read
    (
        props,
        "rho0",
        mppicCoefficients::bounds::above(0)
    );

    // Largest solids fraction the gas sees (the solvers' gas fraction is
    // bounded below by 1 - alphaMax)
    mppicCoefficients::read
    (
        props,
        "alphaMax",
        mppicCoefficients::bounds::openClosed(0, 1)
    );
}


void Foam::cloudInputChecks::solutionControls
(
    const dictionary& cloudProperties,
    const fvMesh& mesh
)
{
    if (!cloudProperties.found("solution"))
    {
        FatalIOErrorInFunction(cloudProperties)
            << "Dictionary " << cloudProperties.name()
            << ": required sub-dictionary solution is missing"
            << exit(FatalIOError);
    }

    const dictionary& solution = cloudProperties.subDict("solution");

    // Largest parcel Courant number of a tracking step (OpenFOAM reads it
    // where given, else uses its default)
    mppicCoefficients::read
    (
        solution,
        "maxCo",
        1,
        mppicCoefficients::bounds::above(0)
    );

    // Averaging method: the MPPIC parcels, packing, damping and isotropy
    // models all select it from solution/averagingMethod, scalar and vector
    if (!solution.found("averagingMethod", keyType::LITERAL))
    {
        FatalIOErrorInFunction(solution)
            << "Dictionary " << solution.name()
            << ": required keyword averagingMethod is missing; allowed names "
            << AveragingMethod<scalar>::dictionaryConstructorTablePtr_
               ->sortedToc()
            << exit(FatalIOError);
    }

    const word averaging(solution.get<word>("averagingMethod"));

    checkName
    (
        solution, "averagingMethod", averaging,
        AveragingMethod<scalar>::dictionaryConstructorTablePtr_->sortedToc(),
        "an averaging method"
    );
    checkName
    (
        solution, "averagingMethod", averaging,
        AveragingMethod<vector>::dictionaryConstructorTablePtr_->sortedToc(),
        "an averaging method for vectors"
    );

    // Interpolation of each carrier field: the vector table for a vector
    // field of the mesh (the gas velocity), else the scalar one
    const dictionary& schemes =
        solution.subOrEmptyDict("interpolationSchemes");

    for (const entry& e : schemes)
    {
        if (e.isDict())
        {
            continue;
        }

        const word& field = e.keyword();
        const word scheme(e.stream());

        if (mesh.foundObject<volVectorField>(field))
        {
            checkName
            (
                schemes, field, scheme,
                interpolation<vector>::dictionaryConstructorTablePtr_
                    ->sortedToc(),
                "an interpolation of vector fields"
            );
        }
        else
        {
            checkName
            (
                schemes, field, scheme,
                interpolation<scalar>::dictionaryConstructorTablePtr_
                    ->sortedToc(),
                "an interpolation of scalar fields"
            );
        }
    }
}


void Foam::cloudInputChecks::liquids(const dictionary& thermophysicalProperties)
{
    if (!thermophysicalProperties.found("liquids"))
    {
        return;
    }

    const dictionary& liquidsDict =
        thermophysicalProperties.subDict("liquids");

    for (const entry& e : liquidsDict)
    {
        const word& name = e.keyword();

        if (!liquidProperties::ConstructorTablePtr_->found(name))
        {
            FatalIOErrorInFunction(liquidsDict)
                << "Dictionary " << liquidsDict.name() << ", keyword "
                << name << ": not a liquid of OpenFOAM's liquid-properties"
                << " database, which has "
                << liquidProperties::ConstructorTablePtr_->sortedToc()
                << exit(FatalIOError);
        }
    }
}


// ************************************************************************* //
