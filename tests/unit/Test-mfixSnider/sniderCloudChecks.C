/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    See sniderCloudChecks.H.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "sniderCloudChecks.H"
#include "mfixCollisionDamping.H"
#include "unitTest.H"
#include "sniderCoeffs.H"

using namespace Foam;
using namespace Foam::unitTest;

namespace
{
    const scalar piValue = constant::mathematical::pi;
}

// * * * * * * * * * * * * * * * * Test groups * * * * * * * * * * * * * * //

parcelType* newParcel
(
    const fvMesh& mesh,
    const point& position,
    const vector& U,
    const scalar nParticle
)
{
    parcelType* p = new parcelType(mesh, position, mesh.findCell(position));
    p->d() = 0.01;
    p->rho() = 2500;
    p->U() = U;
    p->nParticle() = nParticle;
    return p;
}


void addRows
(
    cloudType& cloud,
    const fvMesh& mesh,
    const vector& U1,
    const label firstColumn
)
{
    const scalar Vp = piValue*1e-6/6;
    const scalar Vcell = 0.25*0.25*0.1;
    for (label i = firstColumn; i < 4; ++i)
    {
        const scalar x = 0.125 + 0.25*i;
        cloud.addParticle
        (
            newParcel(mesh, point(x, 0.125, 0.05), Zero, 0.62*Vcell/Vp)
        );
        cloud.addParticle
        (
            newParcel(mesh, point(x, 0.375, 0.05), U1, 0.3*Vcell/Vp)
        );
    }
}


autoPtr<PackingModel<cloudType>> newPackingModel
(
    cloudType& cloud,
    const word& type,
    const dictionary& coeffs
)
{
    dictionary subModels;
    subModels.add("packingModel", type);
    subModels.add(word(type + "Coeffs"), coeffs);
    return PackingModel<cloudType>::New(subModels, cloud);
}


autoPtr<PackingModel<cloudType>> newSniderModel
(
    cloudType& cloud,
    const dictionary& coeffs
)
{
    return newPackingModel(cloud, "mfixSnider", coeffs);
}


void testDamping(cloudType& cloud, const fvMesh& mesh)
{
    cloud.clear();
    const point centre(0.625, 1.125, 0.05);
    cloud.addParticle(newParcel(mesh, centre, vector(1, 0, 0), 1));
    cloud.addParticle(newParcel(mesh, centre, vector(3, 0, 0), 1));
    const label celli = mesh.findCell(centre);

    mfixCollisionDamping damping(0.85, 0.6);
    damping.update(cloud, scalarField(mesh.nCells(), 0.3));

    const scalar r = 0.005;
    const scalar oneByTau =
        16/Foam::sqrt(scalar(3*piValue))*0.3*1/(r/3)*2*(1 - sqr(0.85))/4;
    checkClose("damping 1/tau_x", damping.oneByTau()[celli].x(), oneByTau, 1e-12);
    checkClose("damping 1/tau_y (no spread)", damping.oneByTau()[celli].y(), 0, 1e-12, 1);
    checkClose("damping: cell mean", damping.meanVelocity()[celli].x(), 2, 1e-12);

    const scalar dt = 1e-3;
    const scalar ratio = 0.5*dt*oneByTau;
    checkClose
    (
        "damped U_x", damping.damped(vector(1, 0, 0), celli, dt).x(),
        (1 + ratio*2)/(1 + ratio), 1e-12
    );
    checkClose
    (
        "a cell with one parcel is not damped",
        damping.oneByTau()[0].x(), 0, 1e-12, 1
    );
}


void testConserveMomentum(cloudType& cloud, const fvMesh& mesh)
{
    cloud.clear();
    const scalar Vp = piValue*1e-6/6;
    const scalar Vcell = 0.25*0.25*0.1;
    const scalar n0 = 0.62*Vcell/Vp;
    const scalar n1 = 0.3*Vcell/Vp;
    const scalar dt = 1e-3;

    parcelType* rowOne =
        newParcel(mesh, point(0.125, 0.45, 0.05), vector(0, -2, 0), n1);
    parcelType* packed =
        newParcel(mesh, point(0.125, 0.125, 0.05), Zero, n0);
    cloud.addParticle(rowOne);
    cloud.addParticle(packed);
    addRows(cloud, mesh, Zero, 1);

    dictionary coeffs;
    coeffs.add("closePackFraction", 0.6);
    coeffs.add("capacityLimit", word("none"));
    coeffs.add("conserveMomentum", word("packs"));
    autoPtr<PackingModel<cloudType>> model(newSniderModel(cloud, coeffs));
    mesh.lookupObjectRef<volVectorField>("kinematicCloud:UMean") ==
        dimensionedVector(dimVelocity, Zero);

    parcelType::trackingData td(cloud);
    td.updateAverages(cloud);
    model->cacheFields(true);

    // The row-1 parcel, moving down at rest's slip: the impulse 4.8e-5 m/s
    // up, given by row 0 (the stress gradient points down, at cell 0)
    const vector dU = model->velocityCorrection(*rowOne, dt);
    const scalar dUy = dt*36/(2500*0.3);
    checkClose("conserveMomentum: impulse as without it", dU.y(), dUy, 1e-9);
    rowOne->U() += dU;

    const scalar m = n1*rowOne->mass();
    const scalar M = n0*rowOne->mass();
    const scalar f = M/(M + m);
    model->cacheFields(false);
    checkClose
    (
        "conserveMomentum: the parcel keeps f dU, f = M/(M + m)",
        rowOne->U().y(), -2 + f*dUy, 1e-12
    );
    checkClose
    (
        "conserveMomentum: cell 0's parcel takes -f m dU/M",
        packed->U().y(), -f*m*dUy/M, 1e-9
    );
    checkClose
    (
        "conserveMomentum: momentum of the two unchanged",
        m*rowOne->U().y() + M*packed->U().y(), -2*m, 1e-12
    );
}


