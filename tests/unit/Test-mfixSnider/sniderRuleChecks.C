/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    See sniderRuleChecks.H.

\*---------------------------------------------------------------------------*/

#include "sniderStressRules.H"
#include "cellFaceGeometry.H"
#include "fvMesh.H"
#include "unitTest.H"
#include "sniderRuleChecks.H"

using namespace Foam;
using namespace Foam::unitTest;

// * * * * * * * * * * * * * * * * Test groups * * * * * * * * * * * * * * //

void testRelease()
{
    dictionary coeffs;
    coeffs.add("closePackFraction", 0.6);
    const sniderStressRules never(coeffs, 0.6);
    coeffs.add("releaseAbove", 0.65);
    const sniderStressRules release(coeffs, 0.6);

    const vector grad(3, -4, 0);
    const scalar l = 3.7*0.005/(3*Foam::sqrt(2.0)*0.68);
    const vector v = release.releaseVelocity(grad, 0.68, 0.005, 1e-3);
    checkClose("release above 0.65, x", v.x(), -0.6*l/1e-3, 1e-12);
    checkClose("release above 0.65, y", v.y(), 0.8*l/1e-3, 1e-12);
    checkClose("release above 0.65, z", v.z(), 0, 1e-12, 1);
    checkClose
    (
        "no release at 0.65",
        mag(release.releaseVelocity(grad, 0.65, 0.005, 1e-3)), 0, 1e-12, 1
    );
    checkClose
    (
        "no release by default, at the cap 0.69",
        mag(never.releaseVelocity(grad, 0.69, 0.005, 1e-3)), 0, 1e-12, 1
    );
}


void testVelocityIntoBoundary(const fvMesh& mesh)
{
    // Cell 0: the corner cell on the side wall x = 0 and the bottom y = 0;
    // cell 5 (column 1, row 1) has no boundary face
    const vector U(-2, -1, 0.5);
    const point x(0.01, 0.1, 0.05);
    const List<Tuple2<vector, vector>> cases
    ({
        {vector(-0.02, 0.05, 0), vector(0, -1, 0.5)},
        {vector(-0.005, -0.2, 0), vector(-2, 0, 0.5)},
        {vector(-0.02, -0.2, 0), vector(0, 0, 0.5)},
        {vector(-0.005, -0.05, 0), U}
    });
    for (const Tuple2<vector, vector>& c : cases)
    {
        const vector kept =
            cellFaceGeometry::withoutVelocityIntoBoundary
            (
                mesh, 0, x, c.first(), U
            );
        for (direction k = 0; k < vector::nComponents; ++k)
        {
            checkClose
            (
                "velocity into a boundary, d = " + name(c.first())
              + ", component " + name(k),
                kept[k], c.second()[k], 1e-12, 1
            );
        }
    }
    checkClose
    (
        "velocity away from the wall it reaches: kept",
        cellFaceGeometry::withoutVelocityIntoBoundary
        (
            mesh, 0, x, vector(-0.02, 0, 0), vector(2, 0, 0)
        ).x(),
        2, 1e-12
    );
    checkClose
    (
        "no boundary face: kept",
        cellFaceGeometry::withoutVelocityIntoBoundary
        (
            mesh, 5, point(0.375, 0.375, 0.05), vector(-1, -1, 0), U
        ).x(),
        -2, 1e-12
    );
}


// ************************************************************************* //
