/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    MfixSnider's velocity correction of one parcel: the limited impulse,
    the optional damping and release, the capacity limit, the reactions
    and the boundary rule (see MfixSnider.H). The velocity the parcel
    keeps goes to keepAfterTrack, which writes it once in the step
    (DensePackingModel.H: at once, or with conserveMomentum at the end of
    the step with the packs' reactions).

\*---------------------------------------------------------------------------*/

#include "cellFaceGeometry.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::vector Foam::PackingModels::MfixSnider<CloudType>::velocityCorrection
(
    typename CloudType::parcelType& p,
    const scalar deltaT
) const
{
    const label celli = p.cell();

    const vector tauGrad = stressGradient_.at(p.position(), celli);

    const vector dU =
        rules_.impulseVelocity(tauGrad, p.rho(), cellAlpha_[celli], deltaT);

    vector Unew =
        rules_.correctedVelocity
        (
            p.U(), (*previousMeanVelocity_)[celli], dU, tauGrad
        );

    // The stress's share of the change (the limiter's), before the
    // damping, which relaxes toward the cell's own mean
    const vector dStress = Unew - p.U();

    if (collisionDamping_)
    {
        Unew = damping_.damped(Unew, celli, deltaT);
    }

    vector kept = Unew;
    vector move = Unew - p.U();

    // The release of an over-packed cell: a displacement down the stress
    // gradient that the parcel does not keep as velocity
    vector release =
        rules_.releaseVelocity(tauGrad, cellAlpha_[celli], 0.5*p.d(), deltaT);

    const typename ParcelEntries<CloudType>::entry* entered =
        this->capacityLimit() ? this->limit().entries().find(p) : nullptr;
    const bool refused = entered && !entered->admitted;

    if (this->capacityLimit())
    {
        // As coloringFunction's capacity limit (CapacityLimit): the
        // parcel keeps no velocity into a cell that refused it relative to
        // that cell's parcels (their mean of the previous step), and the
        // correction move stays in the cell the parcel may be in
        if (refused)
        {
            release = Zero;
        }
        move =
            this->limit().move
            (
                p,
                Unew - p.U(),
                (*previousMeanVelocity_)[celli],
                deltaT,
                kept,
                release
            );
    }
    else
    {
        move += release;
    }

    if (this->conserveMomentum())
    {
        // The pack that turned the parcel takes the opposite impulse at
        // the end of the step: the cell that refused it, else the denser
        // neighbour the stress gradient points at (none at a wall: the
        // wall takes it)
        const vector dPack = kept - Unew + dStress;
        const label pack =
            refused ? this->globalCell(p) : packCell(p, tauGrad);
        if (pack >= 0 && magSqr(dPack) > 0)
        {
            this->recordReaction(p, pack, dPack);
        }
    }

    if (this->capacityLimit())
    {
        // A parcel the correction presses through a wall, inlet or outlet
        // stays in its cell (the move above) and keeps no velocity into
        // that boundary, as into a refusing cell; the boundary takes the
        // impulse. MFiX reflects a parcel that crossed a wall before it
        // forms the mean solids velocity; without this the mean of the
        // parcels held at a wall points into it, and the limiter's
        // reflection about that mean drives them faster into the wall
        // every step
        kept =
            cellFaceGeometry::withoutVelocityIntoBoundary
            (
                this->owner().mesh(),
                celli,
                p.position(),
                (Unew - p.U() + release)*deltaT,
                kept
            );
    }

    this->recordVelocityChange(p, kept - p.U());

    if (this->capacityLimit() || magSqr(release) > 0)
    {
        // The correction track adds the move to the velocity after it
        this->keepAfterTrack(p, kept, move);
    }
    return move;
}


// ************************************************************************* //
