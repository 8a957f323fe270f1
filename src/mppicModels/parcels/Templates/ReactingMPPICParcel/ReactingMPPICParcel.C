/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "ReactingMPPICParcel.H"

// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class ParcelType>
template<class TrackCloudType>
void Foam::ReactingMPPICParcel<ParcelType>::calc
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar dt
)
{
    // The correction tracks of the damping and packing steps only move the
    // parcel by its correction velocity
    if (td.part() == trackingData::tpLinearTrack)
    {
        ParcelType::calc(cloud, td, dt);
    }
}


// ************************************************************************* //
