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

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The sub-dictionary name of the cloud's properties, FatalIOError naming
//  it when it is missing
const dictionary& requiredSubDict
(
    const dictionary& cloudProperties,
    const word& name
)
{
    if (!cloudProperties.found(name))
    {
        FatalIOErrorInFunction(cloudProperties)
            << "Dictionary " << cloudProperties.name()
            << ": required sub-dictionary " << name << " is missing"
            << exit(FatalIOError);
    }

    return cloudProperties.subDict(name);
}

} // End anonymous namespace


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


void Foam::cloudInputChecks::forEachInjectionModel
(
    const dictionary& cloudProperties,
    const std::function<void(const dictionary&)>& check
)
{
    const dictionary& injectors =
        cloudProperties.subOrEmptyDict("subModels")
       .subOrEmptyDict("injectionModels");

    for (const entry& e : injectors)
    {
        if (e.isDict())
        {
            check(e.dict());
        }
    }
}


void Foam::cloudInputChecks::statisticalWeights
(
    const dictionary& cloudProperties
)
{
    forEachInjectionModel
    (
        cloudProperties,
        [](const dictionary& model)
        {
            if (model.found("nParticle"))
            {
                mppicCoefficients::read
                (
                    model,
                    "nParticle",
                    mppicCoefficients::bounds::above(0)
                );
            }
        }
    );
}


void Foam::cloudInputChecks::injectionAmounts
(
    const dictionary& cloudProperties
)
{
    forEachInjectionModel
    (
        cloudProperties,
        [](const dictionary& model)
        {
            for (const word keyword : {"massTotal", "parcelsPerSecond"})
            {
                mppicCoefficients::read
                (
                    model,
                    keyword,
                    0,
                    mppicCoefficients::bounds::atLeast(0)
                );
            }
        }
    );
}


void Foam::cloudInputChecks::constantProperties
(
    const dictionary& cloudProperties
)
{
    const dictionary& props =
        requiredSubDict(cloudProperties, "constantProperties");

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
    const dictionary& solution = requiredSubDict(cloudProperties, "solution");

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
