/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Registers the linearHat interpolation for scalar and vector fields in
    OpenFOAM's interpolation run-time selection table.

\*---------------------------------------------------------------------------*/

#include "interpolationLinearHat.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makeInterpolationType(interpolationLinearHat, scalar);
    makeInterpolationType(interpolationLinearHat, vector);
}

// ************************************************************************* //
