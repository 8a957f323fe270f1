/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The keywords of <type>Coeffs read by the base, the one check of every
    entry of that dictionary (the model's, the base's and CapacityLimit's
    keywords), and the base's conserveMomentum.

\*---------------------------------------------------------------------------*/

#include "DensePackingModel.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

template<class CloudType>
const Foam::wordList
Foam::PackingModels::DensePackingModel<CloudType>::keywords
({
    "closePackFraction", "conserveMomentum", "holdSupportedPacks"
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
const Foam::dictionary&
Foam::PackingModels::DensePackingModel<CloudType>::checkedCoeffs
(
    const dictionary& dict,
    const word& type,
    const wordList& own
)
{
    const dictionary& coeffs = dict.subDict(type + "Coeffs");

    wordList valid(own);
    valid.append(keywords);
    valid.append(CapacityLimit<CloudType>::keywords);

    mppicCoefficients::checkKeywords(coeffs, valid, type);
    return coeffs;
}


template<class CloudType>
Foam::word
Foam::PackingModels::DensePackingModel<CloudType>::readConserveMomentum
(
    const dictionary& coeffs
)
{
    return mppicCoefficients::readChoice
    (
        coeffs, "conserveMomentum", "none", {"none", "packs", "gas"}
    );
}


// ************************************************************************* //
