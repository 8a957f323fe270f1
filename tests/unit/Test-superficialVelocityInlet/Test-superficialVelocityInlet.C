/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Application
    Test-superficialVelocityInlet

Description
    superficialVelocityInletVelocity on the bottom patch of the unit box
    (4 x 8 x 1 cells of 0.25 x 0.25 x 0.1; the bottom faces have area
    0.025 and outward normal (0 -1 0)). The gas fraction alpha.air is
    zeroGradient, 0.4, 0.5, 0.8 and 1 in the four cells of the bottom row.
    superficialVelocity table ((0 (0 0 0)) (2 (0 1 0))): at t = 1 the
    superficial velocity is (0 0.5 0), so, by hand,
        U on the faces = 0.5/alpha = 1.25, 1.0, 0.625, 0.5 (y component),
        alpha U.S per face = -0.5*0.025 = -0.0125, the patch -0.05 m3/s,
    at t = 3 (beyond the table: held) (0 1 0): U = 2.5 on the first face.
    The default gas fraction field of U.air is alpha.air (its group).
    Bad input, each a FatalIOError naming the keyword and the value:
    alpha alpha.nothing (no such field); a gas fraction 0 on the patch.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "superficialVelocityInletVelocityFvPatchVectorField.H"
#include "unitTest.H"

using namespace Foam::unitTest;

dictionary inletDict(const string& extra)
{
    return dictionary
    (
        IStringStream
        (
            "type superficialVelocityInletVelocity;"
            "superficialVelocity table ((0 (0 0 0)) (2 (0 1 0)));"
          + extra
        )()
    );
}


int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    volScalarField alpha
    (
        IOobject("alpha.air", runTime.timeName(), mesh),
        mesh,
        dimensionedScalar("one", dimless, 1.0),
        zeroGradientFvPatchScalarField::typeName
    );
    const scalarList bottomRow({0.4, 0.5, 0.8, 1.0});
    forAll(bottomRow, i)
    {
        alpha[i] = bottomRow[i];
    }
    alpha.correctBoundaryConditions();

    volVectorField U
    (
        IOobject("U.air", runTime.timeName(), mesh),
        mesh,
        dimensionedVector("zero", dimVelocity, Zero)
    );

    const label bottom = mesh.boundaryMesh().findPatchID("bottom");
    const fvPatch& patch = mesh.boundary()[bottom];

    runTime.setTime(1.0, 1);

    superficialVelocityInletVelocityFvPatchVectorField inlet
    (
        patch, U, inletDict("")
    );
    inlet.updateCoeffs();

    const scalarList expected({1.25, 1.0, 0.625, 0.5});
    scalar patchFlux = 0;
    forAll(inlet, facei)
    {
        const label celli = patch.faceCells()[facei];
        const label column = celli % 4;
        checkClose
        (
            "U_y on the face of column " + Foam::name(column),
            inlet[facei].y(), expected[column], 1e-12
        );
        checkClose
        (
            "x and z components zero, column " + Foam::name(column),
            mag(inlet[facei].x()) + mag(inlet[facei].z()), 0, 0, 1e-300
        );
        const scalar faceFlux =
            alpha.boundaryField()[bottom][facei]
           *(inlet[facei] & patch.Sf()[facei]);
        checkClose
        (
            "alpha U.S on the face of column " + Foam::name(column),
            faceFlux, -0.0125, 1e-12
        );
        patchFlux += faceFlux;
    }
    checkClose("alpha U.S over the patch", patchFlux, -0.05, 1e-12);

    runTime.setTime(3.0, 2);
    superficialVelocityInletVelocityFvPatchVectorField later
    (
        patch, U, inletDict("")
    );
    later.updateCoeffs();
    forAll(later, facei)
    {
        if (patch.faceCells()[facei] == 0)
        {
            checkClose("t = 3, column 0: U_y", later[facei].y(), 2.5, 1e-12);
        }
    }

    checkClose
    (
        "superficialVelocity() at t = 3", later.superficialVelocity().y(),
        1.0, 1e-12
    );

    checkTrue
    (
        "alpha: no such field -> FatalIOError",
        raisesError
        (
            [&]()
            {
                superficialVelocityInletVelocityFvPatchVectorField bad
                (
                    patch, U, inletDict("alpha alpha.nothing;")
                );
                bad.updateCoeffs();
            },
            {"alpha", "alpha.nothing", "bottom", "alpha.air"}
        )
    );

    alpha[2] = 0;
    alpha.correctBoundaryConditions();
    checkTrue
    (
        "gas fraction 0 on the patch -> FatalIOError",
        raisesError
        (
            [&]()
            {
                superficialVelocityInletVelocityFvPatchVectorField bad
                (
                    patch, U, inletDict("")
                );
                bad.updateCoeffs();
            },
            {"alpha", "alpha.air", "bottom", "(0,", "1]"}
        )
    );

    return summary();
}


// ************************************************************************* //
