/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "linearHatKernel.H"
#include "cellFaceGeometry.H"
#include "cyclicPolyPatch.H"
#include "hexMatcher.H"
#include "volMesh.H"

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

bool Foam::linearHatKernel::faceDelta
(
    const label celli,
    const label facei,
    const List<vectorField>& patchDeltas,
    vector& delta
) const
{
    const fvMesh& mesh = this->mesh();

    if (neighbours_.across(celli, facei) < 0)
    {
        return false;
    }

    if (mesh.isInternalFace(facei))
    {
        const label nbr = cellFaceGeometry::cellAcross(mesh, celli, facei);
        delta = mesh.cellCentres()[nbr] - mesh.cellCentres()[celli];
    }
    else
    {
        const label patchi = mesh.boundaryMesh().whichPatch(facei);
        delta =
            patchDeltas[patchi][facei - mesh.boundaryMesh()[patchi].start()];
    }
    return true;
}


Foam::label Foam::linearHatKernel::stepToward
(
    const label globalCell,
    const vector& dir
) const
{
    // The cell's faces: its own, or as the processor owning it sent them
    label across = -1;
    scalar bestCos = minStepCos;
    bool found = false;

    if (neighbours_.isLocal(globalCell))
    {
        const label celli = neighbours_.toLocal(globalCell);
        for (const label facei : mesh().cells()[celli])
        {
            const scalar cosAngle =
                cellFaceGeometry::outwardNormal(mesh(), celli, facei) & dir;
            if (cosAngle > bestCos)
            {
                bestCos = cosAngle;
                across = neighbours_.across(celli, facei);
                found = true;
            }
        }
    }
    else
    {
        const vectorField* normals = nullptr;
        const labelList* acrossFaces = nullptr;
        if (!halo_.remoteFaces(globalCell, normals, acrossFaces))
        {
            return -1;
        }
        forAll(*normals, j)
        {
            const scalar cosAngle = (*normals)[j] & dir;
            if (cosAngle > bestCos)
            {
                bestCos = cosAngle;
                across = (*acrossFaces)[j];
                found = true;
            }
        }
    }

    return found && across >= 0 ? across : globalCell;
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
    labelHashSet& unknown,
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
        const scalar distance =
            faceDelta(celli, faces[j], patchDeltas, delta)
          ? (delta & normals[j])
          : 0;

        towardFace_[facesPerCell*celli + j] =
            distance > VSMALL ? normals[j]/distance : vector::zero;

        const scalar toPlane =
            (mesh().faceCentres()[faces[j]] - mesh().cellCentres()[celli])
          & normals[j];
        towardOwnFace_[facesPerCell*celli + j] =
            toPlane > VSMALL ? normals[j]/toPlane : vector::zero;
    }

    for (label entry = 0; entry < blockSize; ++entry)
    {
        const FixedList<label, 3> steps
        ({
            entry/9 - 1, (entry/3)%3 - 1, entry%3 - 1
        });

        block_[blockSize*celli + entry] =
            blockCell(celli, steps, normals, unknown, nStopped);
    }
}


Foam::label Foam::linearHatKernel::blockCell
(
    const label celli,
    const FixedList<label, 3>& steps,
    const FixedList<vector, 6>& normals,
    labelHashSet& unknown,
    label& nStopped
) const
{
    // The orders of the three directions, the serial one (0 1 2) first: a
    // step from a cell of another processor is known only where that cell
    // is across a processor face of this one
    static const label orders[6][3] =
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

    label lastKnown = -1;
    for (const auto& order : orders)
    {
        label cellk = neighbours_.toGlobal(celli);
        for (const label i : order)
        {
            if (steps[i] != 0 && cellk >= 0)
            {
                const label next =
                    stepToward(cellk, normals[2*i + (steps[i] > 0 ? 0 : 1)]);
                if (next < 0)
                {
                    unknown.insert(cellk);
                    if (lastKnown < 0)
                    {
                        lastKnown = cellk;
                    }
                }
                cellk = next;
            }
        }
        if (cellk >= 0)
        {
            return cellk;
        }
    }

    ++nStopped;
    return lastKnown;
}


void Foam::linearHatKernel::addOtherCell(const label celli)
{
    hexahedral_[celli] = false;
    for (label entry = 0; entry < blockSize; ++entry)
    {
        block_[blockSize*celli + entry] = neighbours_.toGlobal(celli);
    }
    for (label j = 0; j < facesPerCell; ++j)
    {
        towardFace_[facesPerCell*celli + j] = Zero;
        towardOwnFace_[facesPerCell*celli + j] = Zero;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearHatKernel::linearHatKernel(const fvMesh& mesh)
:
    MeshObject<fvMesh, GeometricMeshObject, linearHatKernel>(mesh),
    block_(blockSize*mesh.nCells()),
    towardFace_(facesPerCell*mesh.nCells()),
    towardOwnFace_(facesPerCell*mesh.nCells()),
    hexahedral_(mesh.nCells(), true),
    neighbours_(coupledCellNeighbours::New(mesh)),
    halo_(mesh),
    ghostVolumes_()
{
    // Cell-to-cell vectors across the cyclic and processor patches
    List<vectorField> patchDeltas(mesh.boundary().size());
    forAll(mesh.boundary(), patchi)
    {
        if
        (
            isA<cyclicPolyPatch>(mesh.boundaryMesh()[patchi])
         || neighbours_.isProcessorPatch(patchi)
        )
        {
            patchDeltas[patchi] = mesh.boundary()[patchi].delta();
        }
    }

    // The blocks in global cell indices; where a step from a remote cell
    // needs faces not yet known, they are fetched and the blocks built
    // again (each pass one step further beyond the processor faces)
    const label nPasses = 3;
    label nStopped = 0;
    hexMatcher hex;
    for (label pass = 0; pass < nPasses; ++pass)
    {
        labelHashSet unknown;
        nStopped = 0;
        for (label celli = 0; celli < mesh.nCells(); ++celli)
        {
            if (hex.isA(mesh, celli))
            {
                addHexCell(celli, patchDeltas, unknown, nStopped);
            }
            else
            {
                addOtherCell(celli);
            }
        }

        if
        (
            pass == nPasses - 1
         || !returnReduce(unknown.size(), sumOp<label>())
        )
        {
            break;
        }
        halo_.fetchFaces(unknown.sortedToc());
    }

    // ... then cells of this processor by their own index, those of others
    // by nCells + their slot
    for (label& cellk : block_)
    {
        cellk =
            neighbours_.isLocal(cellk)
          ? neighbours_.toLocal(cellk)
          : mesh.nCells() + halo_.slot(cellk);
    }

    if (Pstream::parRun())
    {
        halo_.finalise();
        halo_.ghostValues(mesh.V().field(), ghostVolumes_);

        reduce(nStopped, sumOp<label>());
        if (nStopped)
        {
            Info<< "linearHatKernel: " << nStopped << " kernel block "
                << "entries stop at the last cell known" << endl;
        }
    }
}


// ************************************************************************* //
