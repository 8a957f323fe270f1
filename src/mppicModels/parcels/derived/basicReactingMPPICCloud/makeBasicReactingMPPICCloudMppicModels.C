/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Instantiates the models of libmppicModels for basicReactingMPPICCloud,
    the cloud of mppicReactingPimpleFoam: the same lists as for
    basicKinematicMPPICCloud, each model family listed once in
    parcels/include.

\*---------------------------------------------------------------------------*/

#include "basicReactingMPPICCloud.H"

#include "makeMppicParcelPackingModels.H"
#include "makeMppicParcelForces.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeMppicParcelPackingModels(basicReactingMPPICCloud);
makeMppicParcelForces(basicReactingMPPICCloud);

// ************************************************************************* //
