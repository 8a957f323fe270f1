/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Application
    Test-bedPressureDrop

Description
    Checks functionObjects::bedPressureDrop on the 1 m x 2 m x 0.1 m box of
    tests/unit/cases/box (bottom at y = 0, top at y = 2 m, g = -9.81 y),
    with pressure fields linear in height whose patch values are known:

    - kinematic p = 100 - 40*y [m2/s2], rhoInf 1.5:
        deltaP = 1.5*(100 - 20) = 120 Pa, gas head = 1.5*9.81*2 = 29.43 Pa
    - same p with a density field rho.air = 1.2:
        deltaP = 1.2*80 = 96 Pa
    - p in Pa, pPa = 1000 - 200*y: deltaP = 400 Pa, whatever rhoInf
    - bed weight per area of a cloud holding one parcel of 1000 beads of
      1 mm, 2500 kg/m3 (mass 1000*2500*pi/6*1e-9 kg): m*9.81/A with A the
      bottom patch's area 1 m x 0.1 m = 0.1 m2, or crossSection 0.05 m2;
    - bad input: unknown patch, lowerPatch == upperPatch, rhoInf <= 0,
      missing rhoInf, crossSection <= 0 all raise FatalIOError naming the
      keyword; so does rhoInf 1.5 with a kinematic p while the gas density
      field rho.air = 1.2 is registered (it would report 1.5/1.2 = 1.25
      times the pressure drop), and rhoInf 1.2 beside it is accepted
      (deltaP = 96 Pa).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "bedPressureDrop.H"
#include "basicKinematicMPPICCloud.H"
#include "unitTest.H"

using namespace Foam;

// Linear field a - b*y in the cells and on every patch face
tmp<volScalarField> linearInHeight
(
    const fvMesh& mesh,
    const word& name,
    const dimensionSet& dims,
    const scalar a,
    const scalar b
)
{
    tmp<volScalarField> tfld
    (
        new volScalarField
        (
            IOobject(name, mesh.time().timeName(), mesh),
            mesh,
            dimensionedScalar(dims, Zero),
            calculatedFvPatchScalarField::typeName
        )
    );
    volScalarField& fld = tfld.ref();

    fld.primitiveFieldRef() = a - b*mesh.C().primitiveField().component(1);
    forAll(fld.boundaryField(), patchi)
    {
        fld.boundaryFieldRef()[patchi] =
            a - b*mesh.C().boundaryField()[patchi].component(1);
    }
    return tfld;
}


dictionary settings(const word& lower, const word& upper)
{
    dictionary dict;
    dict.add("type", "bedPressureDrop");
    dict.add("lowerPatch", lower);
    dict.add("upperPatch", upper);
    dict.add("rhoInf", 1.5);
    dict.add("writeToFile", false);
    return dict;
}


// True when constructing with dict raises a FatalIOError mentioning keyword
bool rejects(const Time& runTime, const dictionary& dict, const word& keyword)
{
    return unitTest::raisesError
    (
        [&]()
        {
            functionObjects::bedPressureDrop fo("bad", runTime, dict);
        },
        {keyword}
    );
}


