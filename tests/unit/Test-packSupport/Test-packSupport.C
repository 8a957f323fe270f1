/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Application
    Test-packSupport

Description
    PackSupport (the full cells of a packed bed that rest on a support) on
    the unit box: 4 x 8 x 1 cells of 0.25 x 0.25 x 0.1, patches bottom
    (wall), top (patch), walls (wall: the sides, front and back). Cell
    (column i, row j) has label i + 4*j.

    Full cells, g = (0 -9.81 0) (support: the wall patches, the default):
      column 0: rows 0-3 and 5-6 full     -> held rows 0-3 (row 4 breaks
                                             the chain; 5-6 rest on it)
      column 1: rows 1-7 full, row 0 not  -> none held
      column 2: all rows full             -> all 8 held
      column 3: none full                 -> none
      12 held cells in all.
    Same full cells, g = (0 9.81 0) (the bed hangs from the top):
      default support (walls only; top is a patch) -> none held;
      supportPatches (top)                        -> column 1 rows 1-7
      and column 2 all rows: 15 held cells.
    g = (-9.81 -9.81 0)/sqrt(2): the lower faces are the bottom (x
    normal . gHat = 0.707 > 0.1) and the x-min face of each cell, with
    equal weights (areas 0.025 each, both 0.707): a cell is held when one
    of the two rests on support (at least half of the weight). The walls
    are then 45 degrees from the horizontal, steeper than the 40 degrees
    a support face may be (cos 0.766 > 0.707): with every cell full none
    is held.
    g = 0 -> none held.
    restingVelocity, g down: U = (1 -2 0.5) -> (1 0 0.5);
      U = (1 2 0) unchanged.
    heldVelocity(U0 before the rules, U after them), g down:
      falling U0 (0 -2 0), U (0.5 1.7 0) (bounced) -> (0.5 0 0);
      rising U0 (0 1 0), U (0.2 0.5 0) -> unchanged;
      rising U0 (0 1 0), U (0 -0.3 0) -> (0 0 0).
    Bad input: supportPatches (nowhere) -> FatalIOError naming the
    keyword, the value and the patches allowed.

    The capacity limit's room (cellRoom::fits, v <= room + 0.5 v), by
    hand, for parcels of 0.12 of a unit cell and close pack 0.62:
      4 parcels (room 0.14): a fifth fits (0.12 <= 0.20);
      5 parcels (room 0.02): a sixth does not (0.08); 6 (room -0.10): a
        seventh does not;
    parcels of 0.2 and close pack 0.6, 3 parcels summed (room 0.6 - 3*0.2,
    zero to round-off): a fourth does not fit.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "PackSupport.H"
#include "cellRoom.H"
#include "unitTest.H"

using namespace Foam::unitTest;

label countHeld(const PackSupport& support, const label nCells)
{
    label n = 0;
    for (label celli = 0; celli < nCells; ++celli)
    {
        n += support.held(celli);
    }
    return n;
}


bool heldRows
(
    const PackSupport& support,
    const label column,
    const labelList& rows
)
{
    bool ok = true;
    for (label row = 0; row < 8; ++row)
    {
        ok = ok && support.held(column + 4*row) == rows.found(row);
    }
    return ok;
}


