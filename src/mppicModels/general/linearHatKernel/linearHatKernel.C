/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "linearHatKernel.H"
#include "cellFaceGeometry.H"
#include "cyclicPolyPatch.H"
#include "processorPolyPatch.H"
#include "hexMatcher.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(linearHatKernel, 0);
}

#include "linearHatKernelBlock.H"

namespace
{
    //- Smallest cosine between a face normal and a step direction
    const Foam::scalar minStepCos = 0.5;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::linearHatKernel::cellAcross
(
    const label celli,
    const label facei,
    const List<vectorField>& patchDeltas,
    vector& delta
) const
{
    const fvMesh& mesh = this->mesh();

    if (mesh.isInternalFace(facei))
    {
        const label nbr = cellFaceGeometry::cellAcross(mesh, celli, facei);
        delta = mesh.cellCentres()[nbr] - mesh.cellCentres()[celli];
        return nbr;
    }

    const label patchi = mesh.boundaryMesh().whichPatch(facei);
    const polyPatch& pp = mesh.boundaryMesh()[patchi];

    if (patchGhostStart_[patchi] >= 0)
    {
        const label patchFacei = facei - pp.start();
        delta = patchDeltas[patchi][patchFacei];
        return mesh.nCells() + patchGhostStart_[patchi] + patchFacei;
    }

    if (!isA<cyclicPolyPatch>(pp))
    {
        return -1;
    }

    const cyclicPolyPatch& cyclic = refCast<const cyclicPolyPatch>(pp);
    if (!cyclic.parallel())
    {
        return -1;
    }

    const label patchFacei = facei - pp.start();
    delta = patchDeltas[patchi][patchFacei];
    return cyclic.neighbPatch().faceCells()[patchFacei];
}


Foam::label Foam::linearHatKernel::stepToward
(
    const label celli,
    const vector& dir,
    const List<vectorField>& patchDeltas
) const
{
    const fvMesh& mesh = this->mesh();

    label bestFace = -1;
    scalar bestCos = minStepCos;
    for (const label facei : mesh.cells()[celli])
    {
        const scalar cosAngle =
            cellFaceGeometry::outwardNormal(mesh, celli, facei) & dir;
        if (cosAngle > bestCos)
        {
            bestCos = cosAngle;
            bestFace = facei;
        }
    }

    if (bestFace < 0)
    {
        return celli;
    }

    vector delta;
    const label nbr = cellAcross(celli, bestFace, patchDeltas, delta);
    return nbr < 0 ? celli : nbr;
}


Foam::FixedList<Foam::label, 6>
Foam::linearHatKernel::facePairs(const label celli) const
{
    const labelList& cellFaces = mesh().cells()[celli];
    const faceList& faces = mesh().faces();

    auto shareAPoint = [&](const label facea, const label faceb)
    {
        for (const label pointi : faces[facea])
        {
            if (faces[faceb].found(pointi))
            {
                return true;
            }
        }
        return false;
    };

    FixedList<label, 6> ordered(-1);
    boolList used(facesPerCell, false);
    label n = 0;
    for (label i = 0; i < facesPerCell; ++i)
    {
        if (used[i])
        {
            continue;
        }
        for (label j = i + 1; j < facesPerCell; ++j)
        {
            if (!used[j] && !shareAPoint(cellFaces[i], cellFaces[j]))
            {
                used[i] = used[j] = true;
                ordered[n++] = cellFaces[i];
                ordered[n++] = cellFaces[j];
                break;
            }
        }
    }
    return ordered;
}


void Foam::linearHatKernel::addHexCell
(
    const label celli,
    const List<vectorField>& patchDeltas,
    label& nStopped
)
{
    const FixedList<label, 6> faces = facePairs(celli);
    if (faces.found(-1))
    {
        addOtherCell(celli);
        return;
    }

    // Faces 2*i (step +1) and 2*i + 1 (step -1) along direction i
    FixedList<vector, 6> normals;
    for (label j = 0; j < facesPerCell; ++j)
    {
        normals[j] = cellFaceGeometry::outwardNormal(mesh(), celli, faces[j]);

        vector delta(Zero);
        const label nbr = cellAcross(celli, faces[j], patchDeltas, delta);
        const scalar distance = nbr < 0 ? 0 : (delta & normals[j]);

        towardFace_[facesPerCell*celli + j] =
            distance > VSMALL ? normals[j]/distance : vector::zero;
    }

    for (label entry = 0; entry < blockSize; ++entry)
    {
        const FixedList<label, 3> steps
        ({
            entry/9 - 1, (entry/3)%3 - 1, entry%3 - 1
        });

        block_[blockSize*celli + entry] =
            blockCell(celli, steps, normals, patchDeltas, nStopped);
    }
}


Foam::label Foam::linearHatKernel::blockCell
(
    const label celli,
    const FixedList<label, 3>& steps,
    const FixedList<vector, 6>& normals,
    const List<vectorField>& patchDeltas,
    label& nStopped
) const
{
    const label nCells = mesh().nCells();

    // The orders of the three directions, the serial one (0 1 2) first
    static const label orders[6][3] =
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

    label stopped = -1;
    for (const auto& order : orders)
    {
        label cellk = celli;
        bool atGhost = false;
        for (const label i : order)
        {
            if (steps[i] == 0)
            {
                continue;
            }
            if (atGhost)
            {
                // A ghost has no faces here: no further step from it
                atGhost = false;
                cellk = -1;
                break;
            }
            const vector& dir = normals[2*i + (steps[i] > 0 ? 0 : 1)];
            cellk = stepToward(cellk, dir, patchDeltas);
            atGhost = cellk >= nCells;
            if (atGhost && stopped < 0)
            {
                stopped = cellk;
            }
        }
        if (cellk >= 0)
        {
            return cellk;
        }
    }

    ++nStopped;
    return stopped;
}


void Foam::linearHatKernel::addOtherCell(const label celli)
{
    hexahedral_[celli] = false;
    for (label entry = 0; entry < blockSize; ++entry)
    {
        block_[blockSize*celli + entry] = celli;
    }
    for (label j = 0; j < facesPerCell; ++j)
    {
        towardFace_[facesPerCell*celli + j] = Zero;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearHatKernel::linearHatKernel(const fvMesh& mesh)
:
    MeshObject<fvMesh, GeometricMeshObject, linearHatKernel>(mesh),
    block_(blockSize*mesh.nCells()),
    towardFace_(facesPerCell*mesh.nCells()),
    hexahedral_(mesh.nCells(), true),
    ghostPatches_(),
    patchGhostStart_(mesh.boundary().size(), -1),
    nGhosts_(0),
    ghostVolumes_()
{
    setGhostSlots();

    // Cell-to-cell vectors across the cyclic and processor patches
    List<vectorField> patchDeltas(mesh.boundary().size());
    forAll(mesh.boundary(), patchi)
    {
        if
        (
            isA<cyclicPolyPatch>(mesh.boundaryMesh()[patchi])
         || patchGhostStart_[patchi] >= 0
        )
        {
            patchDeltas[patchi] = mesh.boundary()[patchi].delta();
        }
    }

    label nStopped = 0;
    hexMatcher hex;
    for (label celli = 0; celli < mesh.nCells(); ++celli)
    {
        if (hex.isA(mesh, celli))
        {
            addHexCell(celli, patchDeltas, nStopped);
        }
        else
        {
            addOtherCell(celli);
        }
    }

    if (Pstream::parRun())
    {
        ghostValues(mesh.V().field(), ghostVolumes_);

        reduce(nStopped, sumOp<label>());
        if (nStopped)
        {
            Info<< "linearHatKernel: " << nStopped << " kernel block "
                << "entries across two processor faces stop at the first"
                << endl;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::linearHatKernel::evaluate
(
    const point& position,
    const label celli,
    weights& w
) const
{
    const vector offset = position - mesh().cellCentres()[celli];
    const label firstFace = facesPerCell*celli;

    // Along each direction: the fraction t toward the chosen face and the
    // block step to the cell across it
    FixedList<scalar, 3> t;
    FixedList<label, 3> step;
    for (label i = 0; i < 3; ++i)
    {
        const scalar towardPlus = offset & towardFace_[firstFace + 2*i];
        if (towardPlus > 0)
        {
            t[i] = min(towardPlus, scalar(1));
            step[i] = blockStride[i];
        }
        else
        {
            const scalar towardMinus =
                offset & towardFace_[firstFace + 2*i + 1];
            t[i] = min(max(towardMinus, scalar(0)), scalar(1));
            step[i] = -blockStride[i];
        }
    }

    // Corner k takes the far side along direction i when bit i of k is set
    const label firstEntry = blockSize*celli + blockCentre;
    for (label k = 0; k < 8; ++k)
    {
        label entry = firstEntry;
        scalar weight = 1;
        for (label i = 0; i < 3; ++i)
        {
            if (k & (1 << i))
            {
                entry += step[i];
                weight *= t[i];
            }
            else
            {
                weight *= 1 - t[i];
            }
        }
        w.cells[k] = block_[entry];
        w.values[k] = weight;
    }
}


// ************************************************************************* //
