/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "basicReactingMPPICParcel.H"
#include "Cloud.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    // The layers below also name themselves (in their I/O)
    typedef ThermoParcel<MPPICParcel<KinematicParcel<particle>>>
        thermoMPPICParcel;
    typedef ReactingParcel<thermoMPPICParcel> reactingMPPICParcel;

    defineTemplateTypeNameAndDebug(thermoMPPICParcel, 0);
    defineTemplateTypeNameAndDebug(reactingMPPICParcel, 0);
    defineTemplateTypeNameAndDebug(basicReactingMPPICParcel, 0);
    defineTemplateTypeNameAndDebug(Cloud<basicReactingMPPICParcel>, 0);
}

// ************************************************************************* //
