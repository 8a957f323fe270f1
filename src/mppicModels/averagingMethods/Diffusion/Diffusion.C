/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "Diffusion.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
Foam::diffusionSmoother Foam::AveragingMethods::Diffusion<Type>::readSmoother
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    namespace coeff = mppicCoefficients;

    const dictionary& coeffs = dict.subDict("diffusionCoeffs");
    coeff::checkKeywords(coeffs, {"bandwidth", "nSteps"}, "diffusion");

    const scalar bandwidth =
        coeff::read(coeffs, "bandwidth", coeff::bounds::above(0));

    // Range first (FatalIOError naming it), then as an integer
    coeff::read(coeffs, "nSteps", 3, coeff::bounds::atLeast(1));
    const label nSteps = coeffs.lookupOrDefault<label>("nSteps", 3);

    return diffusionSmoother(mesh, bandwidth, nSteps);
}


template<class Type>
void Foam::AveragingMethods::Diffusion<Type>::smoothNewDeposits()
{
    if (hasNewDeposits_)
    {
        smoother_.smooth(FieldField<Field, Type>::operator[](0));
        hasNewDeposits_ = false;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class Type>
Foam::AveragingMethods::Diffusion<Type>::Diffusion
(
    const IOobject& io,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    Basic<Type>(io, dict, mesh),
    smoother_(readSmoother(dict, mesh)),
    hasNewDeposits_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::AveragingMethods::Diffusion<Type>::add
(
    const barycentric& coordinates,
    const tetIndices& tetIs,
    const Type& value
)
{
    Basic<Type>::add(coordinates, tetIs, value);
    hasNewDeposits_ = true;
}


template<class Type>
void Foam::AveragingMethods::Diffusion<Type>::average()
{
    smoothNewDeposits();
    Basic<Type>::average();
}


template<class Type>
void Foam::AveragingMethods::Diffusion<Type>::average
(
    const AveragingMethod<scalar>& weight
)
{
    smoothNewDeposits();
    Basic<Type>::average(weight);
}


// ************************************************************************* //
