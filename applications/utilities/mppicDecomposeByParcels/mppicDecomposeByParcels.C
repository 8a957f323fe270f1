/*---------------------------------------------------------------------------*\
    mppicDecomposeByParcels: part of the mppicModels project,
    GPL-3.0-or-later.
-------------------------------------------------------------------------------
Application
    mppicDecomposeByParcels

Group
    grpParallelUtilities

Description
    Writes a cell-to-processor list (constant/cellDecomposition, for
    decomposePar's method manual) that gives each processor about the same
    work, counting the parcels as well as the cells. A bed that fills half
    of a column then gets as many parcels on each processor as the gas
    cells allow, where simple's equal cell counts put the bed on one
    processor and the freeboard on the other.

    1. Each cell weighs
           w = 1 + parcelWeight*(parcels in the cell),
       the parcels being those of the injection's positions file;
       parcelWeight is the cost of a parcel relative to a cell (a step of
       the cloud costs about as much per parcel as the gas's per cell:
       default 1).
    2. The cells are cut as decomposePar's simple method cuts them,
       n = (nx ny nz) slabs one direction after the other (x, then y
       within each x slab, then z), but at equal weight instead of equal
       cell count.
    3. Prints, per processor, the cells, the parcels and the weight.

Usage
    mppicDecomposeByParcels [-positions <file>] [-report]

    -positions: the parcel positions file in constant/ (a vectorField, as
    written by mppicSeedParcels; default kinematicCloudPositions).
    -report: write nothing; print the cells, parcels and weight of each
    processor of the decomposition in constant/cellDecomposition (e.g. the
    one decomposePar -cellDist writes for any method).

    system/decomposeParDict:
    \verbatim
    numberOfSubdomains 2;
    method          manual;
    coeffs
    {
        dataFile    "cellDecomposition";
    }
    mppicDecomposeByParcelsCoeffs
    {
        n               (2 1 1);
        parcelWeight    1;
    }
    \endverbatim

    \table
        Keyword      | Meaning                                 | Default | Range | MFiX
        n            | slabs in x, y and z                     | (required) | each >= 1, product numberOfSubdomains | -
        parcelWeight | cost of a parcel relative to a cell     | 1       | [0, inf) | -
    \endtable
    A value outside its range stops with a FatalIOError naming the
    keyword and the value.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "vectorIOField.H"
#include "labelIOList.H"
#include "SortableList.H"
#include "labelVector.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Cut cells into n groups of equal weight along direction dir; recurse
//  into the next direction; write the processor of each cell
void cutSlabs
(
    const labelList& cells,
    const pointField& centres,
    const scalarField& weight,
    const labelVector& n,
    const direction dir,
    const label offset,
    labelList& processor
)
{
    if (dir == vector::nComponents)
    {
        for (const label celli : cells)
        {
            processor[celli] = offset;
        }
        return;
    }

    // Cells in order along dir
    SortableList<scalar> coordinate(cells.size());
    forAll(cells, i)
    {
        coordinate[i] = centres[cells[i]][dir];
    }
    coordinate.sort();
    const labelList& order = coordinate.indices();

    scalar total = 0;
    for (const label celli : cells)
    {
        total += weight[celli];
    }

    // Processors one step further in dir are this many apart
    label stride = 1;
    for (direction d = dir + 1; d < vector::nComponents; ++d)
    {
        stride *= n[d];
    }

    label start = 0;
    scalar done = 0;
    for (label slab = 0; slab < n[dir]; ++slab)
    {
        // Up to the slab's share of the weight (the last takes the rest)
        const scalar target = total*(slab + 1)/n[dir];
        DynamicList<label> slabCells;
        while
        (
            start < order.size()
         && (slab == n[dir] - 1 || done + 0.5*weight[cells[order[start]]] <= target)
        )
        {
            const label celli = cells[order[start]];
            slabCells.append(celli);
            done += weight[celli];
            ++start;
        }
        cutSlabs
        (
            slabCells, centres, weight, n, dir + 1, offset + slab*stride,
            processor
        );
    }
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Decomposition for method manual that balances cells and parcels"
    );
    argList::noParallel();
    argList::addBoolOption
    (
        "report",
        "print the balance of constant/cellDecomposition, write nothing"
    );
    argList::addOption
    (
        "positions",
        "file",
        "parcel positions in constant/ (default kinematicCloudPositions)"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    IOdictionary decomposeDict
    (
        IOobject
        (
            "decomposeParDict",
            runTime.system(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );

    const bool report = args.found("report");
    const label nDomains = decomposeDict.get<label>("numberOfSubdomains");
    const dictionary& coeffs =
        decomposeDict.optionalSubDict("mppicDecomposeByParcelsCoeffs");

    const labelVector n
    (
        report
      ? coeffs.getOrDefault<labelVector>("n", labelVector(nDomains, 1, 1))
      : coeffs.get<labelVector>("n")
    );
    if (cmptMin(n) < 1 || cmptProduct(n) != nDomains)
    {
        FatalIOErrorInFunction(coeffs)
            << "n " << n << " in " << coeffs.name() << ": each must be >= 1"
            << " and their product numberOfSubdomains " << nDomains
            << exit(FatalIOError);
    }

    const scalar parcelWeight = coeffs.getOrDefault<scalar>("parcelWeight", 1);
    if (parcelWeight < 0)
    {
        FatalIOErrorInFunction(coeffs)
            << "parcelWeight " << parcelWeight << " in " << coeffs.name()
            << ": allowed range [0, inf)" << exit(FatalIOError);
    }

    const word positionsName
    (
        args.getOrDefault<word>("positions", "kinematicCloudPositions")
    );
    const vectorIOField positions
    (
        IOobject
        (
            positionsName,
            runTime.constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );

    // Parcels per cell
    labelList nParcels(mesh.nCells(), Zero);
    label outside = 0;
    for (const point& p : positions)
    {
        const label celli = mesh.findCell(p);
        if (celli < 0)
        {
            ++outside;
            continue;
        }
        ++nParcels[celli];
    }
    if (outside)
    {
        WarningInFunction
            << outside << " of " << positions.size() << " parcels of "
            << positions.objectPath() << " lie outside the mesh: not counted"
            << endl;
    }

    scalarField weight(mesh.nCells(), 1.0);
    forAll(weight, celli)
    {
        weight[celli] += parcelWeight*nParcels[celli];
    }

    IOobject decompositionIO
    (
        "cellDecomposition",
        mesh.facesInstance(),
        mesh,
        report ? IOobject::MUST_READ : IOobject::NO_READ,
        IOobject::NO_WRITE,
        false
    );

    labelList processor(mesh.nCells(), -1);
    if (report)
    {
        processor = labelIOList(decompositionIO);
        if (processor.size() != mesh.nCells())
        {
            FatalErrorInFunction
                << decompositionIO.objectPath() << " lists "
                << processor.size() << " cells, the mesh has "
                << mesh.nCells() << exit(FatalError);
        }
    }
    else
    {
        cutSlabs
        (
            identity(mesh.nCells()), mesh.cellCentres(), weight, n, 0, 0,
            processor
        );
        labelIOList(decompositionIO, processor).write();
    }

    Info<< nl << "processor  cells  parcels  weight" << nl;
    for (label proci = 0; proci < nDomains; ++proci)
    {
        label cells = 0, parcels = 0;
        scalar w = 0;
        forAll(processor, celli)
        {
            if (processor[celli] == proci)
            {
                ++cells;
                parcels += nParcels[celli];
                w += weight[celli];
            }
        }
        Info<< proci << "  " << cells << "  " << parcels << "  " << w << nl;
    }
    Info<< nl << (report ? "Read " : "Wrote ") << decompositionIO.objectPath()
        << nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
