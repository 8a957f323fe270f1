/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "cloudInputChecks.H"
#include "boundedCoefficient.H"
#include "liquidProperties.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * //

void Foam::cloudInputChecks::statisticalWeights
(
    const dictionary& cloudProperties
)
{
    const dictionary& injectors =
        cloudProperties.subOrEmptyDict("subModels")
       .subOrEmptyDict("injectionModels");

    for (const entry& e : injectors)
    {
        if (e.isDict() && e.dict().found("nParticle"))
        {
            mppicCoefficients::read
            (
                e.dict(),
                "nParticle",
                mppicCoefficients::bounds::above(0)
            );
        }
    }
}


void Foam::cloudInputChecks::liquids(const dictionary& thermophysicalProperties)
{
    if (!thermophysicalProperties.found("liquids"))
    {
        return;
    }

    const dictionary& liquidsDict =
        thermophysicalProperties.subDict("liquids");

    for (const entry& e : liquidsDict)
    {
        const word& name = e.keyword();

        if (!liquidProperties::ConstructorTablePtr_->found(name))
        {
            FatalIOErrorInFunction(liquidsDict)
                << "Dictionary " << liquidsDict.name() << ", keyword "
                << name << ": not a liquid of OpenFOAM's liquid-properties"
                << " database, which has "
                << liquidProperties::ConstructorTablePtr_->sortedToc()
                << exit(FatalIOError);
        }
    }
}


// ************************************************************************* //
