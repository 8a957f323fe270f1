/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Test-mfixSnider's check of capacityLimit refuse and push (push-through;
    hand values), in coloringFunction and in mfixSnider (pSolid 0: no
    stress impulse, so the capacity limit's moves alone; the same hand
    values); holdSupportedPacks false.
    Cells 0.25 x 0.25 x 0.1. Rows 1 and 2 of the box are full, and row 0
    but for column 0: 5 parcels of 0.12 of a cell in each cell (0.60; at
    close pack 0.62 a sixth does not fit: 0.12 > 0.02 + 0.5*0.12), at
    the column's centre x and y = 0.25 row + 0.05 + 0.04 k, k = 0..4; row 3
    is empty but for column 3. In the box's step (1 s) a sixth parcel
    rose into column 0, row 1 (at y 0.3, U = (0 1 0)) out of column 0,
    row 0, and another fell into column 3, row 2 (at y 0.7, U = (0 -1 0))
    out of column 3, row 3. Each origin cell holds, at rest, the first 4
    of its column's places (k = 0..3): with its entrant back, 5 parcels
    (0.60), full: room 0.62 - 0.60 = 0.02 and 0.12 > 0.02 + 0.06, so both
    entrants come out of full cells.
    - capacityLimit refuse: both are refused; their correction moves take
      them back out (|dX_y| > 0.05, their distance to the face), and no
      parcel of the full rows leaves its cell.
    - capacityLimit push: the nearest cells with room, through full cells
      and never into the cell the entrant came from (so the origin cells'
      parcels change no chain), are two steps away: for the rising parcel
      column 0, row 3 (every other cell within two steps is full, or
      column 0, row 0, its origin), so rows 1 and 2 of column 0 each push
      their highest parcel (y = 0.46, 0.71) just into the cell above: dX_y
      = (0.25 - 0.21) + 0.01*0.25 = 0.0425; for the falling one column 2,
      row 3 (column 3, row 3 is its origin), through column 2, row 2,
      whose highest parcel (x = 0.625, y = 0.71) is pushed up by the same
      0.0425. Both entrants are admitted (they stay in their rows).
    - capacityLimit push with the two highest
      parcels of column 2, row 2 level: the fourth at (0.6, 0.71 - 1e-12),
      the fifth at (0.65, 0.71), within 1e-9 of the 0.25 between the
      cells: the fourth, made first and so of the lower origId, is pushed
      (dX_y 0.0425 + 1e-12), the fifth stays in its row (it is not the
      one pushed for being higher by 1e-12).
    - capacityLimit push, the same entrants out of cells with room: the
      origin cells empty (with the entrant back 0.12), and with 3 parcels
      each (with the entrant back 0.48: room 0.14, and a fifth fits, 0.12
      <= 0.14 + 0.06): only an entrant out of a full cell is pushed on, so
      both are refused, their correction moves those of capacityLimit
      refuse (dX_y = +-((0.75 - 0.7) + 0.01*0.25) = +-0.0525), and the
      highest parcels of column 0, rows 1 and 2 and of column 2, row 2
      are not pushed (dX_y 0).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "sniderCloudChecks.H"
#include "PackingModel.H"
#include "unitTest.H"

using namespace Foam;
using namespace Foam::unitTest;

// * * * * * * * * * * * * * * * * Test groups * * * * * * * * * * * * * * //

