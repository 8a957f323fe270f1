/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "PackDrain.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::PackDrain::PackDrain(const fvMesh& mesh, const bool on)
:
    mesh_(mesh),
    on_(on),
    moved_(),
    solids_()
{
    // Made (or read, on a restart) at the time the run starts from
    if (on_)
    {
        drain();
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::volScalarField& Foam::PackDrain::drain() const
{
    if (!drain_)
    {
        drain_ = mesh_.getObjectPtr<volScalarField>("packDrain");
    }
    if (!drain_)
    {
        drain_ = new volScalarField
        (
            IOobject
            (
                "packDrain",
                mesh_.time().timeName(),
                mesh_,
                IOobject::READ_IF_PRESENT,
                IOobject::AUTO_WRITE
            ),
            mesh_,
            dimensionedScalar(dimVelocity, Zero),
            zeroGradientFvPatchScalarField::typeName
        );
        drain_->store();

        if (drain_->headerOk())
        {
            Info<< "PackDrain: the packs' drain read from "
                << drain_->objectPath() << endl;
        }
    }
    return *drain_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::PackDrain::startTally()
{
    const label nCells = mesh_.nCells();
    moved_.setSize(nCells);
    solids_.setSize(nCells);
    moved_ = Zero;
    solids_ = Zero;
}


void Foam::PackDrain::endTally(const scalar dt)
{
    if (!(dt > 0))
    {
        return;
    }

    volScalarField& d = drain();
    scalarField& drain = d.primitiveFieldRef();
    const scalar weight = min(dt/drainTime, scalar(1));
    forAll(drain, celli)
    {
        const scalar u =
            solids_[celli] > 0 ? moved_[celli]/(solids_[celli]*dt) : 0;
        drain[celli] += weight*(u - drain[celli]);
    }
    d.correctBoundaryConditions();
}


// ************************************************************************* //