int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    using namespace unitTest;

    const scalar gHead = 1.5*9.81*2.0;

    {
        tmp<volScalarField> p =
            linearInHeight(mesh, "p", sqr(dimVelocity), 100, 40);
        p.ref().store(p.ptr());

        functionObjects::bedPressureDrop fo
        (
            "dp", runTime, settings("bottom", "top")
        );
        checkClose("kinematic p, rhoInf 1.5: deltaP [Pa]", fo.deltaP(), 120);
        checkClose("gas head rho*|g|*H [Pa]", fo.gasHead(), gHead);
        checkClose("no cloud: weight per area", fo.bedWeightPerArea(), 0, 0, 1);

        functionObjects::bedPressureDrop reversed
        (
            "dpReversed", runTime, settings("top", "bottom")
        );
        checkClose("patches swapped: deltaP [Pa]", reversed.deltaP(), -120);

        volScalarField* rhoPtr = new volScalarField
        (
            IOobject("rho.air", runTime.timeName(), mesh),
            mesh,
            dimensionedScalar("rho", dimDensity, 1.2)
        );
        rhoPtr->store();

        dictionary dict(settings("bottom", "top"));
        dict.set("rho", "rho.air");
        functionObjects::bedPressureDrop withField("dpRho", runTime, dict);
        checkClose("kinematic p, rho field 1.2: deltaP [Pa]", withField.deltaP(), 96);

        checkTrue
        (
            "rhoInf 1.5 beside the gas density field rho.air 1.2 rejected",
            rejects(runTime, settings("bottom", "top"), "rhoInf")
        );

        dict = settings("bottom", "top");
        dict.set("rhoInf", 1.2);
        functionObjects::bedPressureDrop agreeing("dpAgree", runTime, dict);
        checkClose
        (
            "kinematic p, rhoInf 1.2 = rho.air: deltaP [Pa]",
            agreeing.deltaP(),
            96
        );
    }

    {
        tmp<volScalarField> pPa =
            linearInHeight(mesh, "pPa", dimPressure, 1000, 200);
        pPa.ref().store(pPa.ptr());

        dictionary dict(settings("bottom", "top"));
        dict.set("p", "pPa");
        functionObjects::bedPressureDrop fo("dpPa", runTime, dict);
        checkClose("p in Pa: deltaP [Pa]", fo.deltaP(), 400);
    }

    {
        dictionary dict(settings("bottom", "top"));
        dict.set("lowerPatch", "floor");
        checkTrue("unknown patch rejected", rejects(runTime, dict, "lowerPatch"));

        checkTrue
        (
            "lowerPatch == upperPatch rejected",
            rejects(runTime, settings("top", "top"), "same patch")
        );

        dict = settings("bottom", "top");
        dict.set("rhoInf", -1.0);
        checkTrue("rhoInf = -1 rejected", rejects(runTime, dict, "rhoInf"));

        dict = settings("bottom", "top");
        dict.remove("rhoInf");
        checkTrue("missing rhoInf rejected", rejects(runTime, dict, "rhoInf"));

        dict = settings("bottom", "top");
        dict.set("rhoInf", 1.2);
        dict.add("crossSection", -0.05);
        checkTrue
        (
            "crossSection = -0.05 rejected",
            rejects(runTime, dict, "crossSection")
        );
    }

    // Weight per area of a cloud with one parcel
    {
        auto uniform = [&](const word& name, const dimensionSet& dims, scalar v)
        {
            return new volScalarField
            (
                IOobject(name, runTime.timeName(), mesh),
                mesh,
                dimensionedScalar(name, dims, v)
            );
        };
        autoPtr<volScalarField> rhoAir(uniform("rhoAir", dimDensity, 1.2));
        autoPtr<volScalarField> muAir
        (
            uniform("mu.air", dimDynamicViscosity, 1.8e-5)
        );
        autoPtr<volScalarField> alphaAir(uniform("alpha.air", dimless, 1));
        volVectorField U
        (
            IOobject("U.air", runTime.timeName(), mesh),
            mesh,
            dimensionedVector(dimVelocity, Zero)
        );
        const uniformDimensionedVectorField g
        (
            IOobject("g", runTime.constant(), mesh, IOobject::MUST_READ)
        );
        basicKinematicMPPICCloud cloud
        (
            "kinematicCloud", rhoAir(), U, muAir(), g
        );

        const point centre(0.5, 0.5, 0.05);
        auto* p = new basicKinematicMPPICCloud::parcelType
        (
            mesh, centre, mesh.findCell(centre)
        );
        p->d() = 1e-3;
        p->rho() = 2500;
        p->nParticle() = 1000;
        cloud.addParticle(p);

        const scalar mass =
            1000*2500*constant::mathematical::pi/6*1e-9;

        dictionary dict(settings("bottom", "top"));
        dict.set("rhoInf", 1.2);
        dict.add("cloud", "kinematicCloud");
        functionObjects::bedPressureDrop fo("dpCloud", runTime, dict);
        checkClose
        (
            "weight per area over the bottom patch (0.1 m2)",
            fo.bedWeightPerArea(),
            mass*9.81/0.1
        );

        dict.add("crossSection", 0.05);
        functionObjects::bedPressureDrop fo2("dpCloudSection", runTime, dict);
        checkClose
        (
            "weight per area over crossSection 0.05 m2",
            fo2.bedWeightPerArea(),
            mass*9.81/0.05
        );
    }

    return summary();
}


// ************************************************************************* //
