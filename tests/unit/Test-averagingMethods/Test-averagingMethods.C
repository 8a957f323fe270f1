/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Application
    Test-averagingMethods

Description
    The averaging methods linearHat, cornerNodes (cornerNodesChecks.C),
    diffusion (diffusionChecks.C) and the linearHat interpolation of
    libmppicModels, selected by name through OpenFOAM's
    run-time tables as the MPPIC cloud selects them, on two meshes:
    - region "periodic": a 1 m cube of 10 x 10 x 10 cells of 0.1 m (centres
      at 0.05, 0.15, ..., 0.95), every boundary cyclic;
    - the box of tests/unit/cases/box: 4 x 8 x 1 cells of 0.25 x 0.25 x
      0.1 m, walls (and a patch at the top).
    Weights are read back as (cell value) x (cell volume) after depositing
    1 at a point; the expected trilinear weights are written out below.

    Next to an inflow patch and a no-slip wall (boundaryInterpolation):
    linearHat gives the interior gas velocity, cellPoint a blend with the
    boundary values (the cause of a bubbling bed's missing weight).

    diffusion: bandwidth b, pseudo-time T = b^2/4, variance b^2/2 per
    direction; with b = 0.2 m: 0.02 m^2.

\*---------------------------------------------------------------------------*/

#include "averagingTestHelpers.H"
#include "interpolation.H"

using namespace Foam;
using namespace Foam::averagingTest;

// * * * * * * * * * * * * * * * * Test groups * * * * * * * * * * * * * * //

void linearHatWeights(const fvMesh& cube, const fvMesh& box)
{
    const dictionary linearHat(solutionDict("averagingMethod linearHat;"));

    checkWeights
    (
        "cell centre", cube, linearHat, point(0.45, 0.45, 0.45),
        {{point(0.45, 0.45, 0.45), 1}}
    );
    checkWeights
    (
        "face centre", cube, linearHat, point(0.5, 0.45, 0.45),
        {{point(0.45, 0.45, 0.45), 0.5}, {point(0.55, 0.45, 0.45), 0.5}}
    );
    cellWeights vertex;
    for (const scalar x : {0.45, 0.55})
    {
        for (const scalar y : {0.45, 0.55})
        {
            for (const scalar z : {0.45, 0.55})
            {
                vertex.append(Tuple2<point, scalar>(point(x, y, z), 0.125));
            }
        }
    }
    checkWeights("vertex of 8 cells", cube, linearHat, point(0.5, 0.5, 0.5), vertex);

    // (0.47, 0.42, 0.53) in the cell at (0.45, 0.45, 0.55): t = 0.2 toward
    // x = 0.55, 0.3 toward y = 0.35, 0.2 toward z = 0.45
    checkWeights
    (
        "off-centre point", cube, linearHat, point(0.47, 0.42, 0.53),
        {
            {point(0.45, 0.45, 0.55), 0.8*0.7*0.8},
            {point(0.55, 0.45, 0.55), 0.2*0.7*0.8},
            {point(0.45, 0.35, 0.55), 0.8*0.3*0.8},
            {point(0.55, 0.35, 0.55), 0.2*0.3*0.8},
            {point(0.45, 0.45, 0.45), 0.8*0.7*0.2},
            {point(0.55, 0.45, 0.45), 0.2*0.7*0.2},
            {point(0.45, 0.35, 0.45), 0.8*0.3*0.2},
            {point(0.55, 0.35, 0.45), 0.2*0.3*0.2}
        }
    );

    // Across the cyclics: 0.03 m from a cell centre toward the boundary
    checkWeights
    (
        "across a cyclic", cube, linearHat, point(0.02, 0.45, 0.45),
        {{point(0.05, 0.45, 0.45), 0.7}, {point(0.95, 0.45, 0.45), 0.3}}
    );
    checkWeights
    (
        "across two cyclics (edge)", cube, linearHat, point(0.02, 0.98, 0.45),
        {
            {point(0.05, 0.95, 0.45), 0.7*0.7},
            {point(0.95, 0.95, 0.45), 0.3*0.7},
            {point(0.05, 0.05, 0.45), 0.7*0.3},
            {point(0.95, 0.05, 0.45), 0.3*0.3}
        }
    );

    // Walls: the part beyond the wall stays in the near cell
    checkWeights
    (
        "next to a wall", box, linearHat, point(0.05, 1.1, 0.05),
        {{point(0.125, 1.125, 0.05), 0.9}, {point(0.125, 0.875, 0.05), 0.1}}
    );
    checkWeights
    (
        "in a wall corner", box, linearHat, point(0.02, 0.03, 0.01),
        {{point(0.125, 0.125, 0.05), 1}}
    );
}


void linearHatConservation(const fvMesh& cube)
{
    const dictionary linearHat(solutionDict("averagingMethod linearHat;"));
    autoPtr<AveragingMethod<vector>> average(newAverage<vector>(cube, linearHat));

    Random rng(1234);
    const label nParcels = 200;
    for (label i = 0; i < nParcels; ++i)
    {
        deposit(average(), cube, rng.sample01<vector>(), vector(1, -2, 0.5));
    }
    average->average();

    const vector total = totalAmount(average(), cube);
    checkClose("200 random parcels: total x", total.x(), nParcels, tol);
    checkClose("200 random parcels: total y", total.y(), -2*nParcels, tol);
    checkClose("200 random parcels: total z", total.z(), 0.5*nParcels, tol);
}


// A lattice of 2 x 2 parcels per cell of the box, at a quarter cell from
// the centre in x and y, deposits 4 parcels' worth in every cell, next to
// the walls and in the corners too (the reflected part makes up for what
// the cell beyond the wall would give); method linearHat or cornerNodes
void uniformLattice(const fvMesh& box, const word& method)
{
    const dictionary solution(solutionDict("averagingMethod " + method + ";"));
    autoPtr<AveragingMethod<scalar>> average(newAverage<scalar>(box, solution));

    const scalar h = 0.25;
    for (label i = 0; i < 8; ++i)
    {
        for (label j = 0; j < 16; ++j)
        {
            deposit(average(), box, point((i + 0.5)*h/2, (j + 0.5)*h/2, 0.05), 1.0);
        }
    }
    average->average();

    const scalarField density(average->primitiveField());
    const scalar expected = 4/(h*h*0.1);
    checkClose(method + " uniform lattice: largest cell value", max(density), expected, tol);
    checkClose(method + " uniform lattice: smallest cell value", min(density), expected, tol);
}


void linearHatInterpolation(const fvMesh& cube)
{
    const volVectorField& C = cube.C();
    volScalarField linear
    (
        IOobject("linear", cube.time().timeName(), cube),
        cube,
        dimensionedScalar("zero", dimless, 0)
    );
    linear.primitiveFieldRef() =
        2 + 3*C.component(0)().primitiveField()
      - C.component(1)().primitiveField() + 0.5*C.component(2)().primitiveField();

    autoPtr<interpolation<scalar>> scheme
    (
        interpolation<scalar>::New("linearHat", linear)
    );

    const dictionary linearHat(solutionDict("averagingMethod linearHat;"));
    autoPtr<AveragingMethod<scalar>> average(newAverage<scalar>(cube, linearHat));
    average()[0] = linear.primitiveField();

    const pointField interior
    ({
        point(0.47, 0.42, 0.53), point(0.5, 0.5, 0.5),
        point(0.31, 0.77, 0.12), point(0.9, 0.1, 0.6)
    });
    for (const point& x : interior)
    {
        const scalar exact = 2 + 3*x.x() - x.y() + 0.5*x.z();
        const passiveParticle p(cube, x);
        checkClose
        (
            "interpolation linearHat of 2 + 3x - y + z/2 at " + Foam::name(x),
            scheme->interpolate(x, p.cell()), exact, tol
        );
        checkClose
        (
            "averaging linearHat interpolate of the same at " + Foam::name(x),
            average->interpolate(p.coordinates(), p.currentTetIndices()),
            exact, tol
        );
    }
}


// The gas velocity a parcel next to an inflow patch and a no-slip wall
// sees (uniformFluidization, README): the box's cells hold the interstitial
// velocity of a bed fluidized at 0.5 m/s superficial and gas fraction 0.52,
// (0 0.96 0); the bottom patch holds the inflow's 0.5 m/s (gas fraction 1
// there), the side walls the no-slip 0. A parcel a quarter cell from the
// bottom and from the left wall, at (0.0625, 0.0625, 0.05):
//   linearHat: boundary values are not used (the kernel's part beyond the
//       boundary is reflected into the cell) -> 0.96 exactly;
//   cellPoint: the cell's vertices on the bottom and the wall take the
//       boundary values, so the parcel sees a blend: at most 0.8 x 0.96.
//   The drag on such parcels was too small and they sank onto the bottom,
//   which then carried 0.2 of a bubbling bed's weight.
void boundaryInterpolation(const fvMesh& box)
{
    volVectorField U
    (
        IOobject("U", box.time().timeName(), box),
        box,
        dimensionedVector("U", dimVelocity, vector(0, 0.96, 0))
    );
    const label bottom = box.boundaryMesh().findPatchID("bottom");
    const label walls = box.boundaryMesh().findPatchID("walls");
    U.boundaryFieldRef()[bottom] == vector(0, 0.5, 0);
    U.boundaryFieldRef()[walls] == vector::zero;

    const point x(0.0625, 0.0625, 0.05);
    const label celli = box.findCell(x);

    autoPtr<interpolation<vector>> hat(interpolation<vector>::New("linearHat", U));
    autoPtr<interpolation<vector>> cellPoint
    (
        interpolation<vector>::New("cellPoint", U)
    );
    const passiveParticle p(box, x);

    checkClose
    (
        "linearHat next to inflow and wall: interior 0.96",
        hat->interpolate(x, celli).y(), 0.96, tol
    );
    const scalar blended =
        cellPoint->interpolate(p.coordinates(), p.currentTetIndices()).y();
    Info<< "    cellPoint there: " << blended << endl;
    checkTrue
    (
        "cellPoint next to inflow and wall blends in the boundary values "
        "(" + Foam::name(blended) + " <= 0.8 x 0.96)",
        blended <= 0.8*0.96
    );
}


// The diffusion averaging's spreading and its bad coefficients
// (diffusionChecks.C)
void diffusionSpreading(const fvMesh& cube, const fvMesh& box);
void badCoefficients(const fvMesh& cube);

// (cornerNodesChecks.C)
void cornerNodesChecks(const fvMesh& cube, const fvMesh& box);


// * * * * * * * * * * * * * * * * * * Main * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    fvMesh cube
    (
        IOobject("periodic", runTime.timeName(), runTime, IOobject::MUST_READ)
    );

    linearHatWeights(cube, mesh);
    linearHatConservation(cube);
    uniformLattice(mesh, "linearHat");
    linearHatInterpolation(cube);
    boundaryInterpolation(mesh);
    diffusionSpreading(cube, mesh);
    badCoefficients(cube);
    cornerNodesChecks(cube, mesh);

    return summary();
}


// ************************************************************************* //
