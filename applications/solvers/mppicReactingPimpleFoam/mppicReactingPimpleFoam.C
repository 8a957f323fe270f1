/*---------------------------------------------------------------------------*\
    mppicReactingPimpleFoam: part of the mppicModels project,
    GPL-3.0-or-later.
-------------------------------------------------------------------------------
Application
    mppicReactingPimpleFoam

Group
    grpLagrangianSolvers

Description
    Transient PIMPLE solver for a compressible, multi-species, laminar gas
    carrying one MPPIC parcel cloud that exchanges momentum, heat and mass
    with it (leanReactingMPPICCloud: libmppicModels'
    basicReactingMPPICCloud, OpenFOAM's reacting parcels, with its
    heat-transfer, composition and phase-change models, over MPPIC parcels,
    with the packing, damping, isotropy, drag and averaging models of
    OpenFOAM and libmppicModels; with LeanMPPICCloud's step).

    The gas fraction ag = max(1 - theta, 1 - alphaMax) of the cloud's
    solids fraction theta enters every gas equation:
        d(ag rho)/dt + div(ag phi)                      = S_rho
        d(ag rho U)/dt + div(ag phi U) - div(ag tau)    = -grad(p) + rho g
                                                           + F_cloud
        d(ag rho Yi)/dt + div(ag phi Yi)
            - div(ag kappa/Cp grad(Yi))                 = S_Yi
        d(ag rho h)/dt + div(ag phi h) + d(ag rho K)/dt + div(ag phi K)
            - ag dp/dt - div(ag kappa/Cp grad(h))       = ag rho U.g + S_h
    with phi the interstitial mass flux, h the sensible enthalpy, K the
    kinetic energy, tau the laminar stress of the mixture's viscosity, the
    species diffusivity rho D = kappa/Cp (unit Lewis number) and rho from
    the thermo (rhoReactionThermo, psi p). The momentum equation has the
    form of mppicPimpleFoam and MPPICFoam (full pressure gradient and
    gravity, the cloud's implicit drag in the matrix, its explicit part
    with gravity as face fluxes); S_rho, S_Yi, S_h and F_cloud are the
    cloud's Srho, SYi, Sh and SU.

    Each time step (the steps shared with mppicPimpleFoam are written once,
    in mppicCommon/):
    1. The time step from the gas Courant number (adjustTimeStep, maxCo).
    2. The cloud moves through the step (evolveCloud.H), in sub-steps with
       solidsSubCycling (libmppicModels' SolidsSubCycle, which sums the
       momentum, enthalpy and species sources over the sub-steps:
       CloudSourceSum); the solids fraction is deposited
       (solidsFractionDeposition) and the gas fraction updated
       (updateCloudGasFraction.H); the cloud's momentum source is split
       into its implicit and explicit parts (cloudMomentumSource.H).
    3. With a single PIMPLE outer corrector, the gas continuity for rho.
    4. PIMPLE loop: momentum, species and energy, then the pressure
       correctors. Cell velocities come from face fluxes by
       libmppicModels' reconstructFlux (see mppicPimpleFoam).
    5. The packing monitor and the write (writeTimeStep.H).
    Also shared: the -cloud option and the cloud's name (addCloudOption.H,
    readCloudName.H), the gas fraction field (createGasFraction.H) and the
    cloud's share of it (createCloudGasFraction.H), the construction of
    the cloud (newCloudOrExit.H) and the packing monitor
    (createPackingMonitor.H).

Usage
    mppicReactingPimpleFoam [-cloud <name>] [-parallel]
    Reads constant/thermophysicalProperties (rhoReactionThermo with
    energy sensibleEnthalpy; inertSpecie; liquids and solids for
    SLGThermo), constant/<cloud>Properties (default cloud name
    reactingCloud; OpenFOAM's reacting-cloud dictionary with the MPPIC
    submodels and constantProperties/alphaMax; libmppicModels'
    solidsFractionFrom and solidsSubCycling), constant/g, 0/U, 0/p, 0/T,
    0/<specie> and system/fvSolution PIMPLE (pimpleControl's and
    setRefCell's keywords only: any other, a misspelling, stops with a
    FatalIOError listing the valid ones). Writes U, p, T, the species,
    rho, alpha.gas (gas fraction) and alpha.<cloud> (solids fraction).
    \table
        Entry        | Meaning                               | Default
        inertSpecie  | specie set to one minus the others      | required
        -cloud       | name of the cloud                       | reactingCloud
    \endtable
    The gas is laminar; an inertSpecie that is not one of the species, or
    an energy other than sensibleEnthalpy, stops with a FatalIOError. As
    mppicPimpleFoam, it runs libmppicModels' packingMonitor when the cloud
    has a packing model ("packingMonitor off;" in system/controlDict turns
    it off).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "rhoReactionThermo.H"
#include "SLGThermo.H"
#include "pimpleControl.H"
#include "leanReactingMPPICCloud.H"
#include "packingMonitor.H"
#include "SolidsSubCycle.H"
#include "solidsFractionDeposition.H"
#include "reconstructFlux.H"
#include "newCloudOrExit.H"
#include "cloudInputChecks.H"
#include "boundedCoefficient.H"
#include "multivariateScheme.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "PIMPLE solver for a compressible multi-species gas coupled to a"
        " reacting MPPIC parcel cloud (libmppicModels)"
    );
    const word defaultCloudName("reactingCloud");
    #include "addCloudOption.H"

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "createControl.H"
    const wordList solverPimpleKeywords(0);
    #include "checkPimpleKeywords.H"
    #include "createTimeControls.H"
    #include "createFields.H"
    #include "createPackingMonitor.H"
    #include "initContinuityErrs.H"

    #include "compressibleCourantNo.H"
    #include "setInitialDeltaT.H"

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "compressibleCourantNo.H"
        #include "setDeltaT.H"

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        #include "evolveCloud.H"
        alphaPhi = alphagf*phi;

        if (pimple.nCorrPIMPLE() <= 1)
        {
            #include "gasContinuityEqn.H"
        }

        while (pimple.loop())
        {
            #include "gasMomentumEqn.H"
            #include "gasSpeciesEqn.H"
            #include "gasEnergyEqn.H"

            while (pimple.correct())
            {
                #include "gasPressureEqn.H"
            }
        }

        rho = thermo.rho();

        #include "writeTimeStep.H"
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
