/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "boundedCoefficient.H"
#include "FlatOutput.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mppicCoefficients::interval::interval
(
    const scalar lower,
    const scalar upper,
    const bool lowerClosed,
    const bool upperClosed
)
:
    lower_(lower),
    upper_(upper),
    lowerClosed_(lowerClosed),
    upperClosed_(upperClosed)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::mppicCoefficients::interval::contains(const scalar value) const
{
    const bool aboveLower = lowerClosed_ ? value >= lower_ : value > lower_;
    const bool belowUpper = upperClosed_ ? value <= upper_ : value < upper_;

    return aboveLower && belowUpper;
}


Foam::mppicCoefficients::interval
Foam::mppicCoefficients::bounds::closed(const scalar lower, const scalar upper)
{
    return interval(lower, upper, true, true);
}


Foam::mppicCoefficients::interval
Foam::mppicCoefficients::bounds::open(const scalar lower, const scalar upper)
{
    return interval(lower, upper, false, false);
}


Foam::mppicCoefficients::interval
Foam::mppicCoefficients::bounds::closedOpen
(
    const scalar lower,
    const scalar upper
)
{
    return interval(lower, upper, true, false);
}


Foam::mppicCoefficients::interval
Foam::mppicCoefficients::bounds::openClosed
(
    const scalar lower,
    const scalar upper
)
{
    return interval(lower, upper, false, true);
}


Foam::mppicCoefficients::interval
Foam::mppicCoefficients::bounds::atLeast(const scalar lower)
{
    return interval(lower, GREAT, true, true);
}


Foam::mppicCoefficients::interval
Foam::mppicCoefficients::bounds::above(const scalar lower)
{
    return interval(lower, GREAT, false, true);
}


void Foam::mppicCoefficients::rangeError
(
    const dictionary& dict,
    const word& keyword,
    const scalar value,
    const interval& range
)
{
    FatalIOErrorInFunction(dict)
        << "Dictionary " << dict.name() << ", keyword " << keyword
        << ": value " << value << " is outside the allowed range "
        << range << exit(FatalIOError);
}


Foam::scalar Foam::mppicCoefficients::read
(
    const dictionary& dict,
    const word& keyword,
    const interval& range
)
{
    if (!dict.found(keyword, keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ": required keyword "
            << keyword << " is missing; allowed range " << range
            << exit(FatalIOError);
    }

    const scalar value = dict.get<scalar>(keyword, keyType::LITERAL);

    if (!range.contains(value))
    {
        rangeError(dict, keyword, value, range);
    }

    return value;
}


Foam::scalar Foam::mppicCoefficients::read
(
    const dictionary& dict,
    const word& keyword,
    const scalar defaultValue,
    const interval& range
)
{
    if (!dict.found(keyword, keyType::LITERAL))
    {
        return defaultValue;
    }

    return read(dict, keyword, range);
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

Foam::Ostream& Foam::mppicCoefficients::operator<<
(
    Ostream& os,
    const interval& range
)
{
    os  << (range.lowerClosed_ ? "[" : "(") << range.lower_ << ", ";

    if (range.upper_ >= GREAT)
    {
        os  << "inf)";
    }
    else
    {
        os  << range.upper_ << (range.upperClosed_ ? "]" : ")");
    }

    return os;
}


Foam::word Foam::mppicCoefficients::readChoice
(
    const dictionary& dict,
    const word& keyword,
    const word& deflt,
    const wordList& allowed
)
{
    const word value(dict.lookupOrDefault<word>(keyword, deflt));

    if (!allowed.found(value))
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ", keyword " << keyword
            << ": value " << value << " is not one of " << allowed
            << exit(FatalIOError);
    }
    return value;
}


void Foam::mppicCoefficients::checkKeywords
(
    const dictionary& dict,
    const wordList& validKeywords,
    const word& reader
)
{
    for (const entry& e : dict)
    {
        if (!validKeywords.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Dictionary " << dict.name() << ": unknown keyword "
                << e.keyword() << nl << reader << " reads "
                << flatOutput(validKeywords) << exit(FatalIOError);
        }
    }
}


// ************************************************************************* //
