/*---------------------------------------------------------------------------*\
    mppicPimpleFoam: part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Application
    mppicPimpleFoam

Group
    grpLagrangianSolvers

Description
    Transient PIMPLE solver for an incompressible gas carrying one MPPIC
    parcel cloud (leanKinematicMPPICCloud: basicKinematicMPPICCloud with
    LeanMPPICCloud's step), with the gas volume fraction seen by both
    phases. Stock MPPICFoam's equations and step of OpenFOAM v1912, so that
    both solvers give the same answer on the same case
    (tests/regression/solverParity); the models of libmppicModels are
    linked in and selectable at run time.

    The gas momentum equation is written per unit gas density, in the
    volume-fraction-weighted form

        d(ag U)/dt + div(ag phi U) - U (d(ag)/dt + div(ag phi))
          + div(ag R_eff) = -grad(p) + g + F_cloud/rho_g + S (u_s - U)

    with the gas continuity

        d(ag)/dt + div(ag phi) = S

    where ag = max(1 - theta, 1 - alphaMax) is the gas fraction from the
    cloud's solids fraction theta, p is kinematic, F_cloud the momentum
    the parcels give back and S the gas volume that libmppicModels'
    gasMassSources (constant/gasMassSources, MFiX's point sources) add per
    unit volume and time, spread over the cells within a sphere and
    arriving with their own velocity u_s (zero without that file).

    Each time step:
    1. The time step from the gas Courant number (adjustTimeStep, maxCo).
    2. The cloud moves through the step; with solidsSubCycling active in
       the cloud's properties, in sub-steps of MFiX-PIC's eq 24
       (SolidsSubCycle: CFL, response time, gas step) with the gas frozen
       and the momentum exchange averaged over the gas step.
    3. The solids fraction theta is deposited per cell (solidsFractionFrom
       cell, the default, as MPPICFoam) or by the cloud's averagingMethod
       (solidsFractionFrom averaging, as MFiX-PIC deposits with its
       kernel: solidsFractionDeposition), and ag updated. The step prints
       the number of parcels and the largest cell solids fraction (before
       the alphaMax limit).
    4. The cloud's momentum source is split: the implicit part in the gas
       matrix, the explicit part with gravity distributed as a face flux,
       so that a bed at rest is balanced by the pressure gradient without
       spurious velocities.
    5. PIMPLE loop: momentum predictor and pressure correctors with the
       continuity above. Cell velocities are reconstructed from face
       fluxes with libmppicModels' reconstructFlux: fvc::reconstruct's
       result without its aliasing on non-orthogonal cells (see
       reconstructFlux.H); the same as fvc::reconstruct on orthogonal
       hexahedra.
    6. With balanceImplicitDrag, the parcels get the drag the gas got
       (implicitDragBalance).
    7. When the cloud has a packing model, libmppicModels' packingMonitor
       (postProcessing/packingMonitor; "packingMonitor off;" in
       system/controlDict turns it off); then the fields are written:
       U.<gas>, p (kinematic), alpha.<gas> and alpha.<cloud> (solids
       fraction).

    With constant/prescribedGasFlowProperties (libmppicModels'
    prescribedGasFlow, e.g. "type vortex; period 0.25;") the gas is not
    solved: U.<gas> and phi.<gas> follow the analytic field, at mid-step
    while the parcels move (see createPrescribedGasFlow.H).

Usage
    mppicPimpleFoam [-cloud <name>] [-parallel]

    The cloud's name is kinematicCloud unless -cloud gives another.
    Reads constant/transportProperties (continuousPhase <name>; rho.<name>;
    transportModel, nu), constant/<cloud>Properties (the cloud, with
    constantProperties/alphaMax), constant/turbulenceProperties.<name>,
    constant/g, 0/U.<name>, 0/p and system/fvSolution PIMPLE.

    PIMPLE keywords of its own (the rest are pimpleControl's and
    setRefCell's; any other keyword, a misspelling, stops with a
    FatalIOError listing the valid ones):
    \table
        Keyword              | Meaning                           | Default
        faceInterpolatedDrag | face coefficient of the pressure equation
                               1/interpolate(A), with H and the explicit
                               forces interpolated alongside (the two half
                               cells' drag in series), instead of
                               MPPICFoam's interpolate(1/A),
                               interpolate(H/A)                  | false
        superficialFluxCoupling | the superficial flux ag phi with the
                               face coefficient of its two half cells
                               in series, 1/(ag_f interpolate(A/ag)),
                               H and the forces interpolated
                               alongside, the time-derivative
                               correction of that flux, and the cell
                               velocity the parcels see rebuilt from
                               it (mppicSuperficialFlux); at most one
                               of it and faceInterpolatedDrag true,
                               else a FatalIOError               | false
        balanceImplicitDrag  | after the gas solution the parcels get the
                               drag the gas got: each cell's parcels gain
                               UCoeff (U_g,new - U_g,old) over their mass
                               as one velocity change (implicitDragBalance);
                               needs U semiImplicit in the cloud's
                               sourceTerms, else a FatalIOError | false
    \endtable
    The face coefficient: where the drag coefficient A jumps, between a
    packed cell and the freeboard or a fixed-velocity inflow, or at the
    edge of a falling mixture, the face's resistance is that of its two
    half cells in series, 1/interpolate(A); MPPICFoam's interpolate(1/A)
    adds their conductances as if in parallel. A wall's face then carries
    its half cell's H, which p's fixedFluxPressure condition balances as it
    balances the body forces' flux (every shipped case has it on its
    walls). Off by default: MPPICFoam's form. No MFiX equivalent (MFiX
    solves its momentum on a staggered grid). Either interpolated face
    form (this or superficialFluxCoupling) gives the serial answer on 2
    ranks to round-off (tests/regression/parallelFaceForms: U within 6e-10
    of its largest magnitude after 40 steps of the uniform bed).

    The superficial-flux coupling: in a cell the gas's momentum balance
    gives its superficial velocity ag U = (H + F - grad p) ag/A, so the
    resistance per superficial velocity is A/ag and a face's is that of
    its two half cells in series, interpolate(A/ag). The flux's
    time-derivative correction compares the old superficial flux with
    the interpolated old superficial velocity, and the cell velocity is
    the superficial face flux without that correction, rebuilt, over the
    cell's gas fraction, with the part of the cell's own H that the
    faces' interpolation smoothed away restored
    (mppicSuperficialFlux::cellVelocity). At a jump of the gas fraction
    (the top row of a packed bed, a bubble's edge) MPPICFoam's rebuild
    HbyA + rAU reconstruct(face forces) mixes the bed's 1/A with the
    freeboard's pressure gradient: the top row of a packed bed under a
    rising gas sees about half its interstitial velocity and the row
    above three times the inlet's. With the coupling the gas's pressure
    drop over a fixed bed is the drag its parcels get, row by row, and
    the freeboard's rows carry the inlet's velocity within 2.5 %
    (tests/regression/superficialFluxCoupling measures both couplings on
    a fixed bed). Off by default: a fluidized bed rests more of its
    weight on the packing step and the distributor (the uniform bed's gas
    carries 0.86 of it), and the settling-shock filling front falls
    short (docs/VALIDATION.md, the options the defaults leave off). No
    MFiX equivalent.

    The drag balance: with semi-implicit drag the gas takes the drag at its
    new velocity and the parcels took it at the old one; in beds whose
    parcels cross cells the difference keeps one sign, and the parcels get
    more drag than the gas's pressure drop shows. The balance removes the
    difference, but in a bed at rest it lifts the parcels by the drag's
    change each step (a fixed bed under a rising inflow loses part of its
    pressure drop), so it is off by default.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "PhaseIncompressibleTurbulenceModel.H"
#include "pimpleControl.H"
#include "leanKinematicMPPICCloud.H"
#include "packingMonitor.H"
#include "SolidsSubCycle.H"
#include "solidsFractionDeposition.H"
#include "prescribedGasFlow.H"
#include "reconstructFlux.H"
#include "superficialFluxCoupling.H"
#include "implicitDragBalance.H"
#include "gasMassSources.H"
#include "newCloudOrExit.H"
#include "cloudInputChecks.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "PIMPLE solver for an incompressible gas coupled to an MPPIC"
        " parcel cloud (libmppicModels)"
    );
    const word defaultCloudName("kinematicCloud");
    #include "addCloudOption.H"

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "createControl.H"
    const wordList solverPimpleKeywords
    ({
        "faceInterpolatedDrag", "superficialFluxCoupling",
        "balanceImplicitDrag"
    });
    #include "checkPimpleKeywords.H"
    #include "createTimeControls.H"
    #include "createFields.H"
    #include "createPackingMonitor.H"
    #include "createPrescribedGasFlow.H"
    #include "createImplicitDragBalance.H"
    #include "initContinuityErrs.H"

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "gasCourantNo.H"
        #include "setDeltaT.H"

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        gasTransport.correct();
        mug = rhog*gasTransport.nu();

        if (prescribedFlow.valid())
        {
            prescribedFlow->correct
            (
                Ug, phig, runTime.value() - 0.5*runTime.deltaTValue()
            );
        }

        #include "evolveCloud.H"
        alphaPhig = alphagf*phig;

        // The gas velocity the parcels saw, for balanceImplicitDrag
        const vectorField UgSeen
        (
            balanceImplicitDrag ? Ug.primitiveField() : vectorField()
        );

        if (prescribedFlow.valid())
        {
            prescribedFlow->correct(Ug, phig, runTime.value());
        }

        while (!prescribedFlow.valid() && pimple.loop())
        {
            #include "gasMomentumEqn.H"

            while (pimple.correct())
            {
                #include "gasPressureEqn.H"
            }

            if (pimple.turbCorr())
            {
                gasTurbulence->correct();
            }
        }

        if (balanceImplicitDrag && !prescribedFlow.valid())
        {
            const Tuple2<vector, vector> balance
            (
                implicitDragBalance(cloud, UgSeen, Ug)
            );
            Info<< "Implicit drag balance: parcels given " << balance.first()
                << " kg m/s, cells without parcels " << balance.second()
                << endl;
        }

        #include "writeTimeStep.H"
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
