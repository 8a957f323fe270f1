/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The correction tracks of LeanMPPICCloud: each parcel moved by its whole
    correction velocity over what is left of the step, also after it
    crossed to another processor (see the class description).

\*---------------------------------------------------------------------------*/

#include "LeanMPPICCloud.H"
#include "processorPolyPatch.H"
#include "PstreamBuffers.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
template<class TrackCloudType>
bool Foam::LeanMPPICCloud<CloudType>::correctionTrack
(
    parcelType& p,
    TrackCloudType& cloud,
    typename parcelType::trackingData& td,
    const scalar trackTime
)
{
    // The velocity and age the parcel brings to this part of its track: on
    // a processor it crossed to, its velocity already holds the share of
    // the correction it has moved with
    const vector U = p.U();
    const scalar fraction = p.stepFraction();
    const scalar age = p.age();

    // The tracking layer moves the parcel by trackTime*U per unit of step
    // fraction: the correction itself, whatever fraction is left
    p.U() = p.UCorrect();

    const bool keep = p.trackingLayer::move(cloud, td, trackTime);

    p.U() = U + (p.stepFraction() - fraction)*p.UCorrect();
    p.age() = age;

    return keep;
}


template<class CloudType>
template<class TrackCloudType>
Foam::label Foam::LeanMPPICCloud<CloudType>::trackCorrections
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td,
    const scalar trackTime
)
{
    const polyMesh& mesh = this->pMesh();
    const globalMeshData& meshData = mesh.globalData();

    // The processors next to this one, and each one's place in that list
    const labelList& neighbours = meshData[Pstream::myProcNo()];
    labelList neighbourIndex(Pstream::nProcs(), -1);
    forAll(neighbours, i)
    {
        neighbourIndex[neighbours[i]] = i;
    }

    // Processor patches, and for each, the index of the same boundary in
    // the neighbour's list of processor patches
    const labelList& processorPatches = meshData.processorPatches();
    const labelList& patchOnNeighbour = meshData.processorPatchNeighbours();

    // The parcels to track in this round: all, then those that arrived
    DynamicList<parcelType*> toTrack(this->size());
    for (parcelType& p : *this)
    {
        p.stepFraction() = 0;
        toTrack.append(&p);
    }

    label nCrossed = 0;

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);

    // Rounds: every parcel tracks on until it ends its step, leaves the
    // domain or reaches a processor boundary; the last go to the
    // neighbour, which goes on with them in the next round
    while (true)
    {
        List<IDLList<parcelType>> leaving(neighbours.size());
        List<DynamicList<label>> arrivalPatches(neighbours.size());

        for (parcelType* pPtr : toTrack)
        {
            parcelType& p = *pPtr;

            if (!correctionTrack(p, cloud, td, trackTime))
            {
                this->deleteParticle(p);
            }
            else if (td.switchProcessor)
            {
                const label patchi = p.patch();
                const label i = neighbourIndex
                [
                    refCast<const processorPolyPatch>
                    (
                        mesh.boundaryMesh()[patchi]
                    ).neighbProcNo()
                ];

                p.prepareForParallelTransfer();
                leaving[i].append(this->remove(&p));
                arrivalPatches[i].append(patchOnNeighbour[patchi]);
                ++nCrossed;
            }
        }

        toTrack.clear();

        if (!Pstream::parRun())
        {
            break;
        }

        buffers.clear();

        forAll(leaving, i)
        {
            if (leaving[i].size())
            {
                UOPstream toNeighbour(neighbours[i], buffers);
                toNeighbour << arrivalPatches[i] << leaving[i];
            }
        }

        labelList bytesFrom(Pstream::nProcs());
        buffers.finishedSends(bytesFrom);

        bool anyCrossing = false;
        for (const label nBytes : bytesFrom)
        {
            anyCrossing = anyCrossing || nBytes > 0;
        }
        if (!returnReduce(anyCrossing, orOp<bool>()))
        {
            break;
        }

        for (const label proci : neighbours)
        {
            if (bytesFrom[proci])
            {
                UIPstream fromNeighbour(proci, buffers);
                const labelList arrivals(fromNeighbour);
                IDLList<parcelType> arrived
                (
                    fromNeighbour,
                    typename parcelType::iNew(mesh)
                );

                label k = 0;
                for (parcelType& p : arrived)
                {
                    p.correctAfterParallelTransfer
                    (
                        processorPatches[arrivals[k++]],
                        td
                    );
                    toTrack.append(arrived.remove(&p));
                    this->addParticle(toTrack.last());
                }
            }
        }
    }

    return returnReduce(nCrossed, sumOp<label>());
}


// ************************************************************************* //
