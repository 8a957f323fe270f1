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

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "Random.H"
#include "boundedCoefficient.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

// Cells of the region: centres in the box, or the cellZone
boolList regionCells(const fvMesh& mesh, const dictionary& dict)
{
    const word region(dict.get<word>("region"));
    boolList inRegion(mesh.nCells(), false);

    if (region == "box")
    {
        const boundBox box(dict.lookup("box"));
        if (!(box.min() < box.max()))
        {
            FatalIOErrorInFunction(dict)
                << "Dictionary " << dict.name() << ", keyword box: "
                << box << " must have min < max in every direction"
                << exit(FatalIOError);
        }
        forAll(inRegion, celli)
        {
            inRegion[celli] = box.contains(mesh.C()[celli]);
        }
    }
    else if (region == "cellZone")
    {
        const word zoneName(dict.get<word>("cellZone"));
        const label zonei = mesh.cellZones().findZoneID(zoneName);
        if (zonei < 0)
        {
            FatalIOErrorInFunction(dict)
                << "Dictionary " << dict.name() << ", keyword cellZone: "
                << "unknown zone " << zoneName << "; zones: "
                << mesh.cellZones().names() << exit(FatalIOError);
        }
        for (const label celli : mesh.cellZones()[zonei])
        {
            inRegion[celli] = true;
        }
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ", keyword region: value "
            << region << " is not one of (box cellZone)" << exit(FatalIOError);
    }

    return inRegion;
}


#include "parcelArrangements.H"

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
    const scalar alpha = read(dict, "solidsFraction", bounds::open(0, 1));
    const scalar diameter = read(dict, "diameter", bounds::above(0));
    const scalar jitter = read(dict, "jitter", 0.5, bounds::closedOpen(0, 1));
    const label seed = dict.lookupOrDefault<label>("seed", 1);
    const word positionsFile
    (
        dict.lookupOrDefault<word>("positionsFile", "kinematicCloudPositions")
    );

    const boolList inRegion(regionCells(mesh, dict));

    label nRegionCells = 0;
    const scalar volume = regionVolume(mesh, inRegion, nRegionCells);
    if (nRegionCells == 0)
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ": the region has no cells"
            << exit(FatalIOError);
    }

    const scalar particleVolume = constant::mathematical::pi/6*pow3(diameter);
    const word arrangement(dict.lookupOrDefault<word>("arrangement", "lattice"));

    // Parcels per mean cell: given, or from the statistical weight
    const bool byCount = dict.found("parcelsPerCell");
    const bool byWeight = dict.found("statisticalWeight");
    if (byCount == byWeight)
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ": give exactly one of the "
            << "keywords parcelsPerCell and statisticalWeight ("
            << (byCount ? "both" : "neither") << " given)"
            << exit(FatalIOError);
    }
    scalar perCell = 0;
    if (byCount)
    {
        perCell = read(dict, "parcelsPerCell", bounds::atLeast(1));
    }
    else
    {
        const scalar weight =
            read(dict, "statisticalWeight", bounds::atLeast(1));
        if (arrangement == "cell")
        {
            FatalIOErrorInFunction(dict)
                << "Dictionary " << dict.name() << ", keyword "
                << "statisticalWeight: value " << weight << " needs "
                << "arrangement lattice or volume (arrangement cell takes an "
                << "integer parcelsPerCell)" << exit(FatalIOError);
        }
        perCell = alpha*volume/(weight*particleVolume*nRegionCells);
        Info<< "Statistical weight " << weight << ": " << perCell
            << " parcels per mean cell" << nl;
    }

    Random rndGen(seed);

    DynamicList<point> positions;
    if (arrangement == "lattice")
    {
        positions = latticePositions(mesh, inRegion, perCell, jitter, rndGen);
    }
    else if (arrangement == "cell")
    {
        if (perCell != label(perCell))
        {
            FatalIOErrorInFunction(dict)
                << "Dictionary " << dict.name() << ", keyword parcelsPerCell: "
                << "value " << perCell << " must be an integer with "
                << "arrangement cell" << exit(FatalIOError);
        }
        positions =
            cellPositions(mesh, inRegion, label(perCell), jitter, rndGen);
    }
    else if (arrangement == "volume")
    {
        positions = volumePositions(mesh, inRegion, perCell, rndGen);
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ", keyword arrangement: value "
            << arrangement << " is not one of (lattice cell volume)"
            << exit(FatalIOError);
    }

    if (positions.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ": no parcel placed in "
            << "the region (" << perCell << " parcels per mean cell); "
            << "raise parcelsPerCell or lower statisticalWeight"
            << exit(FatalIOError);
    }

    const scalar solidsVolume = alpha*volume;
    const scalar nParticle = solidsVolume/(positions.size()*particleVolume);

    IOField<point> positionsIO
    (
        IOobject
        (
            positionsFile,
            runTime.constant(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        std::move(positions)
    );
    positionsIO.write();

    // Full precision: nParticle sets the seeded solids volume
    IOstream::defaultPrecision(max(IOstream::defaultPrecision(), 15u));

    IOdictionary seeded
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
    seeded.add("nParticle", nParticle);
    seeded.add("nParcels", positionsIO.size());
    seeded.add("solidsVolume", solidsVolume);
    seeded.add("regionVolume", volume);
    seeded.add("nCells", nRegionCells);
    seeded.add("parcelsPerCell", scalar(positionsIO.size())/nRegionCells);
    seeded.regIOobject::write();

    Info<< "Seeded " << positionsIO.size() << " parcels in " << nRegionCells
        << " cells (" << scalar(positionsIO.size())/nRegionCells
        << " per cell), arrangement " << arrangement
        << nl << "nParticle = " << nParticle << " for solids fraction "
        << alpha << " (solids volume " << solidsVolume << " m3)" << nl
        << "Wrote constant/" << positionsFile << " and constant/seededParcels"
        << nl << "End" << endl;

    return 0;
}


// ************************************************************************* //
