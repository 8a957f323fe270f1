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

// Where a ray crosses one face's plane, given the ray's direction along
// the plane's outward normal n (along = direction & n) and its start's
// distance below the plane along n (gap = (c - start) & n, c the face
// centre): leaving through it lowers the exit distance, entering through
// it raises the entry distance
inline void leaveThrough(const scalar along, const scalar gap, scalar& distance)
{
    if (along > SMALL)
    {
        distance = min(distance, max(gap/along, 0));
    }
}


inline void enterThrough(const scalar along, const scalar gap, scalar& distance)
{
    if (along < -SMALL)
    {
        distance = max(distance, gap/along);
    }
}


// The faces of a cell of the mesh as planes, read from the mesh as asked
class meshCellPlanes
{
    const fvMesh& mesh_;
    const label celli_;
    const labelList& faceIds_;

public:

    meshCellPlanes(const fvMesh& mesh, const label celli)
    :
        mesh_(mesh),
        celli_(celli),
        faceIds_(mesh.cells()[celli])
    {}

    label size() const
    {
        return faceIds_.size();
    }

    const point& centre(const label i) const
    {
        return mesh_.faceCentres()[faceIds_[i]];
    }

    vector normal(const label i) const
    {
        return cellFaceGeometry::outwardNormal(mesh_, celli_, faceIds_[i]);
    }
};


// The faces of a cell given as planes (cellFaceGeometry::faces)
class givenCellPlanes
{
    const cellFaceGeometry::faces& cell_;

public:

    explicit givenCellPlanes(const cellFaceGeometry::faces& cell)
    :
        cell_(cell)
    {}

    label size() const
    {
        return cell_.centres.size();
    }

    const point& centre(const label i) const
    {
        return cell_.centres[i];
    }

    const vector& normal(const label i) const
    {
        return cell_.normals[i];
    }
};


// The distance from the initial one after the ray from start along
// direction crossed (leaveThrough or enterThrough) each face plane of the
// cell in turn
template<class CellPlanes, class Crossing>
scalar distanceThroughFaces
(
    const CellPlanes& cell,
    const point& start,
    const vector& direction,
    scalar distance,
    const Crossing& crossing
)
{
    for (label i = 0; i < cell.size(); ++i)
    {
        const vector n = cell.normal(i);
        crossing(direction & n, (cell.centre(i) - start) & n, distance);
    }
    return distance;
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
    return distanceThroughFaces
    (
        meshCellPlanes(mesh, celli), start, direction, GREAT, leaveThrough
    );
}


Foam::scalar Foam::cellFaceGeometry::entryDistance
(
    const fvMesh& mesh,
    const label celli,
    const point& start,
    const vector& direction
)
{
    return distanceThroughFaces
    (
        meshCellPlanes(mesh, celli), start, direction, 0, enterThrough
    );
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
            const vector n = outwardNormal(mesh, celll, facei);
            leaveThrough
            (
                direction & n, (mesh.faceCentres()[facei] - start) & n, distance
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
    return distanceThroughFaces
    (
        givenCellPlanes(cell), start, direction, GREAT, leaveThrough
    );
}


Foam::scalar Foam::cellFaceGeometry::entryDistance
(
    const faces& cell,
    const point& start,
    const vector& direction
)
{
    return distanceThroughFaces
    (
        givenCellPlanes(cell), start, direction, 0, enterThrough
    );
}


// ************************************************************************* //