void testPushThrough(cloudType& cloud, const fvMesh& mesh)
{
    const scalar Vp = constant::mathematical::pi*1e-6/6;
    const scalar Vcell = 0.25*0.25*0.1;
    const scalar n = 0.12*Vcell/Vp;
    const scalar dt = 1e-3;

    // The entrants' origin cells, column 0, row 0 and column 3, row 3
    const labelPairList origins({{0, 0}, {3, 3}});

    for (const word modelName : {"coloringFunction", "mfixSnider"})
    {
        // The refuse case's correction moves of the falling and the rising
        // entrant, which the entrants from cells with room repeat
        vector refusedFall(Zero);
        vector refusedRise(Zero);

        for (const label setUp : {0, 1, 2, 3, 4})
        {
            const bool push = setUp > 0;
            const bool level = setUp == 2;
            const bool roomy = setUp >= 3;
            const bool pushes = push && !roomy;
            cloud.clear();
            List<parcelType*> highest(2);
            List<parcelType*> besideFall(2, nullptr);
            for (label row = 0; row < 3; ++row)
            {
                for (label column = row ? 0 : 1; column < 4; ++column)
                {
                    for (label k = 0; k < 5; ++k)
                    {
                        point x
                        (
                            0.125 + 0.25*column, 0.25*row + 0.05 + 0.04*k, 0.05
                        );
                        if (level && row == 2 && column == 2 && k >= 3)
                        {
                            x = point
                            (
                                k == 3 ? 0.6 : 0.65, 0.71 - 1e-12*(4 - k), 0.05
                            );
                        }
                        parcelType* p = newParcel(mesh, x, Zero, n);
                        cloud.addParticle(p);
                        if (row && column == 0 && k == 4)
                        {
                            highest[row - 1] = p;
                        }
                        if (row == 2 && column == 2 && k >= 3)
                        {
                            // the one to be pushed first
                            besideFall[level ? k - 3 : 4 - k] = p;
                        }
                    }
                }
            }

            // The origin cells' own parcels: 4 (with the entrant back 0.60,
            // full), none, or 3 (with the entrant back 0.48: room for a
            // fifth)
            const label nOrigin = setUp == 3 ? 0 : setUp == 4 ? 3 : 4;
            for (const labelPair& cr : origins)
            {
                for (label k = 0; k < nOrigin; ++k)
                {
                    cloud.addParticle
                    (
                        newParcel
                        (
                            mesh,
                            point
                            (
                                0.125 + 0.25*cr.first(),
                                0.25*cr.second() + 0.05 + 0.04*k,
                                0.05
                            ),
                            Zero,
                            n
                        )
                    );
                }
            }

            parcelType* rising =
                newParcel(mesh, point(0.125, 0.3, 0.05), vector(0, 1, 0), n);
            parcelType* falling =
                newParcel(mesh, point(0.875, 0.7, 0.05), vector(0, -1, 0), n);
            cloud.addParticle(rising);
            cloud.addParticle(falling);

            dictionary coeffs;
            coeffs.add("closePackFraction", 0.62);
            coeffs.add("holdSupportedPacks", false);
            if (!level || push)
            {
                coeffs.add("capacityLimit", word(push ? "push" : "refuse"));
            }
            if (modelName == "mfixSnider")
            {
                coeffs.add("pSolid", 0.0);
            }
            autoPtr<PackingModel<cloudType>> model
            (
                newPackingModel(cloud, modelName, coeffs)
            );
            parcelType::trackingData td(cloud);
            td.updateAverages(cloud);
            model->cacheFields(true);

            const word tag = modelName + ", "
              + (
                    level ? "capacityLimit push, level parcels: "
                  : setUp == 3
                  ? "capacityLimit push, entrants from empty cells: "
                  : setUp == 4
                  ? "capacityLimit push, entrants from cells one parcel short"
                    " of full: "
                  : push ? "capacityLimit push: " : "capacityLimit refuse: "
                );
            const vector fall = dt*model->velocityCorrection(*falling, dt);
            const vector rise = dt*model->velocityCorrection(*rising, dt);
            if (pushes)
            {
                const scalar y = falling->position().y() + fall.y();
                checkTrue
                (
                    tag + "the falling parcel stays in row 2 (y + dX_y "
                  + Foam::name(y) + ")",
                    y > 0.5 && y < 0.75
                );
                parcelType& p = *besideFall[0];
                const vector move = dt*model->velocityCorrection(p, dt);
                checkClose
                (
                    tag + "column 2, row 2's parcel at y "
                  + Foam::name(p.position().y()) + " pushed up, dX_y",
                    move.y(), 0.0425 + (level ? 1e-12 : 0), 1e-9
                );
                parcelType& q = *besideFall[1];
                const scalar yq =
                    q.position().y() + dt*model->velocityCorrection(q, dt).y();
                checkTrue
                (
                    tag + "the other at y " + Foam::name(q.position().y())
                  + " stays in row 2 (y + dX_y " + Foam::name(yq) + ")",
                    yq < 0.75
                );

                const scalar yr = rising->position().y() + rise.y();
                checkTrue
                (
                    tag + "the rising parcel stays in row 1 (y + dX_y "
                  + Foam::name(yr) + ")",
                    yr > 0.25 && yr < 0.5
                );
            }
            else
            {
                checkTrue
                (
                    tag + "the falling parcel goes back up (dX_y "
                  + Foam::name(fall.y()) + " > 0.05)",
                    fall.y() > 0.05
                );
                checkTrue
                (
                    tag + "the rising parcel goes back down (dX_y "
                  + Foam::name(rise.y()) + " < -0.05)",
                    rise.y() < -0.05
                );
            }
            if (!push)
            {
                refusedFall = fall;
                refusedRise = rise;
            }
            if (roomy)
            {
                checkClose
                (
                    tag + "the falling parcel's move as refused, dX_y",
                    fall.y(), refusedFall.y(), 1e-12
                );
                checkClose
                (
                    tag + "the rising parcel's move as refused, dX_y",
                    rise.y(), refusedRise.y(), 1e-12
                );
                parcelType& p = *besideFall[0];
                checkClose
                (
                    tag + "column 2, row 2's parcel at y "
                  + Foam::name(p.position().y()) + " not pushed, dX_y",
                    dt*model->velocityCorrection(p, dt).y(), 0, 1e-12, 1
                );
            }

            for (label row = 1; row < 3; ++row)
            {
                parcelType& p = *highest[row - 1];
                const vector move = dt*model->velocityCorrection(p, dt);
                const word which = "row " + Foam::name(row) + "'s parcel at y "
                  + Foam::name(p.position().y());
                if (pushes)
                {
                    checkClose
                    (
                        tag + which + " pushed up, dX_y", move.y(), 0.0425,
                        1e-9
                    );
                    checkClose(tag + which + ", dX_x", move.x(), 0, 1e-12, 1);
                }
                else if (roomy)
                {
                    checkClose
                    (
                        tag + which + " not pushed, dX_y", move.y(), 0,
                        1e-12, 1
                    );
                }
                else
                {
                    checkTrue
                    (
                        tag + which + " stays in its row",
                        p.position().y() + move.y() < 0.25*(row + 1)
                    );
                }
            }
            model->cacheFields(false);
        }
    }
    cloud.clear();
}


// ************************************************************************* //
