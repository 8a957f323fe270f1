/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Instantiates the averaging methods of libmppicModels (linearHat,
    cornerNodes, diffusion) for scalar and vector, for every MPPIC cloud:
    selected by averagingMethod in the cloud's solution dictionary.

\*---------------------------------------------------------------------------*/

#include "fvcGrad.H"
#include "polyMeshTetDecomposition.H"
#include "pointFields.H"
#include "makeMppicAveragingMethods.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makeMppicAveragingMethods();
}

// ************************************************************************* //
