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
    is empty. In the box's step (1 s) a sixth parcel rose into column 0,
    row 1, from column 0, row 0 (U = (0 1 0)), and another fell into
    column 3, row 2, from row 3 (U = (0 -1 0)).
    - capacityLimit refuse: both are refused; their correction moves take
      them back out (|dX_y| > 0.05, their distance to the face), and no
      parcel of the full rows leaves its cell.
    - capacityLimit push: the nearest cells with room, through full cells
      and not back where the parcel came from, are two steps away: for the
      rising parcel column 0, row 3 (every other cell within two steps is
      full), so rows 1 and 2 of column 0 each push their highest parcel
      (y = 0.46, 0.71) just into the cell above: dX_y = (0.25 - 0.21) +
      0.01*0.25 = 0.0425; for the falling one column 2, row 3, through
      column 2, row 2, whose highest parcel (x = 0.625, y = 0.71) is
      pushed up by the same 0.0425. Both entrants are admitted (they stay
      in their rows).
    - capacityLimit not given (push, the default) with the two highest
      parcels of column 2, row 2 level: the fourth at (0.6, 0.71 - 1e-12),
      the fifth at (0.65, 0.71), within 1e-9 of the 0.25 between the
      cells: the fourth, made first and so of the lower origId, is pushed
      (dX_y 0.0425 + 1e-12), the fifth stays in its row (it is not the
      one pushed for being higher by 1e-12).

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
    for (const word modelName : {"coloringFunction", "mfixSnider"})
    {
        for (const label setUp : {0, 1, 2})
        {
            const bool push = setUp > 0;
            const bool level = setUp == 2;
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
            parcelType* rising =
                newParcel(mesh, point(0.125, 0.3, 0.05), vector(0, 1, 0), n);
            parcelType* falling =
                newParcel(mesh, point(0.875, 0.7, 0.05), vector(0, -1, 0), n);
            cloud.addParticle(rising);
            cloud.addParticle(falling);

            dictionary coeffs;
            coeffs.add("closePackFraction", 0.62);
            coeffs.add("holdSupportedPacks", false);
            if (!level)
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
                    level ? "capacityLimit (default push), level parcels: "
                  : push ? "capacityLimit push: " : "capacityLimit refuse: "
                );
            const vector fall = dt*model->velocityCorrection(*falling, dt);
            if (push)
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
            }
            else
            {
                checkTrue
                (
                    tag + "the falling parcel goes back up (dX_y "
                  + Foam::name(fall.y()) + " > 0.05)",
                    fall.y() > 0.05
                );
            }
            const vector rise = dt*model->velocityCorrection(*rising, dt);
            if (push)
            {
                const scalar y = rising->position().y() + rise.y();
                checkTrue
                (
                    tag + "the rising parcel stays in row 1 (y + dX_y "
                  + Foam::name(y) + ")",
                    y > 0.25 && y < 0.5
                );
            }
            else
            {
                checkTrue
                (
                    tag + "the rising parcel goes back down (dX_y "
                  + Foam::name(rise.y()) + " < -0.05)",
                    rise.y() < -0.05
                );
            }

            for (label row = 1; row < 3; ++row)
            {
                parcelType& p = *highest[row - 1];
                const vector move = dt*model->velocityCorrection(p, dt);
                const word which = "row " + Foam::name(row) + "'s parcel at y "
                  + Foam::name(p.position().y());
                if (push)
                {
                    checkClose
                    (
                        tag + which + " pushed up, dX_y", move.y(), 0.0425,
                        1e-9
                    );
                    checkClose(tag + which + ", dX_x", move.x(), 0, 1e-12, 1);
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
