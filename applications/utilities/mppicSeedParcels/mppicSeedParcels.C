/*---------------------------------------------------------------------------*\
    mppicSeedParcels: part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Application
    mppicSeedParcels

Group
    grpPreProcessingUtilities

Description
    Fills a box or a cellZone with parcels at a target solids fraction, a
    given number of parcels per cell or particles per parcel, on a jittered
    lattice or per cell, and writes the positions file of manualInjection
    together with the number of particles per parcel. Beds then start at
    the intended packing instead of the Poisson over-packing of random
    seeding.

    Three arrangements (parcelArrangements.H):
    - cell: exactly N parcels in every cell of the region, at the centres
      of the N sub-boxes of the cell's bounding box that are closest to
      cubes (for N = 5 in a 0.75 x 1 x 0.75 cm cell: five stacked along
      y), each moved by a uniform random offset in [-jitter*h/2,
      jitter*h/2] per direction. Use it for cells that are not cubes;
    - lattice (default): one lattice over the region's bounding box with N
      points per mean cell volume (counts per direction rounded one
      direction at a time, so that a region one cell deep still gets N per
      cell), jittered likewise, a point kept when it lies in a cell of the
      region. On cubic cells it gives N per cell on average; on cells that
      are not cubes the lattice and the cells beat, and the counts per
      cell spread widely around N;
    - volume: round(N*V_cell/V_mean) parcels in each cell (V_mean the
      region's mean cell volume), each at a uniformly random point of the
      cell, so that every cell starts at the target fraction to within half
      a parcel, whatever its size and shape. Use it on tetrahedra and other
      unstructured cells, where the lattice's counts per cell are uneven
      and the cell arrangement fills bounding boxes.
    Each parcel carries
        nParticle = alpha_s*V_region/(nParcels*pi*d^3/6)
    particles, so that the seeded solids volume is alpha_s*V_region exactly.

    A mixture of solids phases (MFiX's solids phases m = 1..M, each with
    its diameter D_P0(m)): a phases dictionary instead of diameter, one
    sub-dictionary per phase with its diameter, its share of the solids
    volume (volumeFraction; the shares add up to 1) and its parcelsPerCell
    or statisticalWeight. mixing mixed seeds every phase over the whole
    region at solidsFraction times its share; mixing layered splits the
    region into layers along layerDirection, the first phase lowest, each
    layer holding its phase's share of the region's volume, and seeds each
    layer with its phase at solidsFraction. Each phase gets its own
    positions file and nParticle; its density and phase index belong to
    the cloud's injection model (phaseManualInjection).

    Instead of parcelsPerCell, statisticalWeight W (particles per parcel,
    MFiX's PIC_CONST_STATWT) sets the parcel density to alpha_s/(W*pi*d^3/6)
    per unit volume, i.e. parcelsPerCell = alpha_s*V_region/
    (W*pi*d^3/6*nCells) per mean cell; nParticle is then the value above,
    within the rounding of the parcel count of W. Use it on meshes
    whose cells differ in size (tetrahedra), where a parcel count per cell
    has no fixed meaning; it needs arrangement lattice or volume.

Usage
    mppicSeedParcels [-dict <file>]

    system/mppicSeedParcelsDict:
    \verbatim
    region          box;            // box or cellZone
    box             (0 0 0) (0.05 0.1 0.005);   // region box only
    cellZone        bed;            // region cellZone only
    solidsFraction  0.3;
    parcelsPerCell  10;             // or statisticalWeight, not both
    statisticalWeight 4;            // particles per parcel (not with cell)
    diameter        2e-4;           // particle diameter [m]
    arrangement     cell;           // cell, lattice or volume
    jitter          0.5;
    seed            1;
    positionsFile   kinematicCloudPositions;    // in constant/
    \endverbatim

    \table
        Keyword        | Meaning                               | Default | Range
        region         | box or cellZone                       | (required) | box, cellZone
        box            | min and max corners [m]               | (region box) | min < max
        cellZone       | name of the cellZone                  | (region cellZone) |
        solidsFraction | target solids fraction                | (required) | (0, 1)
        parcelsPerCell | parcels per cell                      | (this or statisticalWeight) | [1, inf), an integer with cell
        statisticalWeight | particles per parcel (lattice, volume) | (this or parcelsPerCell) | [1, inf)
        diameter       | particle diameter [m]                 | (required) | (0, inf)
        arrangement    | cell (N per cell), lattice, or volume
                         (N*V_cell/V_mean per cell)             | lattice | cell, lattice, volume
        jitter         | random offset, fraction of the spacing
                         (lattice, cell)                        | 0.5    | [0, 1)
        seed           | random seed                           | 1       | integer
        positionsFile  | output file in constant/              | kinematicCloudPositions |
        phases         | one dictionary per solids phase, instead of diameter | (none: one phase) |
        mixing         | phases mixed over the region or layered | mixed | mixed, layered
        layerDirection | the direction the layers follow (layered) | (0 1 0) | not zero
    \endtable
    A phase's dictionary (phases/<name>):
    \table
        Keyword        | Meaning                               | Default | Range
        diameter       | particle diameter [m] (MFiX: D_P0)    | (required) | (0, inf)
        volumeFraction | the phase's share of the solids volume (MFiX: IC_EP_S(m)/sum) | (required) | (0, 1], adding up to 1
        parcelsPerCell, statisticalWeight | as above, for the phase | (one of them) | as above
        positionsFile  | output file in constant/              | <positionsFile>.<name> |
    \endtable
    Exactly one of parcelsPerCell and statisticalWeight; statisticalWeight
    with arrangement cell stops with a FatalIOError.
    MFiX equivalents: PIC_CONST_STATWT / PIC_CONST_NPC (constant
    statistical weight or parcels per cell) of the initial condition.

    Writes constant/<positionsFile> and constant/seededParcels with
    nParticle, nParcels, solidsVolume, regionVolume, nCells and
    parcelsPerCell (the mean per cell); a cloud dictionary uses it as
        #include "seededParcels"
        ... nParticle $nParticle;
    With phases: one positions file per phase and, in seededParcels, one
    sub-dictionary per phase with those entries and its positionsFile, and
    the totals nParcels and solidsVolume; a cloud dictionary uses them as
        ... nParticle $:<name>.nParticle;
    A phase that places no parcel, phases' volumeFraction not adding up to
    1, a diameter or share out of range, or an unknown keyword stops with
    a FatalIOError naming the dictionary, the keyword and the value.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "Random.H"
#include "boundedCoefficient.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

#include "seedingRegion.H"
#include "parcelArrangements.H"
#include "phaseSeeding.H"
#include "solidsPhases.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Seed parcels on a jittered lattice at a target solids fraction"
    );
    argList::noParallel();
    argList::addOption("dict", "file", "alternative mppicSeedParcelsDict");

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const IOdictionary dict
    (
        IOobject
        (
            args.lookupOrDefault<fileName>
            (
                "dict", runTime.system()/"mppicSeedParcelsDict"
            ),
            runTime,
            IOobject::MUST_READ
        )
    );

    using namespace mppicCoefficients;
    checkKeywords
    (
        dict,
        {
            "FoamFile", "region", "box", "cellZone", "solidsFraction",
            "parcelsPerCell", "statisticalWeight", "diameter", "arrangement",
            "jitter", "seed", "positionsFile", "phases", "mixing",
            "layerDirection"
        },
        "mppicSeedParcels"
    );
    const scalar alpha = read(dict, "solidsFraction", bounds::open(0, 1));
    const label seed = dict.lookupOrDefault<label>("seed", 1);
    const word positionsFile
    (
        dict.lookupOrDefault<word>("positionsFile", "kinematicCloudPositions")
    );

    const boolList inRegion(regionCells(mesh, dict));

    IOdictionary summary
    (
        IOobject
        (
            "seededParcels",
            runTime.constant(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        )
    );

    if (!dict.found("phases"))
    {
        const scalar diameter = read(dict, "diameter", bounds::above(0));
        Random rndGen(seed);
        seededParcels seeded =
            seedRegion(mesh, dict, dict, inRegion, alpha, diameter, rndGen);

        addSummary(summary, seeded);
        Info<< "Seeded " << seeded.positions.size() << " parcels in "
            << seeded.nCells << " cells ("
            << scalar(seeded.positions.size())/seeded.nCells << " per cell)"
            << nl << "nParticle = " << seeded.nParticle
            << " for solids fraction " << alpha << " (solids volume "
            << seeded.solidsVolume << " m3)" << nl;
        writePositions(mesh, positionsFile, seeded.positions);
        Info<< "Wrote constant/" << positionsFile << nl;
    }
    else
    {
        const solidsPhases phases(dict, positionsFile);
        const word mixing
        (
            readChoice(dict, "mixing", "mixed", {"mixed", "layered"})
        );

        List<boolList> layers;
        if (mixing == "layered")
        {
            vector direction(dict.lookupOrDefault("layerDirection", vector(0, 1, 0)));
            if (mag(direction) < VSMALL)
            {
                FatalIOErrorInFunction(dict)
                    << "Dictionary " << dict.name() << ", keyword "
                    << "layerDirection: value " << direction
                    << " must not be zero" << exit(FatalIOError);
            }
            layers = regionLayers
            (
                mesh, inRegion, direction/mag(direction), phases.fractions
            );
        }

        scalar solidsVolume = 0;
        label nParcels = 0;
        forAll(phases.names, phasei)
        {
            const dictionary& phaseDict = phases.dicts[phasei];
            Random rndGen(seed + phasei);
            seededParcels seeded =
            (
                mixing == "layered"
              ? seedRegion
                (
                    mesh, phaseDict, dict, layers[phasei], alpha,
                    phases.diameters[phasei], rndGen
                )
              : seedRegion
                (
                    mesh, phaseDict, dict, inRegion,
                    alpha*phases.fractions[phasei], phases.diameters[phasei],
                    rndGen
                )
            );

            dictionary phaseSummary;
            addSummary(phaseSummary, seeded);
            phaseSummary.add("positionsFile", phases.positionsFiles[phasei]);
            summary.add(phases.names[phasei], phaseSummary);
            solidsVolume += seeded.solidsVolume;
            nParcels += seeded.positions.size();

            Info<< "Phase " << phases.names[phasei] << ": "
                << seeded.positions.size() << " parcels in " << seeded.nCells
                << " cells, nParticle = " << seeded.nParticle
                << ", solids volume " << seeded.solidsVolume << " m3" << nl;
            writePositions
            (
                mesh, phases.positionsFiles[phasei], seeded.positions
            );
            Info<< "Wrote constant/" << phases.positionsFiles[phasei] << nl;
        }
        summary.add("nParcels", nParcels);
        summary.add("solidsVolume", solidsVolume);
        Info<< "Seeded " << phases.names.size() << " solids phases, "
            << mixing << ": " << nParcels << " parcels, solids volume "
            << solidsVolume << " m3" << nl;
    }

    // Full precision: nParticle sets the seeded solids volume (the
    // positions keep the default precision)
    IOstream::defaultPrecision(max(IOstream::defaultPrecision(), 15u));
    summary.regIOobject::write();
    Info<< "Wrote constant/seededParcels" << nl << "End" << endl;

    return 0;
}


// ************************************************************************* //
