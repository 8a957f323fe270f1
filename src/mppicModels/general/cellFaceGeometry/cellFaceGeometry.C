/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "cellFaceGeometry.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

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
        const vector n = outwardNormal(mesh, celli, facei);

        const scalar along = direction & n;
        if (along > SMALL)
        {
            distance =
                min
                (
                    distance,
                    max(((mesh.faceCentres()[facei] - start) & n)/along, 0)
                );
        }
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
        const vector n = outwardNormal(mesh, celli, facei);

        const scalar along = direction & n;
        if (along < -SMALL)
        {
            distance =
                max(distance, ((mesh.faceCentres()[facei] - start) & n)/along);
        }
    }

    return distance;
}


// ************************************************************************* //
