/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    cloudInputChecks::sizeDistributions: the parcel diameters of every
    injection model's sizeDistribution (OpenFOAM's distributionModels) are
    positive; ranges in cloudInputChecks.H.

\*---------------------------------------------------------------------------*/

#include "cloudInputChecks.H"
#include "boundedCoefficient.H"
#include "scalarList.H"
#include "vector2D.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{
namespace
{

using namespace mppicCoefficients;

//- minValue positive, maxValue not below it
void checkSizeRange(const dictionary& coeffs)
{
    const scalar minValue = read(coeffs, "minValue", bounds::above(0));
    read(coeffs, "maxValue", bounds::atLeast(minValue));
}


//- The size range (checkSizeRange) and the positive shape parameters of
//  a distribution
void checkSizeRangeAndShape
(
    const dictionary& coeffs,
    std::initializer_list<const char*> shapeParameters
)
{
    checkSizeRange(coeffs);
    for (const char* keyword : shapeParameters)
    {
        read(coeffs, keyword, bounds::above(0));
    }
}


//- Every element of a list of scalars within range
void checkEach
(
    const dictionary& coeffs,
    const word& keyword,
    const interval& range
)
{
    const scalarList values(coeffs.get<scalarList>(keyword));

    forAll(values, i)
    {
        if (!range.contains(values[i]))
        {
            FatalIOErrorInFunction(coeffs)
                << "Dictionary " << coeffs.name() << ", keyword " << keyword
                << ": element " << i << " of " << values << " is "
                << values[i] << ", outside the allowed range " << range
                << exit(FatalIOError);
        }
    }
}


//- general and binned: ((size frequency) ...), sizes ascending, positive
//  where the frequency is, frequencies not negative and not all zero
void checkSizeTable(const dictionary& coeffs)
{
    const word keyword("distribution");
    const List<vector2D> xy(coeffs.get<List<vector2D>>(keyword));

    auto rowError = [&](const label i, const char* why)
    {
        FatalIOErrorInFunction(coeffs)
            << "Dictionary " << coeffs.name() << ", keyword " << keyword
            << ": row " << i << " (size frequency) = " << xy[i] << ": "
            << why << exit(FatalIOError);
    };

    scalar sumFrequency = 0;

    forAll(xy, i)
    {
        const scalar size = xy[i].x();
        const scalar frequency = xy[i].y();

        if (frequency < 0)
        {
            rowError(i, "frequency outside the allowed range [0, inf)");
        }
        if (frequency > 0 && size <= 0)
        {
            rowError(i, "size outside the allowed range (0, inf)");
        }
        if (size < 0)
        {
            rowError(i, "size outside the allowed range [0, inf)");
        }
        if (i > 0 && size <= xy[i-1].x())
        {
            rowError(i, "sizes must ascend");
        }

        sumFrequency += frequency;
    }

    if (sumFrequency <= 0)
    {
        FatalIOErrorInFunction(coeffs)
            << "Dictionary " << coeffs.name() << ", keyword " << keyword
            << ": value " << xy << " has no positive frequency"
            << exit(FatalIOError);
    }
}


//- The coefficients of one sizeDistribution, by type
void checkSizeDistribution(const dictionary& sizeDict)
{
    const word type(sizeDict.get<word>("type"));
    const dictionary& coeffs = sizeDict.subOrEmptyDict(type + "Distribution");

    if (type == "fixedValue")
    {
        read(coeffs, "value", bounds::above(0));
    }
    else if (type == "uniform")
    {
        checkSizeRange(coeffs);
    }
    else if (type == "normal")
    {
        checkSizeRangeAndShape(coeffs, {"expectation", "variance"});
    }
    else if (type == "RosinRammler" || type == "massRosinRammler")
    {
        checkSizeRangeAndShape(coeffs, {"d", "n"});
    }
    else if (type == "exponential")
    {
        checkSizeRangeAndShape(coeffs, {"lambda"});
    }
    else if (type == "multiNormal")
    {
        checkSizeRange(coeffs);
        checkEach(coeffs, "variance", bounds::above(0));
        checkEach(coeffs, "strength", bounds::atLeast(0));
    }
    else if (type == "general" || type == "binned")
    {
        checkSizeTable(coeffs);
    }
}

} // End anonymous namespace
} // End namespace Foam


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * //

void Foam::cloudInputChecks::sizeDistributions
(
    const dictionary& cloudProperties
)
{
    forEachInjectionModel
    (
        cloudProperties,
        [](const dictionary& model)
        {
            if (model.isDict("sizeDistribution"))
            {
                checkSizeDistribution(model.subDict("sizeDistribution"));
            }
        }
    );
}


// ************************************************************************* //
