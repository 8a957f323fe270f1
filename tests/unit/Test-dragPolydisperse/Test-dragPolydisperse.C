/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Application
    Test-dragPolydisperse

Description
    The voidage laws with polydisperseCorrection Beetstra, selected by
    name for a real basicKinematicMPPICCloud on the box of
    tests/unit/cases/box, in a uniform gas: ag = 0.6, slip w = 0.5 m/s
    (parcels at rest), rho_g = 1.2, mu_g = 1.8e-5, rho_p = 2500.

    Three cells, the sums taken by cacheFields(true):
    - one size: parcels of d = 1 mm with nParticle 3 and 5: Sp is the
      law's own (factor 1 to round-off);
    - two sizes: 1 mm with nParticle 8, 2 mm with nParticle 1, so
      <d> = (8*1 + 1*8)/(8*1 + 1*4) mm = 4/3 mm, y = 0.75 and 1.5,
      <Re> = ag*rho_g*w*<d>/mu_g = 26.67;
    - no parcel: the parcel's own diameter, the law's own Sp.

    Hand values (python on these formulas, not the library's form):
        f(y) = ag*y + (1 - ag)*y^2 + 0.064*ag*y^3,  f(1) = 1 + 0.064*ag
        BVK:    Sp_i = 3*pi*mu_g*d_i*F(phi, <Re>)*f(y_i)/f(1), F Beetstra's
                10*phi/ag^2 + ag^2*(1 + 1.5*sqrt(phi)) + 0.413*Re/(24*ag^2)
                *(1/ag + 3*ag*phi + 8.4*Re^-0.343)/(1 + 10^(3*phi)*Re^-(0.5 + 2*phi))
        Stokes: Sp_i = 3*pi*mu_g*d_i*ag^-3.65*f(y_i)/f(1), so that
                Sp(Beetstra)/Sp(none) = f(y_i)/f(1) = 0.665639445 (1 mm),
                1.858243451 (2 mm)

    Also: a wrong value of polydisperseCorrection raises a FatalIOError
    naming the keyword, the value and the allowed values, and a law
    without a gas fraction does not know the keyword.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "basicKinematicMPPICCloud.H"
#include "particleForceTest.H"
#include "uniformAirFields.H"
#include "Tuple2.H"

using namespace Foam;
using namespace Foam::unitTest;


// * * * * * * * * * * * * * * * * * * Main * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "readGravitationalAcceleration.H"

    uniformAirFields air(mesh, 1.2, 1.8e-5);
    air.alpha.primitiveFieldRef() = 0.6;
    air.U.primitiveFieldRef() = vector(0, 0.5, 0);

    basicKinematicMPPICCloud cloud("kinematicCloud", air.rho, air.U, air.mu, g);

    // A parcel at rest of diameter d and weight n at a cell centre
    auto parcel = [&](const point& pt, const scalar d, const scalar n)
    {
        parcelType* q = new parcelType(mesh, pt, mesh.findCell(pt));
        q->d() = d;
        q->rho() = 2500;
        q->nParticle() = n;
        q->U() = Zero;
        return q;
    };

    const point onePt(0.375, 1.125, 0.05);
    const point twoPt(0.375, 0.375, 0.05);
    const point nonePt(0.625, 1.625, 0.05);

    parcelType* one = parcel(onePt, 1e-3, 3);
    cloud.addParticle(one);
    cloud.addParticle(parcel(onePt, 1e-3, 5));
    parcelType* small = parcel(twoPt, 1e-3, 8);
    parcelType* large = parcel(twoPt, 2e-3, 1);
    cloud.addParticle(small);
    cloud.addParticle(large);
    autoPtr<parcelType> lone(parcel(nonePt, 1e-3, 1));

    // Coupled Sp of the law on the parcel, with and without the correction
    auto Sp = [&](const word& law, const word& correction, parcelType& p)
    {
        autoPtr<ParticleForce<cloudType>> force
        (
            select
            (
                cloud, mesh, law,
                "alphac alpha.air; polydisperseCorrection " + correction + ";"
            )
        );
        force->cacheFields(true);
        vector Su;
        return coefficients(force(), cloud, p, Su).first();
    };

    for (const word law : {"BVKDrag", "StokesDrag", "GidaspowDrag"})
    {
        checkClose
        (
            law + ", one size in the cell: factor 1",
            Sp(law, "Beetstra", *one)/Sp(law, "none", *one),
            1,
            1e-13
        );
        checkClose
        (
            law + ", no parcel in the cell: factor 1",
            Sp(law, "Beetstra", lone())/Sp(law, "none", lone()),
            1,
            1e-13
        );
    }

    // Hand Sp [kg/s] of each law on the 1 mm and the 2 mm parcel
    const List<Tuple2<word, Pair<scalar>>> handSp
    ({
        {"BVKDrag", {1.935918269899497e-06, 1.080887700693886e-05}},
        {"StokesDrag", {7.28669545365611e-07, 4.068404961624661e-06}}
    });
    for (const Tuple2<word, Pair<scalar>>& law : handSp)
    {
        checkClose
        (
            law.first() + ", 1 mm among 2 mm: Sp",
            Sp(law.first(), "Beetstra", *small),
            law.second().first()
        );
        checkClose
        (
            law.first() + ", 2 mm among 1 mm: Sp",
            Sp(law.first(), "Beetstra", *large),
            law.second().second()
        );
    }

    // StokesDrag has no Reynolds number: the ratio is f(y)/f(1) itself
    const List<Tuple2<parcelType*, scalar>> handFactor
    ({
        {small, 0.6656394453004622},
        {large, 1.8582434514637902}
    });
    for (const Tuple2<parcelType*, scalar>& pf : handFactor)
    {
        parcelType& q = *pf.first();
        checkClose
        (
            "StokesDrag, d = " + Foam::name(q.d()) + " m: factor f(y)/f(1)",
            Sp("StokesDrag", "Beetstra", q)/Sp("StokesDrag", "none", q),
            pf.second()
        );
    }

    {
        vector Su;
        checkClose
        (
            "polydisperseCorrection none is the default",
            Sp("BVKDrag", "none", *large),
            coefficients
            (
                select(cloud, mesh, "BVKDrag", "alphac alpha.air;")(),
                cloud, *large, Su
            ).first(),
            0
        );
    }

    checkTrue
    (
        "BVKDrag polydisperseCorrection beetstra rejected",
        rejects
        (
            cloud, mesh, "BVKDrag",
            "alphac alpha.air; polydisperseCorrection beetstra;",
            {"polydisperseCorrection", "beetstra", "none", "Beetstra"}
        )
    );
    checkTrue
    (
        "constantCdDrag does not know polydisperseCorrection",
        rejects
        (
            cloud, mesh, "constantCdDrag",
            "Cd 1; polydisperseCorrection Beetstra;",
            {"unknown keyword", "polydisperseCorrection"}
        )
    );

    cloud.clear();

    return summary();
}


// ************************************************************************* //
