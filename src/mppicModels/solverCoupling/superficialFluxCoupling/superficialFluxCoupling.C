/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "superficialFluxCoupling.H"
#include "reconstructFlux.H"
#include "ddtScheme.H"
#include "EulerDdtScheme.H"
#include "fvcFlux.H"
#include "surfaceInterpolate.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

Foam::tmp<Foam::surfaceScalarField> Foam::mppicSuperficialFlux::ddtCorr
(
    const volScalarField& alpha,
    const volVectorField& U,
    const surfaceScalarField& phi
)
{
    const fvMesh& mesh = U.mesh();
    const word ddtName("ddt(" + alpha.name() + ',' + U.name() + ')');

    tmp<fv::ddtScheme<vector>> tscheme
    (
        fv::ddtScheme<vector>::New(mesh, mesh.ddtScheme(ddtName))
    );
    if (!isA<fv::EulerDdtScheme<vector>>(tscheme()))
    {
        FatalIOErrorInFunction(mesh.schemesDict())
            << "Dictionary " << mesh.schemesDict().name()
            << ", ddtSchemes: " << ddtName << " is "
            << tscheme().type() << "; superficialFluxCoupling supports"
            << " Euler only" << exit(FatalIOError);
    }

    const surfaceScalarField superficialFlux0
    (
        fvc::interpolate(alpha.oldTime())*phi.oldTime()
    );
    const surfaceScalarField fluxDifference
    (
        superficialFlux0 - fvc::flux(alpha.oldTime()*U.oldTime())
    );

    return
        tscheme.ref().fvcDdtPhiCoeff
        (
            U.oldTime(), superficialFlux0, fluxDifference
        )
       *fluxDifference/mesh.time().deltaT();
}


Foam::tmp<Foam::volVectorField> Foam::mppicSuperficialFlux::cellVelocity
(
    const surfaceScalarField& superficialFlux,
    const volScalarField& alpha,
    const volVectorField& H,
    const volScalarField& rAU
)
{
    using mppicReconstruct::reconstructFlux;

    const volVectorField smoothedH(reconstructFlux(fvc::flux(H)));

    return
        reconstructFlux(superficialFlux)/alpha
      + rAU*reconstructFlux(fvc::flux(H - smoothedH));
}


// ************************************************************************* //
