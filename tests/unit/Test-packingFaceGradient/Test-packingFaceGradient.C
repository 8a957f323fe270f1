/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Application
    Test-packingFaceGradient

Description
    packingFaceGradient::at (the coloring function's gradient from the
    faces of a cell, as MFiX-PIC forms it) on the unit box: 4 x 8 x 1 cells
    of 0.25 x 0.25 x 0.1 (cell (column i, row j) has label i + 4*j),
    patches bottom (wall), top, walls (sides, front and back). With h the
    half width across a face and d the centre distance across it (0.25 in
    x and y; 2h = 0.1 across the front and back), each face adds
        w (across - value)/d n,  w = 1 - (distance to the face)/(2h).

    chi: cell 5 (column 1, row 1) 0.7, cell 6 (column 2, row 1) 0.65,
    cell 1 (column 1, row 0) 0.7, every other cell 0.
    1. Cell 5, x = (0.3125 0.375 0.05), a quarter in from its west face;
       boundary value 1:
         west (cell 4, 0):     w 0.75, 0.75*(0 - 0.7)/0.25*(-1) =  2.1
         east (cell 6, 0.65):  w 0.25, 0.25*(0.65 - 0.7)/0.25    = -0.05
         south (cell 1, 0.7):  w 0.5,  0                         =  0
         north (cell 9, 0):    w 0.5,  0.5*(0 - 0.7)/0.25        = -1.4
         front, back (walls):  w 0.5 each, +-0.5*(1 - 0.7)/0.1, cancel
       -> (2.05 -1.4 0)
    2. Cell 1 on the bottom wall, x = (0.375 0.0625 0.05), boundary value 1
       (the cell is close packed):
         bottom (wall, 1):     w 0.75, 0.75*(1 - 0.7)/0.25*(-1)  = -0.9
         north (cell 5, 0.7):  w 0.25, 0
         west (cell 0, 0), east (cell 2, 0): w 0.5 each, cancel
       -> (0 -0.9 0)
    3. Cell 0 (0) at its centre (0.125 0.125 0.05), boundary value 0:
         east (cell 1, 0.7):   w 0.5,  0.5*0.7/0.25              =  1.4
         north (cell 4, 0):    0; walls (0): 0
       -> (1.4 0 0)

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "packingFaceGradient.H"
#include "unitTest.H"

using namespace Foam::unitTest;

// (cornerNodeGradientChecks.C)
void cornerNodeGradientChecks(const fvMesh& mesh);

void checkVector(const string& what, const vector& value, const vector& expected)
{
    for (direction k = 0; k < vector::nComponents; ++k)
    {
        checkClose
        (
            what + " [" + Foam::name(label(k)) + "]", value[k], expected[k],
            1e-12, 1
        );
    }
}


int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    checkTrue("box has 32 cells", mesh.nCells() == 32);

    scalarField chi(mesh.nCells(), Zero);
    chi[5] = 0.7;
    chi[6] = 0.65;
    chi[1] = 0.7;
    const PtrList<scalarField> noCoupled(mesh.boundaryMesh().size());

    checkVector
    (
        "cell 5, a quarter in from the west face",
        packingFaceGradient::at
        (
            mesh, 5, point(0.3125, 0.375, 0.05), chi, noCoupled, 1
        ),
        vector(2.05, -1.4, 0)
    );
    checkVector
    (
        "cell 1, a quarter up from the bottom wall",
        packingFaceGradient::at
        (
            mesh, 1, point(0.375, 0.0625, 0.05), chi, noCoupled, 1
        ),
        vector(0, -0.9, 0)
    );
    checkVector
    (
        "cell 0 at its centre, beside a packed cell",
        packingFaceGradient::at
        (
            mesh, 0, point(0.125, 0.125, 0.05), chi, noCoupled, 0
        ),
        vector(1.4, 0, 0)
    );

    cornerNodeGradientChecks(mesh);

    return summary();
}


// ************************************************************************* //
