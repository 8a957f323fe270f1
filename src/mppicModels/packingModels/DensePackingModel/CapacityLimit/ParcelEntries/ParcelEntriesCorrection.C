/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    ParcelEntries' correction of a parcel: where its correction move may
    take it, and the velocity it keeps (included by ParcelEntries.H).

    limitedCorrection, by the parcel's entry:
    1. pushed on: into the face neighbour it makes room in, toward that
       cell's centre, just past the face (1 % of the way across the cell);
    2. refused, from a known cell here or on another processor: back into
       that cell, aiming at its centre (a face or an edge/corner
       neighbour), the rules' move held between 1 % and 99 % of the way
       across it;
    3. refused, from a cell not known (an injected parcel that came in
       through a processor face): back out of its cell the way it came
       in, between 1 % and 49 % of the cell's size beyond the face;
    4. otherwise the rules' move, shortened to stay within its own cell
       (99 % of the way to the face ahead).
    A move across a processor face is lengthened for OpenFOAM v1912's
    correction track (trackLength), not for LeanMPPICCloud's.
    keptVelocity: a refused parcel keeps no velocity into the refusing
    cell relative to that cell's parcels.

\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::ParcelEntries<CloudType>::trackLength
(
    const scalar travel,
    const scalar toProcessorFace
)
{
    // OpenFOAM v1912's MPPICParcel resumes a correction track on the next
    // processor with its velocity scaled by the fraction of the step left,
    // 1 - f, f = d/L, so that of the rest of a track of length L it covers
    // (1 - f)^2 L, not (1 - f) L. For the parcel to end travel along its
    // path, ask for L with d + (L - d)^2/L = travel. (LeanMPPICCloud's own
    // tracks cover L: its callers pass no processor face, exactTracks_)
    const scalar d = toProcessorFace;
    if (d <= 0 || d >= travel)
    {
        return travel;
    }
    return 0.5*((travel + d) + Foam::sqrt((travel - d)*(travel + 3*d)));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
bool Foam::ParcelEntries<CloudType>::returnsToHeldCell
(
    const parcelType& p
) const
{
    const entry* e = find(p);
    return
        e && !e->admitted && e->remote >= 0 && originHeld_.size()
     && originHeld_[e->remote];
}


template<class CloudType>
Foam::label Foam::ParcelEntries<CloudType>::finalCell
(
    const parcelType& p
) const
{
    const entry* e = find(p);
    if (e && e->pushedTo >= 0)
    {
        return e->pushedTo;
    }
    return e && !e->admitted ? e->from : p.cell();
}


template<class CloudType>
Foam::vector Foam::ParcelEntries<CloudType>::keptVelocity
(
    const parcelType& p,
    const vector& U,
    const vector& uPack
) const
{
    const entry* e = find(p);

    if (e && !e->admitted)
    {
        const scalar inward = (U - uPack) & e->direction;
        if (inward > 0)
        {
            return U - inward*e->direction;
        }
    }
    return U;
}


template<class CloudType>
Foam::vector Foam::ParcelEntries<CloudType>::limitedCorrection
(
    const fvMesh& mesh,
    const parcelType& p,
    const vector& dU,
    const scalar deltaT
) const
{
    const point x = p.position();
    const label celli = p.cell();
    const entry* e = find(p);

    if (e && e->pushedTo >= 0)
    {
        // Pushed on: just into the face neighbour it makes room in (the
        // two hexahedra form a convex block, so the straight move toward
        // the neighbour's centre crosses only their common face)
        vector on = mesh.cellCentres()[e->pushedTo] - x;
        on /= max(mag(on), VSMALL);
        const scalar enter =
            cellFaceGeometry::entryDistance(mesh, e->pushedTo, x, on);
        const scalar leave =
            cellFaceGeometry::exitDistance(mesh, e->pushedTo, x, on);
        return (enter + 0.01*(leave - enter))/deltaT*on;
    }

    if (e && !e->admitted && (e->from >= 0 || e->remote >= 0))
    {
        // Refused: back into the cell it came from (here or on another
        // processor), aiming at its centre (a face or an edge/corner
        // neighbour), and not beyond it
        const bool here = e->from >= 0;
        vector back = fromCentre(mesh, *e) - x;
        back /= max(mag(back), VSMALL);

        const scalar enter =
            here
          ? cellFaceGeometry::entryDistance(mesh, e->from, x, back)
          : cellFaceGeometry::entryDistance(origins_[e->remote].faces, x, back);
        const scalar leave =
            here
          ? cellFaceGeometry::exitDistance(mesh, e->from, x, back)
          : cellFaceGeometry::exitDistance(origins_[e->remote].faces, x, back);

        const scalar backTravel =
            min
            (
                max((dU & back)*deltaT, enter + 0.01*(leave - enter)),
                enter + 0.99*(leave - enter)
            );

        return
            trackLength
            (
                backTravel,
                here || exactTracks_
              ? -1
              : cellFaceGeometry::distanceToProcessorFace
                (
                    mesh, celli, x, back
                )
            )/deltaT*back;
    }

    if (e && !e->admitted)
    {
        // Refused, from a cell not known (an injected parcel that came in
        // through a processor face): back out of this cell the way it
        // came in, a little into the cell beyond
        const vector back = -e->direction;
        const scalar toFace = cellFaceGeometry::exitDistance(mesh, celli, x, back);
        const scalar cellSize = Foam::cbrt(mesh.V()[celli]);

        const scalar backTravel =
            min
            (
                max((dU & back)*deltaT, toFace + 0.01*cellSize),
                toFace + 0.49*cellSize
            );

        return
            trackLength
            (
                backTravel,
                Pstream::parRun() && !exactTracks_
              ? cellFaceGeometry::distanceToProcessorFace(mesh, celli, x, back)
              : -1
            )/deltaT*back;
    }

    // Otherwise the correction move stays in the parcel's cell
    const scalar travel = mag(dU)*deltaT;
    if (travel <= VSMALL)
    {
        return dU;
    }

    const scalar room = 0.99*cellFaceGeometry::exitDistance(mesh, celli, x, dU/mag(dU));

    return travel > room ? dU*room/travel : dU;
}


// ************************************************************************* //
