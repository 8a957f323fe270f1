/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Application
    Test-mfixSnider

Description
    mfixSnider's rules as MFiX-PIC applies them, on the unit box (4 x 8 x 1
    cells of 0.25 x 0.25 x 0.1 m; cell (column i, row j) has label
    i + 4*j and centre (0.125 + 0.25 i, 0.125 + 0.25 j, 0.05); walls all
    round, a plain patch at the top). Hand values:

    1. Stress gradient (linearHatKernel::extrapolatedGradient), cell values
       v = 3 + 2x - 5y: exactly (2, -5, 0) everywhere, in the half cells
       next to the walls and the top patch too (ghosts 2 v_c - v_opp);
       v = y^2: between the centres y = 0.125 and 0.375, and below 0.125
       (ghost), d/dy = (0.375^2 - 0.125^2)/0.25 = 0.5.

    2. The limiter with the previous step's mean solids velocity. Basic
       (cell) averaging, close pack 0.6, Ps 100, gamma 3, eps 1e-7, e1 0.85,
       dt 1e-3, rho_p 2500, d 0.01 (V_p = pi 1e-6/6):
       row 0 packed at rest (one parcel per cell at the centre, alpha 0.62,
       mean velocity 0), row 1 at alpha 0.3 falling at 1 m/s (mean velocity
       (0 -1 0)), rows 2-7 empty:
         tau(0.62) = 100*0.62^3/(1e-7*0.38) = 6.27179e8 Pa,
         tau(0.30) = 100*0.3^3/0.3 = 9 Pa.
       A parcel of the falling block that has just entered the packed cell,
       at (0.125, 0.2, 0.05), U = (0 -1 0): grad_y = (9 - tau0)/0.25, the
       impulse is far beyond the reflection, so U'_y = U_y + (1 + e1)*(0 -
       U_y) = 0.85: turned in one step. With the mean of this step's own
       velocities (-1, what OpenFOAM's uAverage holds), the slip is 0 and
       nothing happens.
       A parcel of row 1 at (0.125, 0.45, 0.05), U = (0 -2 0): grad_y =
       (0 - 9)/0.25 = -36 Pa/m (row 2 empty), dU_y = 1e-3*36/(2500*0.3) =
       4.8e-5 m/s, below the reflection (1.85 m/s): U'_y = -2 + 4.8e-5.
       Our capacity limit, capacityLimit refuse: with the case's step of
       1 s the entering parcel crossed cell 0's top face in this step (its
       displacement 1 m exceeds its 0.05 m from the face), and cell 0
       started above close pack (0.62 > 0.6), so it takes no entrant: the
       correction move takes the parcel back across y = 0.25 into cell 4
       and not past cell 4's centre (0.05 <= dX_y <= 0.175), and it keeps
       U'_y = 0.85 (away from cell 0). With capacityLimit none (MFiX 21.3
       as is) the correction is U' - U = 1.85 and the parcel's velocity is
       not touched; the same-step-mean check uses that model.
       The stress at the cap: tau(0.9) = tau(min(0.995, 0.69)) =
       100*0.69^3/(1e-7*0.31) = 1.05971e9 Pa.

    3. The mean solids velocity stored for the next step (cacheFields
       false): mass-weighted linear-hat deposit to the centres. Cell 0 holds
       its resting parcel (mass m0, at the centre) and 0.7 of the entering
       parcel (t = 0.3 toward row 1), now at U_y = 0.85:
         Us_y(cell 0) = 0.7 m_f 0.85/(m0 + 0.7 m_f),
         Us_y(cell 4) = (-m1 + 0.3 m_f 0.85)/(m1 + 0.3 m_f).

    4. Collision damping (MFiX 21 form): two parcels of r = 0.005 in a cell
       of capped alpha 0.3, U_x = 1 and 3: mean 2, sigma_x = sqrt(1)/(2-1)
       = 1, r32 = r/3, g0 = 0.6/0.3 = 2,
         1/tau_x = 16/sqrt(3 pi) 0.3 * 1/(r/3) * 2 * (1 - 0.85^2)/4,
       U_x = 1 after dt 1e-3: (1 + r*2)/(1 + r), r = dt/(2 tau_x).

    5. conserveMomentum packs (ours), capacityLimit none: rows 0 and 1 as
       in 2, at rest but for the row-1 parcel at (0.125, 0.45, 0.05)
       falling at 2 m/s, mean velocities 0: its impulse dU_y = 4.8e-5 m/s
       comes from row 0 (the gradient points down, at cell 0). At the end
       of the step the pack takes it back as in a collision: the parcel
       (mass m) keeps f dU, f = M/(M + m), cell 0's parcel (mass M) takes
       -f m dU/M, and their momentum is -2 m as before.

    6. Release of an over-packed cell (releaseAbove 0.65, close pack 0.6):
       in a cell at alpha 0.68, r = 0.005, dt 1e-3, grad tau = (3 -4 0):
       the velocity of a move of l = 3.7*0.005/(3 sqrt(2)*0.68) down the
       gradient, l/dt*(-0.6, 0.8, 0); none at 0.65 or without the keyword.

    7. The boundary rule: a parcel at (0.01, 0.1, 0.05) in cell 0 (side
       wall x = 0, bottom y = 0), U = (-2 -1 0.5), keeps no component into
       a boundary whose plane its displacement d reaches: d = (-0.02 0.05
       0) -> (0 -1 0.5); (-0.005 -0.2 0) -> (-2 0 0.5); (-0.02 -0.2 0) ->
       (0 0 0.5); (-0.005 -0.05 0), no plane reached -> U. A velocity away
       from the wall it reaches, (2 0 0), is kept; in cell 5 (no boundary
       face) U is kept.

    8. conserveMomentum packs with capacityLimit refuse: item 2's refused
       entrant (one particle) moves as without conserveMomentum, but its
       velocity is written once, at the end of the step (cacheFields
       false), not by velocityCorrection (-1 until then): the kept 0.85
       less the share cell 0's pack (n0 particles, at rest) takes of the
       impulse 1.85 the parcel was given, f = n0/(n0 + 1):
       0.85 - (1 - f) 1.85 = 0.85 - 1.85/(n0 + 1),
       n0 = 0.62*0.00625/(pi 1e-6/6) = 7400.6.

    9. capacityLimit refuse and push (push-through), in coloringFunction
       and mfixSnider: pushThroughChecks.C.

    10. Bad input, in coloringFunction and mfixSnider, each a
       FatalIOError: capacityLimit true or false -> naming the keyword, the
       value and push, refuse, none; conserveMomentum true -> naming the
       keyword, the value and none, packs, gas; conserveMomentum gas in
       mfixSnider -> naming the keyword, gas and none, packs; pushThrough,
       followDrainingPacks, supportAngle, packAtClosePack and
       freePackReactionsToGas -> an unknown keyword, named.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "basicKinematicMPPICCloud.H"
