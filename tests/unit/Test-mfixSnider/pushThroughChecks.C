/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Test-mfixSnider's check of coloringFunction's pushThrough (hand values).
    The box's bottom row (cells 0.25 x 0.25 x 0.1): columns 0-2 hold 5
    parcels of 0.12 of a cell each (0.60, full at close pack 0.62: a sixth
    does not fit, 0.12 > 0.02 + 0.5*0.12), column 3 is empty. A sixth
    parcel falls into column 0 from the row above (U = (0 -1 0), the box's
    step 1 s carries it across the face).
    - pushThrough false: column 0 refuses it; its correction move takes it
      back up out of the cell (dX_y > 0.05, its distance to the face), and
      no parcel of the row moves out of its cell.
    - pushThrough true: the nearest cell with room beside or ahead of the
      fall is column 3, through columns 1 and 2 (the cell above is behind
      the fall). Each of columns 0, 1 and 2 pushes the parcel that lies
      furthest toward the next column (x = 0.21, 0.46, 0.71) just into it:
      dX = (0.25 - 0.21) + 0.01*0.25 = 0.0425 along x, to x = 0.2525,
      0.5025, 0.7525; the falling parcel is admitted and its correction
      stays in column 0 (0 < y + dX_y < 0.25).

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

    for (const bool push : {false, true})
    {
        cloud.clear();
        List<parcelType*> ends(3);
        for (label column = 0; column < 3; ++column)
        {
            for (label k = 0; k < 5; ++k)
            {
                const scalar x = 0.25*column + 0.05 + 0.04*k;
                parcelType* p =
                    newParcel(mesh, point(x, 0.125, 0.05), Zero, n);
                cloud.addParticle(p);
                if (k == 4)
                {
                    ends[column] = p;
                }
            }
        }
        parcelType* falling =
            newParcel(mesh, point(0.125, 0.2, 0.05), vector(0, -1, 0), n);
        cloud.addParticle(falling);

        dictionary subModels;
        subModels.add("packingModel", "coloringFunction");
        dictionary coeffs;
        coeffs.add("closePackFraction", 0.62);
        coeffs.add("holdSupportedPacks", false);
        coeffs.add("pushThrough", push);
        subModels.add("coloringFunctionCoeffs", coeffs);
        autoPtr<PackingModel<cloudType>> model
        (
            PackingModel<cloudType>::New(subModels, cloud)
        );
        parcelType::trackingData td(cloud);
        td.updateAverages(cloud);
        model->cacheFields(true);

        const word tag = push ? "pushThrough true: " : "pushThrough false: ";
        const vector fallMove = dt*model->velocityCorrection(*falling, dt);
        if (!push)
        {
            checkTrue
            (
                tag + "the falling parcel goes back up (dX_y "
              + Foam::name(fallMove.y()) + " > 0.05)",
                fallMove.y() > 0.05
            );
        }
        else
        {
            const scalar y = falling->position().y() + fallMove.y();
            checkTrue
            (
                tag + "the falling parcel stays in column 0 (y + dX_y "
              + Foam::name(y) + ")",
                y > 0 && y < 0.25 && mag(fallMove.x()) < 0.25
            );
        }

        for (label column = 0; column < 3; ++column)
        {
            const vector move = dt*model->velocityCorrection(*ends[column], dt);
            const word which = "column " + Foam::name(column) + "'s parcel at x "
              + Foam::name(ends[column]->position().x());
            if (push)
            {
                checkClose(tag + which + " pushed on, dX_x", move.x(), 0.0425, 1e-9);
                checkClose(tag + which + ", dX_y", move.y(), 0, 1e-12, 1);
            }
            else
            {
                checkTrue
                (
                    tag + which + " stays in its column",
                    ends[column]->position().x() + move.x() < 0.25*(column + 1)
                );
            }
        }
        model->cacheFields(false);
    }
    cloud.clear();
}


// ************************************************************************* //
