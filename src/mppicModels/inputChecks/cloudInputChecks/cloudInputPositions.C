/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    cloudInputChecks::injectionPositions: every position of a
    manualInjection's positionsFile lies in a cell of the mesh (of some
    processor's, in parallel).

\*---------------------------------------------------------------------------*/

#include "cloudInputChecks.H"
#include "fvMesh.H"
#include "globalIOFields.H"
#include "meshSearch.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{
namespace
{

//- Whether the position is in a cell: the tet search, then, as OpenFOAM's
//  injection models do for a point on an edge, again a little towards the
//  centre of the nearest cell
bool inMesh(const meshSearch& search, const point& position)
{
    if (search.findCell(position) >= 0)
    {
        return true;
    }

    const label nearest = search.findNearestCell(position);

    if (nearest < 0)
    {
        return false;
    }

    const point nudged =
        position + SMALL*(search.mesh().cellCentres()[nearest] - position);

    return search.findCell(nudged) >= 0;
}


//- One manualInjection's positions
void checkPositions(const dictionary& injector, const fvMesh& mesh)
{
    const word positionsFile(injector.get<word>("positionsFile"));

    // Read as ManualInjection reads it (the whole list on every processor),
    // not registered
    const vectorGlobalIOField positions
    (
        IOobject
        (
            positionsFile,
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );

    // Found on any processor
    const meshSearch search(mesh);
    boolList found(positions.size());
    forAll(positions, i)
    {
        found[i] = inMesh(search, positions[i]);
    }
    Pstream::listCombineGather(found, orEqOp<bool>());
    Pstream::listCombineScatter(found);

    label nOutside = 0;
    for (const bool inside : found)
    {
        nOutside += !inside;
    }

    if (nOutside > 0)
    {
        const label first = found.find(false);

        FatalIOErrorInFunction(injector)
            << "Dictionary " << injector.name() << ", keyword positionsFile: "
            << "value " << positionsFile << ": " << nOutside << " of "
            << positions.size() << " positions in " << positions.filePath()
            << " are outside the mesh, the first (element " << first
            << ") at " << positions[first] << "; allowed: positions in a"
            << " cell of the mesh, whose bounding box is "
            << boundBox(mesh.points(), true)
            << " (ignoreOutOfBounds yes drops them)"
            << exit(FatalIOError);
    }
}

} // End anonymous namespace
} // End namespace Foam


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * //

void Foam::cloudInputChecks::injectionPositions
(
    const dictionary& cloudProperties,
    const fvMesh& mesh
)
{
    forEachInjectionModel
    (
        cloudProperties,
        [&mesh](const dictionary& model)
        {
            const word type(model.lookupOrDefault<word>("type", word::null));
            if
            (
                (type == "manualInjection" || type == "phaseManualInjection")
             && !model.lookupOrDefault<bool>("ignoreOutOfBounds", false)
            )
            {
                checkPositions(model, mesh);
            }
        }
    );
}


// ************************************************************************* //
