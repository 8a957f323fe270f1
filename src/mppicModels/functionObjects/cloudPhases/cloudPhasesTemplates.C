/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "cloudPhases.H"
#include "kinematicCloud.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
bool Foam::functionObjects::cloudPhases::sumPhases(const vector& up)
{
    // Looked up through its abstract base (see packingMonitor)
    const CloudType* cloudPtr = dynamic_cast<const CloudType*>
    (
        &mesh_.lookupObject<kinematicCloud>(cloudName_)
    );
    if (!cloudPtr)
    {
        return false;
    }

    DynamicList<label> indices;
    DynamicList<phase> local;
    DynamicList<scalar> massHeight;
    for (const typename CloudType::parcelType& p : *cloudPtr)
    {
        if (p.typeId() < 1)
        {
            continue;
        }
        label i = indices.find(p.typeId());
        if (i < 0)
        {
            i = indices.size();
            indices.append(p.typeId());
            local.append(phase());
            massHeight.append(0);
        }
        const scalar m = p.nParticle()*p.mass();
        ++local[i].nParcels;
        local[i].mass += m;
        massHeight[i] += m*(p.position() & up);
    }

    reducePhases(indices, local, massHeight);

    return true;
}


// ************************************************************************* //
