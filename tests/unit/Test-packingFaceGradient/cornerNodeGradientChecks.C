/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Description
    Test-packingFaceGradient's checks of linearHatKernel::
    cornerNodeFaceGradient (impulse cornerNodeGradient) on the unit box
    (4 x 8 x 1 cells of 0.25 x 0.25 x 0.1, every patch non-coupled).

    1. Hand values, chi as in the face checks (cell 5 0.7, cell 6 0.65,
       cell 1 0.7, else 0; beyond a boundary 1 next to a cell with chi > 0,
       else 0). Per direction the place a in [-1, 1] between the cell's
       faces gives the transverse weights (1 - a)/4, 1/2, (1 + a)/4 (a step
       beyond a boundary stays in the cell) and the face weights
       (1 -+ a)/2; D = (across - value)/d along the outward normal.
       a) cell 5 at (0.3125 0.375 0.05): a = (-0.5, 0, 0).
          x: face weights 0.75 (west), 0.25 (east); rows 0, 1, 2 (cells 1,
             5, 9) weigh 1/4, 1/2, 1/4; z is one cell (weights sum to 1):
             cell 5: 0.75*0.7/0.25 + 0.25*(0.65 - 0.7)/0.25 = 2.05
             cell 1: 0.75*0.7/0.25 + 0.25*(0 - 0.7)/0.25    = 1.4
             cell 9: 0
             -> 0.5*2.05 + 0.25*1.4 = 1.375
          y: face weights 1/2, 1/2; columns 0, 1, 2 (cells 4, 5, 6) weigh
             0.375, 0.5, 0.125:
             cell 5: 0.5*(0.7 - 0.7)/0.25 + 0.5*(0 - 0.7)/0.25 = -1.4
             cell 4: 0;  cell 6: 0.5*0.65/0.25 - 0.5*0.65/0.25 = 0
             -> -0.7
          z: front and back alike, a = 0: 0
       b) cell 1 on the bottom wall at (0.375 0.0625 0.05): a = (0, -0.5, 0).
          x: face weights 1/2, 1/2; rows -1 (the wall: cell 1 again), 0, 1
             weigh 0.375, 0.5, 0.125:
             cell 1: 0.5*0.7/0.25 - 0.5*0.7/0.25 = 0
             cell 5: 0.5*0.7/0.25 + 0.5*(0.65 - 0.7)/0.25 = 1.3
             -> 0.125*1.3 = 0.1625
          y: face weights 0.75 (bottom), 0.25 (north); columns 0, 1, 2
             (cells 0, 1, 2) weigh 1/4, 1/2, 1/4:
             cell 1: 0.75*(1 - 0.7)/(2*0.125)*(-1) + 0 = -0.9
             cell 0: 0 (beyond 0, north 0)
             cell 2: 0.25*(0.65 - 0)/0.25 = 0.65
             -> 0.5*(-0.9) + 0.25*0.65 = -0.2875
    2. Against MFiX's node algorithm written out on the box's index grid,
       for chi = a smooth field plus a step, beyond values 1 where chi >
       0.5: per component, the difference on every face normal to it
       (beyond the boundary at twice the half width); a node takes the
       mean of the 4 faces around it (a face beyond a side boundary
       mirrored to the one inside); the point the trilinear interpolant of
       its cell's 8 nodes. 5 points in each of the 32 cells.
    3. A linear chi = 2x - 3y + 0.5, at mid-depth of cell (column 1, row 3),
       whose x and y faces and their transverse neighbours' are all
       internal: the exact gradient (2 -3 0).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "linearHatKernel.H"
#include "unitTest.H"

using namespace Foam::unitTest;

// (Test-packingFaceGradient.C)
void checkVector
(
    const string& what,
    const vector& value,
    const vector& expected
);

