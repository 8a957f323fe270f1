/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Description
    Test-averagingMethods' checks of the cornerNodes averaging against
    MFiX-PIC's node deposition done the way MFiX does it, written out here
    on the uniform meshes of the test: a parcel at local coordinates
    (xi, eta, zeta) in its cell gives each of the cell's 8 corners the
    trilinear weight (1 - xi or xi)(1 - eta or eta)(1 - zeta or zeta); each
    corner shares what it holds equally among the cells around it that
    exist (8 inside, 4 on a wall, 2 on an edge, 1 in a corner; a cyclic
    wraps round), i.e. in proportion to their volumes as MFiX does.
    Also: hand values at a cell centre, depositAt cellCentre (a parcel
    anywhere in a cell deposits as one at its centre; a word other than
    parcel or cellCentre is a FatalIOError), conservation, a uniform
    lattice next to walls, and the interpolation of a linear field.

\*---------------------------------------------------------------------------*/

#include "averagingTestHelpers.H"
#include "Map.H"

using namespace Foam;
using namespace Foam::averagingTest;

// (Test-averagingMethods.C)
void uniformLattice(const fvMesh& box, const word& method);

namespace
{

// A uniform mesh from the origin: cells of size h, n per direction,
// cyclic or not per direction
struct uniformMesh
{
    vector h;
    FixedList<label, 3> n;
    FixedList<bool, 3> cyclic;
};


// The cells and their shares of a unit deposit at x, by the node algorithm
cellWeights nodeDeposit(const uniformMesh& m, const point& x)
{
    FixedList<label, 3> cell;
    FixedList<scalar, 3> xi;
    for (label d = 0; d < 3; ++d)
    {
        cell[d] = min(label(x[d]/m.h[d]), m.n[d] - 1);
        xi[d] = x[d]/m.h[d] - cell[d];
    }

    Map<scalar> share;
    auto key = [&](const FixedList<label, 3>& c)
    {
        return c[0] + m.n[0]*(c[1] + m.n[1]*c[2]);
    };

    for (label corner = 0; corner < 8; ++corner)
    {
        // The corner node (index of the cell above it) and its weight
        FixedList<label, 3> node;
        scalar weight = 1;
        for (label d = 0; d < 3; ++d)
        {
            const bool upper = corner & (1 << d);
            node[d] = cell[d] + (upper ? 1 : 0);
            weight *= upper ? xi[d] : 1 - xi[d];
        }

        // The cells around the node: below and above it per direction
        List<FixedList<label, 3>> around;
        for (label around3 = 0; around3 < 8; ++around3)
        {
            FixedList<label, 3> c;
            bool exists = true;
            for (label d = 0; d < 3; ++d)
            {
                c[d] = node[d] - ((around3 & (1 << d)) ? 0 : 1);
                if (m.cyclic[d])
                {
                    c[d] = (c[d] + m.n[d]) % m.n[d];
                }
                else if (c[d] < 0 || c[d] >= m.n[d])
                {
                    exists = false;
                }
            }
            if (exists)
            {
                around.append(c);
            }
        }
        for (const FixedList<label, 3>& c : around)
        {
            share(key(c)) += weight/around.size();
        }
    }

    cellWeights expected;
    forAllConstIters(share, iter)
    {
        const label k = iter.key();
        const FixedList<label, 3> c
        ({k % m.n[0], (k/m.n[0]) % m.n[1], k/(m.n[0]*m.n[1])});
        point centre;
        for (label d = 0; d < 3; ++d)
        {
            centre[d] = (c[d] + 0.5)*m.h[d];
        }
        expected.append(Tuple2<point, scalar>(centre, iter.val()));
    }
    return expected;
}

} // End anonymous namespace