#include "linearHatKernel.H"
#include "sniderStressRules.H"
#include "unitTest.H"
#include "uniformAirFields.H"
#include "sniderCoeffs.H"
#include "sniderRuleChecks.H"
#include "sniderCloudChecks.H"

using namespace Foam;
using namespace Foam::unitTest;


const scalar piValue = constant::mathematical::pi;

// * * * * * * * * * * * * * * * * Test groups * * * * * * * * * * * * * * //

void testGradient(const fvMesh& mesh)
{
    const linearHatKernel& kernel = linearHatKernel::New(mesh);
    const vectorField& C = mesh.C();

    scalarField linear(mesh.nCells());
    scalarField quadratic(mesh.nCells());
    const scalarList noGhosts;   // a serial run: the kernel has no ghosts
    forAll(C, celli)
    {
        linear[celli] = 3 + 2*C[celli].x() - 5*C[celli].y();
        quadratic[celli] = sqr(C[celli].y());
    }

    const List<Tuple2<point, word>> points
    ({
        {point(0.4, 0.9, 0.05), "interior"},
        {point(0.05, 1.1, 0.05), "next to the side wall"},
        {point(0.02, 0.03, 0.01), "in a wall corner"},
        {point(0.6, 1.97, 0.08), "next to the top patch"}
    });
    for (const Tuple2<point, word>& pt : points)
    {
        const vector g =
            kernel.extrapolatedGradient
            (
                linear, noGhosts, pt.first(), mesh.findCell(pt.first())
            );
        const string what("linear field, " + pt.second() + ": ");
        checkClose(what + "d/dx", g.x(), 2, 1e-12);
        checkClose(what + "d/dy", g.y(), -5, 1e-12);
        checkClose(what + "d/dz", g.z(), 0, 1e-12, 1);
    }

    const scalar bracket = (sqr(0.375) - sqr(0.125))/0.25;
    for (const scalar y : {0.3, 0.2, 0.05})
    {
        const point pt(0.3, y, 0.05);
        const vector g =
            kernel.extrapolatedGradient
            (
                quadratic, noGhosts, pt, mesh.findCell(pt)
            );
        checkClose
        (
            "y^2 at y = " + Foam::name(y) + ": bracketing centres",
            g.y(), bracket, 1e-12
        );
    }
}


