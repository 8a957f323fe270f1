/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "implicitDragBalance.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::Tuple2<Foam::vector, Foam::vector> Foam::implicitDragBalance
(
    CloudType& cloud,
    const vectorField& Uold,
    const volVectorField& Unew
)
{
    const scalarField& UCoeff = cloud.UCoeff();

    scalarField parcelMass(UCoeff.size(), Zero);
    for (const typename CloudType::parcelType& p : cloud)
    {
        parcelMass[p.cell()] += p.nParticle()*p.mass();
    }

    // The momentum each cell's parcels take: the gas's implicit part less
    // its explicit counterpart at the velocity the parcels saw
    vectorField dU(UCoeff.size(), Zero);
    vector given(Zero);
    vector undistributed(Zero);
    forAll(dU, celli)
    {
        const vector impulse(UCoeff[celli]*(Unew[celli] - Uold[celli]));
        if (parcelMass[celli] > 0)
        {
            dU[celli] = impulse/parcelMass[celli];
            given += impulse;
        }
        else
        {
            undistributed += impulse;
        }
    }

    for (typename CloudType::parcelType& p : cloud)
    {
        p.U() += dU[p.cell()];
    }

    reduce(given, sumOp<vector>());
    reduce(undistributed, sumOp<vector>());
    return Tuple2<vector, vector>(given, undistributed);
}


// ************************************************************************* //
