/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Instantiates the models of libmppicModels for basicKinematicMPPICCloud,
    the cloud of MPPICFoam and mppicPimpleFoam. One such file per cloud
    type supported; each model family is listed once in parcels/include.

\*---------------------------------------------------------------------------*/

#include "basicKinematicMPPICCloud.H"

#include "makeMppicParcelPackingModels.H"
#include "makeMppicParcelForces.H"
#include "makeMppicInjectionModels.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeMppicParcelPackingModels(basicKinematicMPPICCloud);
makeMppicParcelForces(basicKinematicMPPICCloud);
makeMppicInjectionModels(basicKinematicMPPICCloud);

// ************************************************************************* //
