/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Application
    Test-reconstructFlux

Description
    mppicReconstruct::reconstructFlux against the exact answer: the face
    flux U0 & S_f of a uniform vector U0 = (1 2 3) reconstructs to U0 in
    every cell, to round-off, on any mesh (sum_f n_f (n_f & U0)|S_f| =
    (sum_f n_f S_f) & U0). The mesh is a sheared box (case/system/
    blockMeshDict, 4 x 8 x 3 cells), where the tensor sum_f n_f S_f has
    off-diagonal entries. Checked: the largest |U - U0| over the cells, from
    a named flux and from a temporary one, each <= 1e-12 |U0|; and the
    boundary values (extrapolated) equal U0 as well.

    Also printed, not checked: the error of OpenFOAM's fvc::reconstruct on
    the same flux (v1912 built with GCC 12 gets the y and z components
    wrong on such cells, see reconstructFlux.H); the test passes whatever
    that shows, so that a fixed OpenFOAM does not fail it.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "reconstructFlux.H"
#include "unitTest.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const vector U0(1, 2, 3);
    const surfaceScalarField flux("flux", U0 & mesh.Sf());

    // the mesh does have off-diagonal tensors (else the test proves nothing)
    const surfaceVectorField SfHat(mesh.Sf()/mesh.magSf());
    const volTensorField faceTensor(fvc::surfaceSum(SfHat*mesh.Sf()));
    scalar offDiagonal = 0;
    forAll(faceTensor, celli)
    {
        const tensor& t = faceTensor[celli];
        offDiagonal =
            max(offDiagonal, (mag(t.xy()) + mag(t.xz()) + mag(t.yz()))/mag(t));
    }
    unitTest::checkTrue
    (
        "sheared cells: off-diagonal part of sum n S up to "
      + name(offDiagonal) + " of its norm (> 0.05)",
        offDiagonal > 0.05
    );

    const volVectorField U(mppicReconstruct::reconstructFlux(flux));
    const volVectorField Utmp
    (
        mppicReconstruct::reconstructFlux
        (
            tmp<surfaceScalarField>(new surfaceScalarField("flux2", flux))
        )
    );

    const scalar cellError = max(mag(U.primitiveField() - U0))/mag(U0);
    unitTest::checkTrue
    (
        "reconstructFlux(U0 & Sf): max |U - U0|/|U0| over the cells "
      + name(cellError) + " <= 1e-12",
        cellError <= 1e-12
    );
    const scalar tmpError = max(mag(Utmp.primitiveField() - U0))/mag(U0);
    unitTest::checkTrue
    (
        "reconstructFlux(tmp): max |U - U0|/|U0| over the cells "
      + name(tmpError) + " <= 1e-12",
        tmpError <= 1e-12
    );
    scalar boundaryError = 0;
    forAll(U.boundaryField(), patchi)
    {
        if (U.boundaryField()[patchi].size())
        {
            boundaryError = max
            (
                boundaryError,
                max(mag(U.boundaryField()[patchi] - U0))/mag(U0)
            );
        }
    }
    unitTest::checkTrue
    (
        "reconstructFlux(U0 & Sf): max |U - U0|/|U0| on the boundary "
      + name(boundaryError) + " <= 1e-12",
        boundaryError <= 1e-12
    );
    unitTest::checkTrue
    (
        "dimensions of the reconstruction are those of flux/area",
        U.dimensions() == flux.dimensions()/dimArea
    );

    const volVectorField Ufvc(fvc::reconstruct(flux));
    Info<< "(not checked) fvc::reconstruct on the same flux: max |U - U0| = "
        << max(mag(Ufvc.primitiveField() - U0)) << endl;

    return unitTest::summary();
}


// ************************************************************************* //
