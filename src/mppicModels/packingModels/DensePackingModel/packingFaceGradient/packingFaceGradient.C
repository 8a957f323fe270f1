/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "packingFaceGradient.H"
#include "cellFaceGeometry.H"

// * * * * * * * * * * * * * * * * Functions  * * * * * * * * * * * * * * * //

Foam::vector Foam::packingFaceGradient::at
(
    const fvMesh& mesh,
    const label celli,
    const point& position,
    const scalarField& values,
    const PtrList<scalarField>& coupledValues,
    const scalar boundaryValue
)
{
    const point& centre = mesh.cellCentres()[celli];
    const scalar value = values[celli];

    vector grad = Zero;

    for (const label facei : mesh.cells()[celli])
    {
        const vector n = cellFaceGeometry::outwardNormal(mesh, celli, facei);
        const point& faceCentre = mesh.faceCentres()[facei];

        // Half the cell's width across this face, and the point's weight
        const scalar half = (faceCentre - centre) & n;
        if (half <= VSMALL)
        {
            continue;
        }
        const scalar weight =
            max(scalar(0), 1 - ((faceCentre - position) & n)/(2*half));

        scalar across = boundaryValue;
        scalar distance = 2*half;

        if (mesh.isInternalFace(facei))
        {
            const label nbr = cellFaceGeometry::cellAcross(mesh, celli, facei);
            across = values[nbr];
            distance = (mesh.cellCentres()[nbr] - centre) & n;
        }
        else
        {
            const label patchi = mesh.boundaryMesh().whichPatch(facei);
            if (patchi < coupledValues.size() && coupledValues.set(patchi))
            {
                across =
                    coupledValues[patchi]
                    [
                        mesh.boundaryMesh()[patchi].whichFace(facei)
                    ];
            }
        }

        if (distance > VSMALL)
        {
            grad += weight*(across - value)/distance*n;
        }
    }

    return grad;
}


// ************************************************************************* //
