/*---------------------------------------------------------------------------*\
    mppicModels unit tests
-------------------------------------------------------------------------------
Application
    Test-reactingParcelSources

Description
    What one parcel of basicReactingMPPICCloud (libmppicModels) gives the
    gas in one step, against the hand formulas: one parcel of 25 water
    droplets, d = 0.2 mm, rho_p = 958.6 kg/m3, injected at T = 303.15 K, at
    rest in humid air at rest (Y_H2O = 0.013135, 50 % of seed 2's Table 5)
    at Tc = 303.15 K and 101 325 Pa, which the test does not change;
    Ranz-Marshall heat transfer, liquidEvaporation with enthalpyDifference,
    explicit sources, steps of dt = 1e-3 s, maxCo 1 (one track step per
    time step; with maxCo 0.3 a parcel at rest is tracked in sub-steps of
    0.3, 0.3, 0.3 and 0.1 dt, and its mass loss differs from one step's by
    0.3 %, the cooling within the step). The second step is checked
    (OpenFOAM v1912 moves a parcel once when it is injected and again in
    the cloud's motion of the same step, so the first step exchanges twice;
    the test prints it). From the parcel's state after the first step
    (T, m, d) and with the gas and parcel at rest, Re = 0 and Sh = Nu = 2:

    Mass (OpenFOAM's liquidEvaporation, written out):
        Ts  = (2 T + Tc)/3                              film temperature
        D   = 3.6059e-3 (1.8 Ts)^1.75 sqrt(1/18.015 + 1/28)
              / (p (15^(1/3) + 15^(1/3))^2)   (API formula, H2O's numbers)
        pv  = exp(73.649 - 7258.2/T - 7.3037 ln T + 4.1653e-6 T^2)
        Cs  = pv/(RR Ts),  Cinf = X_H2O p/(RR Ts)       [kmol/m3]
        dm  = (2 D/d)(Cs - Cinf) pi d^2 W dt,  W = 18.015
        rhoTrans(H2O) = n dm,  Srho = n dm/(V dt)
    Enthalpy (ThermoParcel's analytical step):
        dh   = Ha_vapour(T) - h_liquid(T),  Ha_vapour = Cp_v T + Hf'
               (v1912's hConst), h_liquid the NSRDS polynomial of H2O
        m'   = m - dm, d' = (6 m'/(pi rho_p))^(1/3), Cp = Cp_liquid(T)
        kappa_c = Cp_mix mu/Pr_mix (constTransport, mass-weighted Cp, Pr),
        kappa_s = kappa_c Ts/Tc
        b    = (2 kappa_s/d') pi d'^2/(m' Cp),  a = -dm dh/dt/(m' Cp)
        dT   = (b Tc + a - b T)(1 - exp(-b dt))/b,  T' = T + dT
        hsTrans = n (dm Cp_v T - m' Cp (dT - a dt))
    Each is checked to 1e-9 relative (the hand sums are in double too).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "rhoReactionThermo.H"
#include "SLGThermo.H"
#include "basicReactingMPPICCloud.H"
#include "unitTest.H"

using namespace Foam;
using namespace Foam::unitTest;

const scalar piValue = constant::mathematical::pi;

// The case (case/constant, case/0)
const scalar nParticle = 25, d0 = 2e-4, rhop = 958.6, T0 = 303.15;
const scalar p0 = 101325, YH2O = 0.013135, dt = 1e-3;
const scalar Wair = 28.9596, Wvap = 18.0153, Wliq = 18.015;
const scalar CpAir = 1005, CpVap = 1864, HfVap = -1.397921e7;
const scalar mu = 0.1, PrAir = 3261.4, PrVap = 6049.0;


// * * * * * * * * * * * * * * Hand formulas  * * * * * * * * * * * * * * * //

scalar diffusivity(const scalar p, const scalar T)
{
    const scalar beta = sqr(2*std::cbrt(15.0));
    return 3.6059e-3*std::pow(1.8*T, 1.75)*std::sqrt(1/18.015 + 1/28.0)
       /(p*beta);
}

scalar vapourPressure(const scalar T)
{
    return std::exp(73.649 - 7258.2/T - 7.3037*std::log(T) + 4.1653e-6*T*T);
}

scalar polynomial(const scalar T, const std::initializer_list<scalar> c)
{
    scalar sum = 0, power = 1;
    for (const scalar ci : c)
    {
        sum += ci*power;
        power *= T;
    }
    return sum;
}

scalar liquidEnthalpy(const scalar T)
{
    return polynomial
    (
        T,
        {
            -17957283.7993676, 15341.1046350264, -58.0099916736053,
            0.150337681561662, -0.000195892311962254, 1.04025534276991e-07
        }
    );
}

scalar liquidCp(const scalar T)
{
    return polynomial
    (
        T,
        {
            15341.1046350264, -116.019983347211, 0.451013044684985,
            -0.000783569247849015, 5.20127671384957e-07
        }
    );
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "readGravitationalAcceleration.H"

    autoPtr<rhoReactionThermo> pThermo(rhoReactionThermo::New(mesh));
    rhoReactionThermo& thermo = pThermo();
    SLGThermo slgThermo(mesh, thermo);

    volScalarField rho
    (
        IOobject("rho", runTime.timeName(), mesh),
        thermo.rho()
    );
    volVectorField U
    (
        IOobject("U", runTime.timeName(), mesh, IOobject::MUST_READ),
        mesh
    );
    volScalarField alphag
    (
        IOobject("alpha.gas", runTime.timeName(), mesh),
        mesh,
        dimensionedScalar("one", dimless, 1)
    );

    basicReactingMPPICCloud cloud("reactingCloud", rho, U, g, slgThermo);

    Info<< "Gas: T " << thermo.T()[0] << ", p " << thermo.p()[0]
        << ", Y_H2O " << thermo.composition().Y("H2O")[0]
        << ", rho " << rho[0] << endl;

    runTime.setDeltaT(dt);

    // Step 1: injection (exchanges twice, see the Description)
    ++runTime;
    cloud.evolve();
    checkTrue("one parcel", cloud.size() == 1);
    const scalar T = cloud.first()->T();
    const scalar m = cloud.first()->mass();
    const scalar d = cloud.first()->d();
    Info<< "After the injection step: T " << T << ", m " << m << ", d " << d
        << endl;

    // Step 2
    ++runTime;
    cloud.evolve();

    // Hand values
    const scalar Tc = T0;
    const scalar XH2O = (YH2O/Wvap)/(YH2O/Wvap + (1 - YH2O)/Wair);
    const scalar RR = constant::thermodynamic::RR;
    const scalar Ts = (2*T + Tc)/3;
    const scalar D = diffusivity(p0, Ts);
    const scalar Cs = vapourPressure(T)/(RR*Ts);
    const scalar Cinf = XH2O*p0/(RR*Ts);
    const scalar dm = 2*D/d*(Cs - Cinf)*piValue*sqr(d)*Wliq*dt;

    const scalar dh = CpVap*T + HfVap - liquidEnthalpy(T);
    const scalar m1 = m - dm;
    const scalar d1 = std::cbrt(6*m1/(piValue*rhop));
    const scalar Cp = liquidCp(T);
    const scalar CpMix = (1 - YH2O)*CpAir + YH2O*CpVap;
    const scalar PrMix = (1 - YH2O)*PrAir + YH2O*PrVap;
    const scalar kappas = CpMix*mu/PrMix*Ts/Tc;
    const scalar b = 2*kappas/d1*piValue*sqr(d1)/(m1*Cp);
    const scalar a = -dm*dh/dt/(m1*Cp);
    const scalar dT = (b*Tc + a - b*T)*(1 - std::exp(-b*dt))/b;
    const scalar hsTrans = nParticle*(dm*CpVap*T - m1*Cp*(dT - a*dt));

    Info<< nl << "Hand values: D " << D << ", pv " << vapourPressure(T)
        << ", dm " << dm << ", dh " << dh << ", kappa_s " << kappas
        << ", dT " << dT << nl << endl;

    // The cloud's
    const label vapour = thermo.composition().species()["H2O"];
    const label celli = mesh.findCell(point(0.125, 0.125, 0.05));

    checkClose
    (
        "vapour given to the gas, rhoTrans(H2O) [kg]",
        cloud.rhoTrans(vapour)[celli], nParticle*dm, 1e-9
    );
    checkClose
    (
        "gas mass source Srho [kg/m3/s]",
        cloud.Srho()()[celli], nParticle*dm/(mesh.V()[celli]*dt), 1e-9
    );
    checkClose("parcel mass after the step [kg]", cloud.first()->mass(), m1, 1e-9);
    checkClose
    (
        "parcel temperature change [K]",
        cloud.first()->T() - T, dT, 1e-9
    );
    checkClose
    (
        "enthalpy given to the gas, hsTrans [J]",
        cloud.hsTrans()[celli], hsTrans, 1e-9
    );

    return summary();
}


// ************************************************************************* //
