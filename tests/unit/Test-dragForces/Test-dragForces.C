/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Application
    Test-dragForces

Description
    The drag laws of libmppicModels as the cloud uses them: each is
    selected by name through OpenFOAM's ParticleForce table, for a real
    basicKinematicMPPICCloud on the box of tests/unit/cases/box, and asked
    for Sp [kg/s] of one parcel at rest (F = Sp*(u_g - u_p)) in a uniform
    gas, against handDragValues.H at the points (alpha_g, w [m/s]) dilute
    (0.995, 0.5), intermediate (0.7, 2), dense (0.45, 5), the other
    Hill-Koch-Ladd branches (0.995, 0.02), (0.7, 0.3), and StokesDrag's
    eq 7 slip; Sp = V_p*beta/(alpha_s*alpha_g) for the voidage laws.

    Also: Gidaspow's blend is continuous at the switch, feedback false
    moves the drag to the explicit (non-coupled) part, slipFrom cellMean
    takes the slip from the mass-weighted mean velocity of the cell's
    parcels (two parcels of weights 1 and 3 at +1 and -1 m/s: mean -0.5
    m/s, so the drag Su + Sp*(u_g - u_p) on a third parcel at rest is
    Sp*(w + 0.5) with Sp of Gidaspow at the slip w + 0.5; in a cell
    without parcels, its own velocity), and the coefficients out of range
    raise FatalIOError naming the keyword and the range.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "basicKinematicMPPICCloud.H"
#include "particleForceTest.H"
#include "uniformAirFields.H"

using namespace Foam;
using namespace Foam::unitTest;

#include "handDragValues.H"

using namespace Foam::handDragValues;


