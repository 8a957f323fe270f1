/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Description
    Test-averagingMethods' checks of the diffusion averaging: its spreading
    (bandwidth b, pseudo-time T = b^2/4, variance b^2/2 per direction; with
    b = 0.2 m: 0.02 m^2) and its coefficients out of range.

\*---------------------------------------------------------------------------*/

#include "averagingTestHelpers.H"

using namespace Foam;
using namespace Foam::averagingTest;


void diffusionSpreading(const fvMesh& cube, const fvMesh& box)
{
    const point centre(0.45, 0.45, 0.45);
    const scalar b = 0.2;

    // The variance of the implicit steps is b^2/2 exactly on an unbounded
    // uniform mesh; measured here by nearest image on the periodic cube,
    // whose half width is 2.5 b. One step has exponential tails, so the
    // cube loses more of them: tolerance 10 % for one step, 5 % for three
    const List<Tuple2<label, scalar>> stepsAndTolerances({{1, 0.1}, {3, 0.05}});
    for (const Tuple2<label, scalar>& steps : stepsAndTolerances)
    {
        const label nSteps = steps.first();
        const dictionary diffusion
        (
            solutionDict
            (
                "averagingMethod diffusion; diffusionCoeffs { bandwidth 0.2; nSteps "
              + Foam::name(nSteps) + "; }"
            )
        );
        autoPtr<AveragingMethod<scalar>> average(newAverage<scalar>(cube, diffusion));
        deposit(average(), cube, centre, scalar(3));
        average->average();

        const string tag = "diffusion nSteps " + Foam::name(nSteps);
        checkClose(tag + ": total kept", totalAmount(average(), cube), 3, tol);
        const vector m2 = secondMoment(average(), cube, centre);
        for (direction i = 0; i < 3; ++i)
        {
            checkClose
            (
                tag + ": variance along " + Foam::name(i) + " = b^2/2",
                m2[i], b*b/2, steps.second()
            );
        }
        checkTrue
        (
            tag + ": the parcel's cell keeps less than half",
            amountIn(average(), cube, centre) < 1.5
        );

        // Assigned from a smoothed average and averaged again: not smoothed
        // a second time
        autoPtr<AveragingMethod<scalar>> copy(newAverage<scalar>(cube, diffusion));
        copy() = average();
        copy->average();
        checkClose
        (
            tag + ": assigned average not smoothed twice",
            amountIn(copy(), cube, centre), amountIn(average(), cube, centre), tol
        );
    }

    // Walls: nothing leaves; weighted average of equal velocities
    const dictionary wide
    (
        solutionDict("averagingMethod diffusion; diffusionCoeffs { bandwidth 0.5; }")
    );
    autoPtr<AveragingMethod<scalar>> mass(newAverage<scalar>(box, wide));
    autoPtr<AveragingMethod<vector>> momentum(newAverage<vector>(box, wide));
    autoPtr<AveragingMethod<vector>> velocity(newAverage<vector>(box, wide));
    const vector U(1, -2, 0.5);
    const List<Tuple2<point, scalar>> parcels
    ({
        {point(0.05, 0.1, 0.05), 1}, {point(0.9, 1.95, 0.02), 2}
    });
    for (const Tuple2<point, scalar>& parcel : parcels)
    {
        deposit(mass(), box, parcel.first(), parcel.second());
        deposit(momentum(), box, parcel.first(), parcel.second()*U);
        deposit(velocity(), box, parcel.first(), parcel.second()*U);
    }
    mass->average();
    momentum->average();
    velocity->average(mass());

    checkClose("diffusion at walls: total mass kept", totalAmount(mass(), box), 3, tol);
    const vector totalMomentum = totalAmount(momentum(), box);
    for (direction i = 0; i < 3; ++i)
    {
        checkClose
        (
            "diffusion at walls: total momentum kept, component " + Foam::name(i),
            totalMomentum[i], 3*U[i], tol
        );
    }
    checkTrue
    (
        "diffusion at walls: the mass spreads over the box (far corner > 0)",
        amountIn(mass(), box, point(0.875, 0.125, 0.05)) > 0
    );

    const label celli = cellAt(box, parcels[0].first());
    const vector Ucell = velocity->primitiveField()()[celli];
    for (direction i = 0; i < 3; ++i)
    {
        checkClose
        (
            "diffusion weighted average of equal velocities, component "
          + Foam::name(i), Ucell[i], U[i], tol
        );
    }
}


void badCoefficients(const fvMesh& cube)
{
    checkTrue
    (
        "diffusion bandwidth 0 rejected",
        rejects
        (
            cube, "averagingMethod diffusion; diffusionCoeffs { bandwidth 0; }",
            {"bandwidth", "(0, inf)"}
        )
    );
    checkTrue
    (
        "diffusion bandwidth -0.1 rejected",
        rejects
        (
            cube, "averagingMethod diffusion; diffusionCoeffs { bandwidth -0.1; }",
            {"bandwidth", "-0.1", "(0, inf)"}
        )
    );
    checkTrue
    (
        "diffusion nSteps 0 rejected",
        rejects
        (
            cube,
            "averagingMethod diffusion; diffusionCoeffs { bandwidth 0.1; nSteps 0; }",
            {"nSteps", "[1, inf)"}
        )
    );
    checkTrue
    (
        "diffusion without diffusionCoeffs rejected",
        rejects(cube, "averagingMethod diffusion;", {"diffusionCoeffs"})
    );
}


// ************************************************************************* //
