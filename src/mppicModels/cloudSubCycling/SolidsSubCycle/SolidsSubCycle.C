/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "SolidsSubCycle.H"
#include "CloudSourceSum.H"
#include "boundedCoefficient.H"
#include "subCycleTime.H"
#include "boundBox.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::SolidsSubCycle<CloudType>::readMaxSubCycles
(
    const dictionary& dict
)
{
    const label n = dict.lookupOrDefault<label>("maxSubCycles", 1000);
    if (n < 1)
    {
        mppicCoefficients::rangeError
        (
            dict,
            "maxSubCycles",
            n,
            mppicCoefficients::bounds::atLeast(1)
        );
    }
    return n;
}


template<class CloudType>
Foam::tmp<Foam::vectorField> Foam::SolidsSubCycle<CloudType>::cellExtents
(
    const fvMesh& mesh
)
{
    tmp<vectorField> textent(new vectorField(mesh.nCells()));
    vectorField& extent = textent.ref();

    forAll(extent, celli)
    {
        extent[celli] =
            boundBox(mesh.points(), mesh.cellPoints(celli), false).span();
    }
    return textent;
}


template<class CloudType>
void Foam::SolidsSubCycle<CloudType>::evolveSubCycles(const label nSubCycles)
{
    Time& runTime = const_cast<Time&>(cloud_.mesh().time());

    CloudSourceSum sources;

    for
    (
        subCycleTime subCycle(runTime, nSubCycles);
        !(++subCycle).end();
        /* nothing */
    )
    {
        cloud_.evolve();
        sources.add(cloud_);
    }

    sources.store(cloud_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::SolidsSubCycle<CloudType>::SolidsSubCycle(CloudType& cloud)
:
    cloud_(cloud),
    settings_
    (
        cloud.particleProperties().subOrEmptyDict("solidsSubCycling")
    ),
    active_(settings_.lookupOrDefault("active", false)),
    CFL_
    (
        mppicCoefficients::read
        (
            settings_,
            "CFL",
            0.1,
            mppicCoefficients::bounds::openClosed(0, 1)
        )
    ),
    relaxationTimeFactor_
    (
        mppicCoefficients::read
        (
            settings_,
            "relaxationTimeFactor",
            0.1,
            mppicCoefficients::bounds::above(0)
        )
    ),
    maxSubCycles_(readMaxSubCycles(settings_)),
    cellExtent_()
{
    mppicCoefficients::checkKeywords
    (
        settings_,
        {"active", "CFL", "relaxationTimeFactor", "maxSubCycles"},
        "solidsSubCycling"
    );

    if (active_)
    {
        cellExtent_ = cellExtents(cloud.mesh());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
typename Foam::SolidsSubCycle<CloudType>::limit
Foam::SolidsSubCycle<CloudType>::solidsTimeStep(const scalar dtGas) const
{
    const volScalarField& mu = cloud_.mu();

    scalar dtCourant = GREAT;
    scalar dtResponse = GREAT;

    for (const auto& p : cloud_)
    {
        const vector& extent = cellExtent_[p.cell()];
        for (direction i = 0; i < vector::nComponents; ++i)
        {
            const scalar speed = mag(p.U()[i]);
            if (speed*GREAT > extent[i])
            {
                dtCourant = min(dtCourant, CFL_*extent[i]/speed);
            }
        }

        const scalar responseTime = p.rho()*sqr(p.d())/(18*mu[p.cell()]);
        dtResponse = min(dtResponse, relaxationTimeFactor_*responseTime);
    }

    reduce(dtCourant, minOp<scalar>());
    reduce(dtResponse, minOp<scalar>());

    limit result{dtGas, "gas step"};
    if (dtCourant < result.deltaT)
    {
        result = limit{dtCourant, "CFL"};
    }
    if (dtResponse < result.deltaT)
    {
        result = limit{dtResponse, "response time"};
    }
    return result;
}


template<class CloudType>
Foam::label Foam::SolidsSubCycle<CloudType>::nSubCycles
(
    const scalar dtGas
) const
{
    const scalar ratio = dtGas/solidsTimeStep(dtGas).deltaT;

    // A ratio a rounding error above an integer needs no extra sub-step
    const label n = label(std::ceil(ratio*(1 - 1e-12)));

    return max(1, min(n, maxSubCycles_));
}


template<class CloudType>
void Foam::SolidsSubCycle<CloudType>::evolve()
{
    if (!active_)
    {
        cloud_.evolve();
        return;
    }

    const scalar dtGas = cloud_.mesh().time().deltaTValue();
    const limit solids = solidsTimeStep(dtGas);
    const label n = nSubCycles(dtGas);

    Info<< "Solids sub-cycling: " << n << " sub-step(s) of "
        << dtGas/n << " s, limited by " << solids.criterion
        << " (dt_sol = " << solids.deltaT << " s)";
    if (n == maxSubCycles_ && dtGas/solids.deltaT > n)
    {
        Info<< ", capped at maxSubCycles";
    }
    Info<< endl;

    if (n == 1)
    {
        cloud_.evolve();
    }
    else
    {
        evolveSubCycles(n);
    }
}


// ************************************************************************* //