// * * * * * * * * * * * * * * * * * * Main * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "readGravitationalAcceleration.H"

    uniformAirFields air(mesh, rhog, mug);
    volScalarField& alpha = air.alpha;
    volVectorField& U = air.U;

    basicKinematicMPPICCloud cloud("kinematicCloud", air.rho, U, air.mu, g);

    const point centre(0.5, 1.0, 0.05);
    parcelType p(mesh, centre, mesh.findCell(centre));
    p.d() = d;
    p.rho() = rhop;
    p.U() = Zero;
    p.nParticle() = 1;

    auto setGas = [&](const scalar ag, const scalar w)
    {
        alpha.primitiveFieldRef() = ag;
        U.primitiveFieldRef() = vector(0, w, 0);
    };

    typedef scalar (*handLaw)(const scalar, const scalar);
    auto compare = [&]
    (
        const word& model,
        const string& text,
        handLaw hand,
        const List<Pair<scalar>>& points
    )
    {
        autoPtr<ParticleForce<cloudType>> force(select(cloud, mesh, model, text));
        for (const Pair<scalar>& pt : points)
        {
            setGas(pt.first(), pt.second());
            vector Su;
            const Pair<scalar> Sp = coefficients(force(), cloud, p, Su);
            checkClose
            (
                model + " Sp at (ag, w) = (" + Foam::name(pt.first()) + ", "
              + Foam::name(pt.second()) + ")",
                Sp.first(),
                hand(pt.first(), pt.second())
            );
        }
    };

    const List<Pair<scalar>> threePoints
    ({
        Pair<scalar>(0.995, 0.5), Pair<scalar>(0.7, 2), Pair<scalar>(0.45, 5)
    });

    compare
    (
        "GidaspowDrag", "alphac alpha.air;",
        [](const scalar ag, const scalar w) { return handGidaspow(ag, w, false); },
        threePoints
    );
    compare
    (
        "GidaspowDrag", "alphac alpha.air; blend true;",
        [](const scalar ag, const scalar w) { return handGidaspow(ag, w, true); },
        threePoints
    );
    compare
    (
        "HillKochLaddDrag", "alphac alpha.air;", handHillKochLadd,
        List<Pair<scalar>>
        ({
            Pair<scalar>(0.995, 0.5), Pair<scalar>(0.7, 2),
            Pair<scalar>(0.45, 5), Pair<scalar>(0.995, 0.02),
            Pair<scalar>(0.7, 0.3)
        })
    );
    compare("BVKDrag", "alphac alpha.air;", handBVK, threePoints);
    compare
    (
        "SyamlalOBrienDrag", "alphac alpha.air;", handSyamlalOBrien,
        threePoints
    );
    compare("StokesDrag", "alphac alpha.air;", handStokes, threePoints);
    compare
    (
        "StokesDrag", "alphac alpha.air; voidageExponent 0;",
        [](const scalar ag, const scalar w)
        {
            return 3*piValue*mug*d/ag;
        },
        threePoints
    );

    // Eq 7 of the settling-shock case: at u_r = g*drho*d^2/(18*mu)*ag^3.65
    // the drag balances the buoyant weight V_p*(rho_p - rho_g)*g
    {
        autoPtr<ParticleForce<cloudType>> force
        (
            select(cloud, mesh, "StokesDrag", "alphac alpha.air;")
        );
        const scalar ag = 0.85;
        const scalar ur =
            9.81*(rhop - rhog)*d*d/(18*mug)*std::pow(ag, 3.65);
        setGas(ag, ur);
        vector Su;
        const scalar Sp = coefficients(force(), cloud, p, Su).first();
        checkClose
        (
            "StokesDrag at eq 7's slip balances the buoyant weight",
            Sp*ur,
            Vp*(rhop - rhog)*9.81
        );
    }

    compare
    (
        "constantCdDrag", "Cd 1;",
        [](const scalar ag, const scalar w) { return handConstantCd(1, w); },
        threePoints
    );
    compare
    (
        "linearRelaxationDrag", "C 100;",
        [](const scalar ag, const scalar w) { return 100*rhop*Vp; },
        threePoints
    );

    // Gidaspow blend: continuous across the switch
    {
        autoPtr<ParticleForce<cloudType>> force
        (
            select(cloud, mesh, "GidaspowDrag", "alphac alpha.air; blend true;")
        );
        vector Su;
        setGas(0.8 - 1e-9, 1);
        const scalar below = coefficients(force(), cloud, p, Su).first();
        setGas(0.8 + 1e-9, 1);
        const scalar above = coefficients(force(), cloud, p, Su).first();
        checkTrue
        (
            "GidaspowDrag blend continuous at the switch (relative jump "
          + Foam::name(mag(above - below)/below) + " < 1e-6)",
            mag(above - below) < 1e-6*below
        );
    }

    // feedback false: the drag leaves Sp and becomes the explicit Su
    {
        autoPtr<ParticleForce<cloudType>> force
        (
            select
            (
                cloud, mesh, "HillKochLaddDrag",
                "alphac alpha.air; feedback false;"
            )
        );
        setGas(0.7, 2);
        vector Su;
        const Pair<scalar> Sp = coefficients(force(), cloud, p, Su);
        checkClose("feedback false: coupled Sp", Sp.first(), 0, 0, 1);
        checkClose
        (
            "feedback false: explicit Su_y = Sp*w",
            Su.y(),
            handHillKochLadd(0.7, 2)*2
        );
        checkClose("feedback false: Su_x", Su.x(), 0, 0, 1);
    }

    // slipFrom cellMean: the slip from the mean velocity of the cell's
    // parcels at the step's start (cacheFields(true))
    {
        const label celli = mesh.findCell(centre);
        const point elsewhere(0.5, 0.2, 0.05);
        const label otherCelli = mesh.findCell(elsewhere);
        checkTrue("slipFrom test: two different cells", otherCelli != celli);

        const List<Pair<scalar>> weightAndUy
        ({
            Pair<scalar>(1, 1), Pair<scalar>(3, -1)
        });
        for (const Pair<scalar>& wu : weightAndUy)
        {
            parcelType* q = new parcelType(mesh, centre, celli);
            q->d() = d;
            q->rho() = rhop;
            q->nParticle() = wu.first();
            q->U() = vector(0, wu.second(), 0);
            cloud.addParticle(q);
        }
        const scalar meanUy = (1*1 + 3*(-1))/4.0;

        autoPtr<ParticleForce<cloudType>> force
        (
            select
            (
                cloud, mesh, "GidaspowDrag",
                "alphac alpha.air; slipFrom cellMean;"
            )
        );
        force->cacheFields(true);

        const scalar ag = 0.45, w = 2;
        setGas(ag, w);
        vector Su;
        const scalar Sp = coefficients(force(), cloud, p, Su).first();
        const scalar slip = w - meanUy;
        checkClose
        (
            "slipFrom cellMean: Sp at the cell mean's slip",
            Sp,
            handGidaspow(ag, slip, false)
        );
        checkClose
        (
            "slipFrom cellMean: drag Su + Sp*(u_g - u_p) = Sp*(u_g - u_s)",
            Su.y() + Sp*w,
            handGidaspow(ag, slip, false)*slip
        );
        checkClose("slipFrom cellMean: Su_x", Su.x(), 0, 0, 1);

        parcelType lone(mesh, elsewhere, otherCelli);
        lone.d() = d;
        lone.rho() = rhop;
        lone.nParticle() = 1;
        lone.U() = vector(0, 0.5, 0);
        const scalar SpLone = coefficients(force(), cloud, lone, Su).first();
        checkClose
        (
            "slipFrom cellMean, empty cell: Sp at the parcel's own slip",
            SpLone,
            handGidaspow(ag, w - 0.5, false)
        );
        checkClose
        (
            "slipFrom cellMean, empty cell: no explicit part",
            mag(Su), 0, 0, 1
        );

        cloud.clear();
    }

    // Bad coefficients
    checkTrue
    (
        "GidaspowDrag slipFrom average rejected",
        rejects
        (
            cloud, mesh, "GidaspowDrag",
            "alphac alpha.air; slipFrom average;",
            {"slipFrom", "average", "cellMean"}
        )
    );
    checkTrue
    (
        "SyamlalOBrienDrag c1 0 rejected",
        rejects
        (
            cloud, mesh, "SyamlalOBrienDrag", "alphac alpha.air; c1 0;",
            {"c1", "(0, inf)"}
        )
    );
    checkTrue
    (
        "SyamlalOBrienDrag d1 -2 rejected",
        rejects
        (
            cloud, mesh, "SyamlalOBrienDrag", "alphac alpha.air; d1 -2;",
            {"d1", "-2", "(0, inf)"}
        )
    );
    checkTrue
    (
        "StokesDrag voidageExponent -1 rejected",
        rejects
        (
            cloud, mesh, "StokesDrag", "alphac alpha.air; voidageExponent -1;",
            {"voidageExponent", "-1", "[0, inf)"}
        )
    );
    checkTrue
    (
        "BVKDrag without a gas-fraction field rejected",
        rejects(cloud, mesh, "BVKDrag", "alphac alpha.gas;", {"alphac"})
    );

    return summary();
}


// ************************************************************************* //
