/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "polydisperseCorrection.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::polydisperseCorrection::keyword
(
    "polydisperseCorrection"
);

const Foam::wordList Foam::polydisperseCorrection::names({"none", "Beetstra"});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polydisperseCorrection::polydisperseCorrection
(
    const dictionary& coeffs
)
:
    active_
    (
        mppicCoefficients::readChoice(coeffs, keyword, names[0], names)
     == names[1]
    ),
    sumD3_(),
    sumD2_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polydisperseCorrection::reset(const label nCells)
{
    sumD3_.setSize(nCells);
    sumD3_ = Zero;
    sumD2_.setSize(nCells);
    sumD2_ = Zero;
}


Foam::scalar Foam::polydisperseCorrection::meanDiameter
(
    const label celli,
    const scalar dOwn
) const
{
    if (celli >= sumD2_.size() || sumD2_[celli] <= 0)
    {
        return dOwn;
    }
    return sumD3_[celli]/sumD2_[celli];
}


Foam::scalar Foam::polydisperseCorrection::toMeanDiameter
(
    dragCorrelations::dragState& s,
    const label celli
) const
{
    const scalar dMean = meanDiameter(celli, s.d);
    const scalar y = s.d/dMean;
    s.d = dMean;
    return dragCorrelations::beetstraPolydisperseScale(s.alphag, y);
}


// ************************************************************************* //
