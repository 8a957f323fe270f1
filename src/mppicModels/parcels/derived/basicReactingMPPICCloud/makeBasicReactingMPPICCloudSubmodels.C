/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Instantiates OpenFOAM's own submodels (those of its reacting clouds and
    its MPPIC damping, isotropy and packing models) for
    basicReactingMPPICCloud, a cloud type OpenFOAM's library does not have.
    libmppicModels' own models: makeBasicReactingMPPICCloudMppicModels.C.

\*---------------------------------------------------------------------------*/

#include "basicReactingMPPICCloud.H"

#include "makeParcelCloudFunctionObjects.H"

// Kinematic
#include "makeThermoParcelForces.H"
#include "makeParcelDispersionModels.H"
#include "makeReactingParcelInjectionModels.H"
#include "makeParcelPatchInteractionModels.H"
#include "makeParcelStochasticCollisionModels.H"
#include "makeReactingParcelSurfaceFilmModels.H"

// Thermodynamic
#include "makeParcelHeatTransferModels.H"

// Reacting
#include "makeReactingParcelCompositionModels.H"
#include "makeReactingParcelPhaseChangeModels.H"

// MPPIC
#include "makeMPPICParcelDampingModels.H"
#include "makeMPPICParcelIsotropyModels.H"
#include "makeMPPICParcelPackingModels.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeParcelCloudFunctionObjects(basicReactingMPPICCloud);

makeThermoParcelForces(basicReactingMPPICCloud);
makeParcelDispersionModels(basicReactingMPPICCloud);
makeReactingParcelInjectionModels(basicReactingMPPICCloud);
makeParcelPatchInteractionModels(basicReactingMPPICCloud);
makeParcelStochasticCollisionModels(basicReactingMPPICCloud);
makeReactingParcelSurfaceFilmModels(basicReactingMPPICCloud);

makeParcelHeatTransferModels(basicReactingMPPICCloud);

makeReactingParcelCompositionModels(basicReactingMPPICCloud);
makeReactingParcelPhaseChangeModels(basicReactingMPPICCloud);

makeMPPICParcelDampingModels(basicReactingMPPICCloud);
makeMPPICParcelIsotropyModels(basicReactingMPPICCloud);
makeMPPICParcelPackingModels(basicReactingMPPICCloud);

// ************************************************************************* //
