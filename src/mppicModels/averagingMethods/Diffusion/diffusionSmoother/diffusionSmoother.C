/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "diffusionSmoother.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "fvMatrices.H"
#include "fvmSup.H"
#include "laplacianScheme.H"
#include "zeroGradientFvPatchFields.H"
#include "IStringStream.H"

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- Linear-solver controls of the smoothing step (no fvSolution entry)
Foam::dictionary smoothingSolverControls()
{
    Foam::dictionary controls;
    controls.add("solver", Foam::word("PCG"));
    controls.add("preconditioner", Foam::word("DIC"));
    controls.add("tolerance", 1e-12);
    controls.add("relTol", 0.0);
    controls.add("maxIter", 1000);
    return controls;
}


//- An unregistered, unwritten IOobject for a temporary field
Foam::IOobject temporaryField(const Foam::fvMesh& mesh, const Foam::word& name)
{
    return Foam::IOobject
    (
        name,
        mesh.time().timeName(),
        mesh,
        Foam::IOobject::NO_READ,
        Foam::IOobject::NO_WRITE,
        false
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::diffusionSmoother::diffusionSmoother
(
    const fvMesh& mesh,
    const scalar bandwidth,
    const label nSteps
)
:
    mesh_(mesh),
    stepTime_(0.25*sqr(bandwidth)/nSteps),
    nSteps_(nSteps)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::diffusionSmoother::implicitStep(volScalarField& phi) const
{
    const scalarField phiOld(phi.primitiveField());

    const surfaceScalarField unitDiffusivity
    (
        temporaryField(mesh_, "diffusionSmoother:diffusivity"),
        mesh_,
        dimensionedScalar("one", dimless, 1)
    );

    IStringStream schemeSpec("Gauss linear uncorrected");
    tmp<fv::laplacianScheme<scalar, scalar>> laplacian
    (
        fv::laplacianScheme<scalar, scalar>::New(mesh_, schemeSpec)
    );

    // (phi - phiOld)/dt = laplacian(phi), dt = stepTime_ [m^2]
    const dimensionedScalar rate("rate", dimless/dimArea, 1/stepTime_);
    fvScalarMatrix stepEqn
    (
        fvm::Sp(rate, phi) - laplacian->fvmLaplacian(unitDiffusivity, phi)
    );
    stepEqn.source() += rate.value()*phiOld*mesh_.V();

    const int printResidual = solverPerformance::debug;
    solverPerformance::debug = 0;
    stepEqn.solve(smoothingSolverControls());
    solverPerformance::debug = printResidual;

    // Conservative update with the fluxes of the solution
    const tmp<volScalarField> divFlux =
        laplacian->fvcLaplacian(unitDiffusivity, phi);
    phi.primitiveFieldRef() = phiOld + stepTime_*divFlux().primitiveField();
    phi.correctBoundaryConditions();
}


void Foam::diffusionSmoother::smoothComponent(scalarField& cellValues) const
{
    volScalarField phi
    (
        temporaryField(mesh_, "diffusionSmoother:phi"),
        mesh_,
        dimensionedScalar("zero", dimless, 0),
        zeroGradientFvPatchScalarField::typeName
    );
    phi.primitiveFieldRef() = cellValues;
    phi.correctBoundaryConditions();

    for (label step = 0; step < nSteps_; ++step)
    {
        implicitStep(phi);
    }

    cellValues = phi.primitiveField();
}


// ************************************************************************* //
