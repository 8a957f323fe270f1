/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "cellFaceGeometry.H"
#include "processorPolyPatch.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// Where a ray from start along direction crosses one face's plane (centre
// c, outward normal n): leaving through it lowers the exit distance,
// entering through it raises the entry distance
inline void leaveThrough
(
    const point& c,
    const vector& n,
    const point& start,
    const vector& direction,
    scalar& distance
)
{
    const scalar along = direction & n;
    if (along > SMALL)
    {
        distance = min(distance, max(((c - start) & n)/along, 0));
    }
}


inline void enterThrough
(
    const point& c,
    const vector& n,
    const point& start,
    const vector& direction,
    scalar& distance
)
{
    const scalar along = direction & n;
    if (along < -SMALL)
    {
        distance = max(distance, ((c - start) & n)/along);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::vector Foam::cellFaceGeometry::withoutVelocityIntoBoundary
(
    const fvMesh& mesh,
    const label celli,
    const point& x,
    const vector& d,
    const vector& U
)
{
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    vector kept = U;
    for (const label facei : mesh.cells()[celli])
    {
        if
        (
            mesh.isInternalFace(facei)
         || patches[patches.whichPatch(facei)].coupled()
        )
        {
            continue;
        }
        const vector n = outwardNormal(mesh, celli, facei);
        const bool reached = ((x + d - mesh.faceCentres()[facei]) & n) >= 0;
        const scalar into = kept & n;
        if (reached && into > 0)
        {
            kept -= into*n;
        }
    }
    return kept;
}


Foam::scalar Foam::cellFaceGeometry::exitDistance
(
    const fvMesh& mesh,
    const label celli,
    const point& start,
    const vector& direction
)
{
    scalar distance = GREAT;
    for (const label facei : mesh.cells()[celli])
    {
        leaveThrough
        (
            mesh.faceCentres()[facei],
            outwardNormal(mesh, celli, facei),
            start,
            direction,
            distance
        );
    }
    return distance;
}


Foam::scalar Foam::cellFaceGeometry::entryDistance
(
    const fvMesh& mesh,
    const label celli,
    const point& start,
    const vector& direction
)
{
    scalar distance = 0;
    for (const label facei : mesh.cells()[celli])
    {
        enterThrough
        (
            mesh.faceCentres()[facei],
            outwardNormal(mesh, celli, facei),
            start,
            direction,
            distance
        );
    }
    return distance;
}


Foam::scalar Foam::cellFaceGeometry::distanceToProcessorFace
(
    const fvMesh& mesh,
    const label celli,
    const point& start,
    const vector& direction,
    const label maxCells
)
{
    label celll = celli;
    for (label nCells = 0; nCells < maxCells; ++nCells)
    {
        // The face through which the path leaves this cell
        scalar distance = GREAT;
        label exitFace = -1;
        for (const label facei : mesh.cells()[celll])
        {
            const scalar before = distance;
            leaveThrough
            (
                mesh.faceCentres()[facei],
                outwardNormal(mesh, celll, facei),
                start,
                direction,
                distance
            );
            if (distance < before)
            {
                exitFace = facei;
            }
        }

        if (exitFace < 0)
        {
            return -1;
        }
        if (mesh.isInternalFace(exitFace))
        {
            celll = cellAcross(mesh, celll, exitFace);
            continue;
        }

        const polyPatch& patch =
            mesh.boundaryMesh()[mesh.boundaryMesh().whichPatch(exitFace)];
        return isA<processorPolyPatch>(patch) ? distance : -1;
    }
    return -1;
}


Foam::cellFaceGeometry::faces Foam::cellFaceGeometry::cellFaces
(
    const fvMesh& mesh,
    const label celli
)
{
    const labelList& cellFaceIds = mesh.cells()[celli];
    faces cell{pointField(cellFaceIds.size()), vectorField(cellFaceIds.size())};
    forAll(cellFaceIds, i)
    {
        cell.centres[i] = mesh.faceCentres()[cellFaceIds[i]];
        cell.normals[i] = outwardNormal(mesh, celli, cellFaceIds[i]);
    }
    return cell;
}


Foam::scalar Foam::cellFaceGeometry::exitDistance
(
    const faces& cell,
    const point& start,
    const vector& direction
)
{
    scalar distance = GREAT;
    forAll(cell.centres, i)
    {
        leaveThrough(cell.centres[i], cell.normals[i], start, direction, distance);
    }
    return distance;
}


Foam::scalar Foam::cellFaceGeometry::entryDistance
(
    const faces& cell,
    const point& start,
    const vector& direction
)
{
    scalar distance = 0;
    forAll(cell.centres, i)
    {
        enterThrough(cell.centres[i], cell.normals[i], start, direction, distance);
    }
    return distance;
}


// ************************************************************************* //