void testGivenAtStepEnd(cloudType& cloud, const fvMesh& mesh)
{
    cloud.clear();
    const scalar Vp = piValue*1e-6/6;
    const scalar Vcell = 0.25*0.25*0.1;
    const scalar n0 = 0.62*Vcell/Vp;
    const scalar dt = 1e-3;

    // Item 2's bed with capacityLimit refuse and conserveMomentum packs
    parcelType* entering =
        newParcel(mesh, point(0.125, 0.2, 0.05), vector(0, -1, 0), 1);
    cloud.addParticle(entering);
    addRows(cloud, mesh, vector(0, -1, 0));

    dictionary coeffs(sniderCoeffs());
    coeffs.add("slipVelocityFactor", 1);
    coeffs.add("capacityLimit", word("refuse"));
    coeffs.add("conserveMomentum", word("packs"));
    autoPtr<PackingModel<cloudType>> model(newSniderModel(cloud, coeffs));

    volVectorField& Us =
        mesh.lookupObjectRef<volVectorField>("kinematicCloud:UMean");
    Us == dimensionedVector(dimVelocity, Zero);
    for (label i = 0; i < 4; ++i)
    {
        Us[4 + i] = vector(0, -1, 0);
    }

    parcelType::trackingData td(cloud);
    td.updateAverages(cloud);
    model->cacheFields(true);

    const vector move = model->velocityCorrection(*entering, dt);
    checkTrue
    (
        "conserveMomentum: the refused entrant's move as without it "
        "(0.05 <= dX_y <= 0.175; dX_y " + Foam::name(dt*move.y()) + ")",
        dt*move.y() >= 0.05 && dt*move.y() <= 0.175
    );
    checkClose
    (
        "conserveMomentum: velocityCorrection leaves the velocity alone",
        entering->U().y(), -1, 1e-12
    );

    // End of the step, written once: kept 0.85 less the share the pack
    // (cell 0, M = n0 m) takes of the impulse 1.85 given to the parcel
    // (mass m): 0.85 - 1.85 m/(M + m)
    model->cacheFields(false);
    checkClose
    (
        "conserveMomentum: at the step's end kept with its share, "
        "0.85 - 1.85/(n0 + 1)",
        entering->U().y(), 0.85 - 1.85/(n0 + 1), 1e-12
    );
}


void testBadInput(cloudType& cloud)
{
    cloud.clear();
    for (const word modelName : {"coloringFunction", "mfixSnider"})
    {
        const word coeffsName(modelName + "Coeffs");
        const auto rejects = [&]
        (
            const word& keyword,
            const word& value,
            const wordList& named
        )
        {
            dictionary coeffs;
            coeffs.add("closePackFraction", 0.6);
            coeffs.add(keyword, value);
            checkTrue
            (
                modelName + ", " + keyword + " " + value + ": FatalIOError",
                raisesError
                (
                    [&]() { newPackingModel(cloud, modelName, coeffs); },
                    named
                )
            );
        };

        for (const word value : {"true", "false"})
        {
            rejects
            (
                "capacityLimit", value,
                {coeffsName, "capacityLimit", value, "push", "refuse", "none"}
            );
        }
        rejects
        (
            "conserveMomentum", "true",
            {coeffsName, "conserveMomentum", "true", "none", "packs", "gas"}
        );
        if (modelName == "mfixSnider")
        {
            rejects
            (
                "conserveMomentum", "gas",
                {coeffsName, "conserveMomentum", "gas", "none", "packs"}
            );
        }
        for
        (
            const word keyword
          : {
                "pushThrough", "followDrainingPacks", "supportAngle",
                "packAtClosePack", "freePackReactionsToGas"
            }
        )
        {
            rejects(keyword, "true", {coeffsName, "unknown", keyword});
        }
    }
}

// ************************************************************************* //