void cornerNodesChecks(const fvMesh& cube, const fvMesh& box)
{
    const dictionary cornerNodes(solutionDict("averagingMethod cornerNodes;"));
    const uniformMesh cubeMesh{vector(0.1, 0.1, 0.1), {10, 10, 10}, {true, true, true}};
    const uniformMesh boxMesh{vector(0.25, 0.25, 0.1), {4, 8, 1}, {false, false, false}};

    // At a cell centre, by hand: 1/2 kept and 1/4 to each side along each
    // direction, so 1/8 in the cell, 1/16 across a face, 1/32 across an
    // edge, 1/64 across a corner (27 cells, sum 1)
    checkWeights
    (
        "cornerNodes at a cell centre", cube, cornerNodes, point(0.45, 0.45, 0.45),
        {
            {point(0.45, 0.45, 0.45), 0.125},
            {point(0.55, 0.45, 0.45), 0.0625},
            {point(0.45, 0.35, 0.45), 0.0625},
            {point(0.55, 0.35, 0.45), 0.03125},
            {point(0.35, 0.55, 0.55), 0.015625}
        }
    );

    const List<Tuple2<point, const uniformMesh*>> points
    ({
        {point(0.47, 0.42, 0.53), &cubeMesh},   // off-centre, inside
        {point(0.02, 0.98, 0.45), &cubeMesh},   // across two cyclics
        {point(0.05, 1.1, 0.05), &boxMesh},     // next to a wall
        {point(0.02, 0.03, 0.01), &boxMesh},    // in a wall corner
        {point(0.9, 1.93, 0.07), &boxMesh}      // under the top patch
    });
    for (const Tuple2<point, const uniformMesh*>& p : points)
    {
        const fvMesh& mesh = p.second() == &cubeMesh ? cube : box;
        checkWeights
        (
            "cornerNodes against the node algorithm at " + Foam::name(p.first()),
            mesh, cornerNodes, p.first(), nodeDeposit(*p.second(), p.first())
        );
    }

    // depositAt cellCentre: a parcel anywhere in the cell at (0.45, 0.45,
    // 0.55) deposits as the one at its centre
    const dictionary atCentres
    (
        solutionDict
        (
            "averagingMethod cornerNodes; cornerNodesCoeffs { depositAt cellCentre; }"
        )
    );
    checkWeights
    (
        "cornerNodes depositAt cellCentre, parcel at (0.47 0.42 0.53)", cube,
        atCentres, point(0.47, 0.42, 0.53),
        {
            {point(0.45, 0.45, 0.55), 0.125},
            {point(0.55, 0.45, 0.55), 0.0625},
            {point(0.45, 0.45, 0.45), 0.0625},
            {point(0.35, 0.35, 0.65), 0.015625}
        }
    );
    checkTrue
    (
        "cornerNodes depositAt middle: FatalIOError naming the keyword and the names",
        rejects
        (
            cube, "averagingMethod cornerNodes; cornerNodesCoeffs { depositAt middle; }",
            {"depositAt", "middle", "parcel", "cellCentre"}
        )
    );

    // Conservation of 200 random parcels on the periodic cube
    {
        autoPtr<AveragingMethod<scalar>> average(newAverage<scalar>(cube, cornerNodes));
        Random rng(4321);
        for (label i = 0; i < 200; ++i)
        {
            deposit(average(), cube, rng.sample01<vector>(), scalar(0.7));
        }
        average->average();
        checkClose
        (
            "cornerNodes: 200 random parcels, total", totalAmount(average(), cube),
            140, tol
        );
    }

    // 2 x 2 parcels per cell, next to the walls too (Test-averagingMethods.C)
    uniformLattice(box, "cornerNodes");

    // A linear field is read back exactly inside: the weights of the steps
    // -1 and +1 differ by a/2, a = 2 (x - x_c)/h
    {
        autoPtr<AveragingMethod<scalar>> average(newAverage<scalar>(cube, cornerNodes));
        const volVectorField& C = cube.C();
        average()[0] =
            2 + 3*C.component(0)().primitiveField()
          - C.component(1)().primitiveField() + 0.5*C.component(2)().primitiveField();
        for (const point& x : {point(0.47, 0.42, 0.53), point(0.31, 0.77, 0.12)})
        {
            const passiveParticle p(cube, x);
            checkClose
            (
                "cornerNodes interpolate of 2 + 3x - y + z/2 at " + Foam::name(x),
                average->interpolate(p.coordinates(), p.currentTetIndices()),
                2 + 3*x.x() - x.y() + 0.5*x.z(), tol
            );
        }
    }
}


// ************************************************************************* //