namespace
{

const label nx = 4, ny = 8;
const scalar hx = 0.25, hy = 0.25, hz = 0.1;

label cellOf(const label i, const label j)
{
    return i + nx*j;
}

// The gradient component along x (dir 0) or y (dir 1) on the face between
// columns (rows) f - 1 and f, f = 0..n, at the row (column) t; beyond a
// boundary the cell's beyond value at twice its half width
scalar faceDifference
(
    const scalarField& chi,
    const scalarField& beyond,
    const label dir,
    const label f,
    const label t
)
{
    const label n = dir == 0 ? nx : ny;
    const scalar h = dir == 0 ? hx : hy;
    auto at = [&](const label s)
    {
        return dir == 0 ? cellOf(s, t) : cellOf(t, s);
    };

    if (f == 0)
    {
        return (chi[at(0)] - beyond[at(0)])/h;
    }
    if (f == n)
    {
        return (beyond[at(n - 1)] - chi[at(n - 1)])/h;
    }
    return (chi[at(f)] - chi[at(f - 1)])/h;
}


// MFiX's node algorithm at x in cell (ci, cj)
vector nodeGradient
(
    const scalarField& chi,
    const scalarField& beyond,
    const point& x,
    const label ci,
    const label cj
)
{
    const scalar xi = x[0]/hx - ci;
    const scalar eta = x[1]/hy - cj;
    const scalar zeta = x[2]/hz;

    vector grad(Zero);

    // Along dir (x: 0, y: 1): nodes at the faces c, c + 1 of the cell's
    // index c along dir, each between the rows (columns) t - 1|t and
    // t|t + 1 across it (a row beyond the boundary mirrored)
    const FixedList<label, 2> cell({ci, cj});
    const FixedList<scalar, 2> local({xi, eta});
    const FixedList<label, 2> nAcross({ny, nx});
    for (label dir = 0; dir < 2; ++dir)
    {
        const label t = cell[1 - dir];
        for (label a = 0; a < 2; ++a)
        {
            for (label b = 0; b < 2; ++b)
            {
                const label r0 = t - 1 + b, r1 = t + b;
                const label m0 = r0 < 0 ? r1 : r0;
                const label m1 = r1 >= nAcross[dir] ? r0 : r1;
                const scalar node =
                    0.5
                   *(
                        faceDifference(chi, beyond, dir, cell[dir] + a, m0)
                      + faceDifference(chi, beyond, dir, cell[dir] + a, m1)
                    );
                // a: the node's side along dir, b: across it
                const scalar along = a ? local[dir] : 1 - local[dir];
                const scalar across = b ? local[1 - dir] : 1 - local[1 - dir];
                grad[dir] += along*across*node;
            }
        }
    }

    // z: one cell between the front and back walls; the nodes at the back
    // (z = 0) and front faces average the 2 x 2 columns and rows around
    // them, each face difference (v - beyond)/hz and (beyond - v)/hz
    for (label a = 0; a < 2; ++a)
    {
        for (label b = 0; b < 2; ++b)
        {
            scalar back = 0;
            for (label p = 0; p < 2; ++p)
            {
                for (label q = 0; q < 2; ++q)
                {
                    label c = ci - 1 + a + p, r = cj - 1 + b + q;
                    c = c < 0 ? 0 : (c >= nx ? nx - 1 : c);
                    r = r < 0 ? 0 : (r >= ny ? ny - 1 : r);
                    const label cell = cellOf(c, r);
                    back += 0.25*(chi[cell] - beyond[cell])/hz;
                }
            }
            // the front face's difference is the back's negated
            grad[2] +=
                (a ? xi : 1 - xi)*(b ? eta : 1 - eta)
               *((1 - zeta)*back - zeta*back);
        }
    }

    return grad;
}

} // End anonymous namespace


void cornerNodeGradientChecks(const fvMesh& mesh)
{
    const linearHatKernel& kernel = linearHatKernel::New(mesh);
    const List<scalar> noGhosts;

    // 1. Hand values
    {
        scalarField chi(mesh.nCells(), Zero);
        chi[5] = 0.7;
        chi[6] = 0.65;
        chi[1] = 0.7;
        scalarField beyond(pos(chi - 0.5));

        checkVector
        (
            "corner nodes: cell 5, a quarter in from the west face",
            kernel.cornerNodeFaceGradient
            (
                chi, noGhosts, beyond, noGhosts, point(0.3125, 0.375, 0.05), 5
            ),
            vector(1.375, -0.7, 0)
        );
        checkVector
        (
            "corner nodes: cell 1, a quarter up from the bottom wall",
            kernel.cornerNodeFaceGradient
            (
                chi, noGhosts, beyond, noGhosts, point(0.375, 0.0625, 0.05), 1
            ),
            vector(0.1625, -0.2875, 0)
        );
    }

    // 2. Against the node algorithm, a smooth field plus a step
    {
        scalarField chi(mesh.nCells());
        forAll(chi, celli)
        {
            const point& c = mesh.cellCentres()[celli];
            chi[celli] =
                0.3 + 0.2*Foam::sin(7*c.x()) + 0.1*c.y()*c.y()
              + (c.y() > 1.1 ? 0.35 : 0);
        }
        const scalarField beyond(pos(chi - 0.5));

        label nChecked = 0;
        scalar worst = 0;
        for (label cj = 0; cj < ny; ++cj)
        {
            for (label ci = 0; ci < nx; ++ci)
            {
                for (label k = 0; k < 5; ++k)
                {
                    const point x
                    (
                        hx*(ci + 0.1 + 0.19*k),
                        hy*(cj + 0.93 - 0.21*k),
                        hz*(0.05 + 0.22*k)
                    );
                    const vector g =
                        kernel.cornerNodeFaceGradient
                        (
                            chi, noGhosts, beyond, noGhosts, x, cellOf(ci, cj)
                        );
                    const vector expected = nodeGradient(chi, beyond, x, ci, cj);
                    worst =
                        max(worst, mag(g - expected)/max(mag(expected), 1e-3));
                    ++nChecked;
                }
            }
        }
        checkTrue("corner nodes: 160 points checked", nChecked == 160);
        checkClose
        (
            "corner nodes against the node algorithm, worst relative error",
            1 + worst, 1, 1e-12
        );
    }

    // 3. A linear field in the interior
    {
        scalarField chi(2*mesh.C().primitiveField().component(0));
        chi -= 3*mesh.C().primitiveField().component(1);
        chi += 0.5;
        const scalarField beyond(mesh.nCells(), Zero);

        // Cell (column 1|2, row 2..5): all 8 around it exist
        checkVector
        (
            "corner nodes: a linear field in cell (1, 3)",
            kernel.cornerNodeFaceGradient
            (
                chi, noGhosts, beyond, noGhosts, point(0.31, 0.93, 0.05),
                cellOf(1, 3)
            ),
            vector(2, -3, 0)
        );
    }
}


// ************************************************************************* //