int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const label nCells = mesh.nCells();
    checkTrue("box has 32 cells", nCells == 32);

    boolList full(nCells, false);
    for (label row = 0; row < 8; ++row)
    {
        full[0 + 4*row] = row != 4 && row != 7;
        full[1 + 4*row] = row != 0;
        full[2 + 4*row] = true;
    }

    const dictionary noKeywords;
    PackSupport support(mesh, noKeywords);

    support.update(vector(0, -9.81, 0), full);
    checkTrue("g down: column 0 held rows 0-3", heldRows(support, 0, {0, 1, 2, 3}));
    checkTrue("g down: column 1 none held", heldRows(support, 1, labelList()));
    checkTrue
    (
        "g down: column 2 all held",
        heldRows(support, 2, {0, 1, 2, 3, 4, 5, 6, 7})
    );
    checkTrue("g down: 12 held", countHeld(support, nCells) == 12);
    checkTrue("g down: nHeld 12", support.nHeld() == 12);

    support.update(vector(0, 9.81, 0), full);
    checkTrue("g up, walls only: none held", countHeld(support, nCells) == 0);

    dictionary topSupport;
    topSupport.add("supportPatches", wordRes({wordRe("top")}));
    PackSupport hanging(mesh, topSupport);
    hanging.update(vector(0, 9.81, 0), full);
    checkTrue
    (
        "g up, top: column 1 rows 1-7",
        heldRows(hanging, 1, {1, 2, 3, 4, 5, 6, 7})
    );
    checkTrue("g up, top: 15 held", countHeld(hanging, nCells) == 15);

    // Gravity 45 degrees from the walls: steeper than the 40 degrees a
    // support face may be, so the walls do not hold
    const vector gSlant(-9.81/Foam::sqrt(2.0), -9.81/Foam::sqrt(2.0), 0);
    support.update(gSlant, boolList(nCells, true));
    checkTrue
    (
        "g slanted 45 (support faces up to 40): walls too steep, none held",
        countHeld(support, nCells) == 0
    );

    support.update(Zero, full);
    checkTrue("g zero: none held", countHeld(support, nCells) == 0);

    support.update(vector(0, -9.81, 0), full);
    const vector falling = support.restingVelocity(vector(1, -2, 0.5));
    checkTrue
    (
        "restingVelocity (1 -2 0.5) -> (1 0 0.5)",
        mag(falling - vector(1, 0, 0.5)) < 1e-15
    );
    const vector rising = support.restingVelocity(vector(1, 2, 0));
    checkTrue
    (
        "restingVelocity (1 2 0) unchanged",
        mag(rising - vector(1, 2, 0)) < 1e-15
    );

    const vector stopped =
        support.heldVelocity(vector(0, -2, 0), vector(0.5, 1.7, 0));
    checkTrue
    (
        "heldVelocity falling (0 -2 0), rules (0.5 1.7 0) -> (0.5 0 0)",
        mag(stopped - vector(0.5, 0, 0)) < 1e-15
    );
    const vector rose =
        support.heldVelocity(vector(0, 1, 0), vector(0.2, 0.5, 0));
    checkTrue
    (
        "heldVelocity rising (0 1 0), rules (0.2 0.5 0) unchanged",
        mag(rose - vector(0.2, 0.5, 0)) < 1e-15
    );
    const vector turned =
        support.heldVelocity(vector(0, 1, 0), vector(0, -0.3, 0));
    checkTrue
    (
        "heldVelocity rising (0 1 0), rules (0 -0.3 0) -> (0 0 0)",
        mag(turned) < 1e-15
    );

    dictionary nowhere;
    nowhere.name() = "coloringFunctionCoeffs";
    nowhere.add("supportPatches", wordRes({wordRe("nowhere")}));
    checkTrue
    (
        "supportPatches (nowhere): FatalIOError",
        raisesError
        (
            [&]() { PackSupport bad(mesh, nowhere); },
            {"supportPatches", "nowhere", "bottom", "top", "walls"}
        )
    );

    // The capacity limit's room
    {
        const scalar v = 0.12;
        const scalar cp = 0.62;
        checkTrue("cellRoom: parcel 5 fits", cellRoom::fits(v, cp - 4*v));
        for (const label n : {5, 6})
        {
            checkTrue
            (
                "cellRoom: parcel " + Foam::name(n + 1) + " does not fit",
                !cellRoom::fits(v, cp - n*v)
            );
        }
        const scalar w = 0.2;
        const scalar room = 0.6 - (w + w + w);
        checkTrue
        (
            "cellRoom: a fourth of 0.2 at close pack 0.6 does not fit"
            " (room " + Foam::name(room) + ")",
            !cellRoom::fits(w, room)
        );
    }

    return summary();
}


// ************************************************************************* //