void testLimiterAndMean(cloudType& cloud, const fvMesh& mesh)
{
    const scalar Vp = piValue*1e-6/6;
    const scalar Vcell = 0.25*0.25*0.1;
    const scalar n0 = 0.62*Vcell/Vp;
    const scalar n1 = 0.3*Vcell/Vp;
    const scalar nf = 1;
    const scalar dt = 1e-3;

    // Row 0 at rest, row 1 falling; the entering parcel and the row-1
    // parcel under test are the first two
    parcelType* entering =
        newParcel(mesh, point(0.125, 0.2, 0.05), vector(0, -1, 0), nf);
    parcelType* rowOne =
        newParcel(mesh, point(0.125, 0.45, 0.05), vector(0, -2, 0), 0);
    cloud.addParticle(entering);
    cloud.addParticle(rowOne);
    addRows(cloud, mesh, vector(0, -1, 0));

    dictionary coeffs(sniderCoeffs());
    coeffs.add("slipVelocityFactor", 1);
    coeffs.add("capacityLimit", word("refuse"));
    autoPtr<PackingModel<cloudType>> model(newSniderModel(cloud, coeffs));

    // The previous step's mean: row 0 at rest, row 1 falling
    volVectorField& Us =
        mesh.lookupObjectRef<volVectorField>("kinematicCloud:UMean");
    checkClose("UMean starts at zero (no file)", mag(Us[0]), 0, 1e-12, 1);
    for (label i = 0; i < 4; ++i)
    {
        Us[4 + i] = vector(0, -1, 0);
    }

    parcelType::trackingData td(cloud);
    td.updateAverages(cloud);
    model->cacheFields(true);

    const scalar m0 = n0*entering->mass();
    const scalar m1 = n1*entering->mass();
    const scalar mf = nf*entering->mass();
    Info<< "cell 0 solids fraction (basic): "
        << (n0 + nf)*Vp/Vcell << endl;

    const vector dEntering = model->velocityCorrection(*entering, dt);
    checkClose
    (
        "entering parcel turned in one step: U'_y", 
        entering->U().y() + dEntering.y(), 0.85, 1e-12
    );
    checkClose("entering parcel: no x change", dEntering.x(), 0, 1e-12, 1);

    // Our capacity limit (refuse): the parcel crossed into cell 0
    // through its top face within the case's step (1 s), and cell 0
    // started above close pack (0.62), so it takes no entrant: the
    // correction move takes the parcel back into cell 4, the cell it came
    // from, and it keeps the turned velocity, which leaves cell 0
    const label backCell =
        mesh.findCell(entering->position() + dt*dEntering);
    checkTrue
    (
        "refused entrant: the correction move ends in cell 4 (ends in "
      + Foam::name(backCell) + ")",
        backCell == 4
    );
    checkTrue
    (
        "refused entrant: the move crosses the face at y 0.25 and stops "
        "short of cell 4's centre (0.05 <= dX_y <= 0.175; dX_y "
      + Foam::name(dt*dEntering.y()) + ")",
        dt*dEntering.y() >= 0.05 && dt*dEntering.y() <= 0.175
    );

    // MFiX 21.3 as is (capacityLimit none): the correction is U' - U and
    // the parcel's velocity is not touched
    dictionary asIs(coeffs);
    asIs.set("capacityLimit", word("none"));
    autoPtr<PackingModel<cloudType>> mfix(newSniderModel(cloud, asIs));
    mfix->cacheFields(true);
    entering->U() = vector(0, -1, 0);
    const vector dAsIs = mfix->velocityCorrection(*entering, dt);
    checkClose("capacityLimit none: dU_y = 0.85 + 1", dAsIs.y(), 1.85, 1e-12);
    checkClose
    (
        "capacityLimit none: the velocity is not touched",
        entering->U().y(), -1, 1e-12
    );

    // The mean of this step's own velocities leaves the block alone
    Us[0] = vector(0, -1, 0);
    const vector dSameStep = mfix->velocityCorrection(*entering, dt);
    checkClose
    (
        "with this step's mean (-1): no correction", dSameStep.y(), 0,
        1e-12, 1
    );
    Us[0] = Zero;

    // End of the step: the stored mean from the final velocities
    entering->U() = vector(0, 0.85, 0);
    model->cacheFields(false);
    checkClose
    (
        "stored mean, cell 0",
        Us[0].y(), 0.7*mf*0.85/(m0 + 0.7*mf), 1e-10
    );
    checkClose
    (
        "stored mean, cell 4",
        Us[4].y(), (-m1 + 0.3*mf*0.85)/(m1 + 0.3*mf), 1e-10
    );
    checkClose("stored mean, empty cell 12", mag(Us[12]), 0, 1e-12, 1);

    dictionary rules(coeffs);
    checkClose
    (
        "stress at the cap, tau(0.9)", sniderStressRules(rules, 0.6).tau(0.9),
        100*pow3(0.69)/(1e-7*0.31), 1e-12
    );
    checkClose
    (
        "stress below close pack, tau(0.3)",
        sniderStressRules(rules, 0.6).tau(0.3), 9, 1e-12
    );
}


// * * * * * * * * * * * * * * * * * * Main  * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "readGravitationalAcceleration.H"

    uniformAirFields air(mesh, 1.2, 1.8e-5);

    basicKinematicMPPICCloud cloud("kinematicCloud", air.rho, air.U, air.mu, g);

    testGradient(mesh);
    testLimiterAndMean(cloud, mesh);
    testRelease();
    testVelocityIntoBoundary(mesh);
    testDamping(cloud, mesh);
    testConserveMomentum(cloud, mesh);
    testGivenAtStepEnd(cloud, mesh);
    testPushThrough(cloud, mesh);
    testBadInput(cloud);

    return summary();
}


// ************************************************************************* //
