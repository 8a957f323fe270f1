/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Test-mfixSnider's check of coloringFunction's randomVelocity (MFiX-PIC's
    SIG_U): one parcel alone in the box (solids fraction far below close
    pack, so the rules leave its velocity as it is), U = (1 -2 3),
    impulse faceGradient, no capacity limit. The correction is then the
    random velocity alone, dU_i = s N(0,1) U_i:
      s = 0:    dU = 0 exactly;
      s = 0.05: over 20 000 calls, dU_i/(s U_i) has mean 0 (within 0.05,
                about 7 standard errors of 1/sqrt(20000)) and standard
                deviation 1 (within 3 %: the standard error of a sample
                standard deviation is 1/sqrt(2 n) = 0.5 %).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "sniderCloudChecks.H"
#include "PackingModel.H"
#include "unitTest.H"

using namespace Foam;
using namespace Foam::unitTest;

// * * * * * * * * * * * * * * * * Test groups * * * * * * * * * * * * * * //

void testRandomVelocity(cloudType& cloud, const fvMesh& mesh)
{
    cloud.clear();
    const vector U(1, -2, 3);
    parcelType* p = newParcel(mesh, point(0.625, 1.125, 0.05), U, 1);
    cloud.addParticle(p);

    const scalar dt = 1e-3;
    const label n = 20000;
    for (const scalar s : {0.0, 0.05})
    {
        dictionary coeffs;
        coeffs.add("closePackFraction", 0.6);
        coeffs.add("impulse", "faceGradient");
        coeffs.add("capacityLimit", false);
        coeffs.add("randomVelocity", s);
        autoPtr<PackingModel<cloudType>> model
        (
            newPackingModel(cloud, "coloringFunction", coeffs)
        );
        parcelType::trackingData td(cloud);
        td.updateAverages(cloud);
        model->cacheFields(true);

        vector sum(Zero), sumSqr(Zero);
        for (label i = 0; i < n; ++i)
        {
            p->U() = U;
            const vector dU = model->velocityCorrection(*p, dt);
            const vector r = s > 0 ? vector(cmptDivide(dU, s*U)) : dU;
            sum += r;
            sumSqr += cmptSqr(r);
        }
        const vector mean = sum/n;
        const vector var = sumSqr/n - cmptSqr(mean);

        const word tag = "randomVelocity " + Foam::name(s) + ": ";
        if (s == 0)
        {
            checkClose(tag + "no correction", mag(sumSqr), 0, 1e-12, 1);
            continue;
        }
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            const word c(vector::componentNames[d]);
            checkClose(tag + "mean of dU_" + c + "/(s U_" + c + ")", mean[d], 0, 0.05, 1);
            checkClose
            (
                tag + "standard deviation of dU_" + c + "/(s U_" + c + ")",
                Foam::sqrt(var[d]), 1, 0.03
            );
        }
    }
    cloud.clear();
}


// ************************************************************************* //
