/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "LinearHat.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class Type>
Foam::AveragingMethods::LinearHat<Type>::LinearHat
(
    const IOobject& io,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    Basic<Type>(io, dict, mesh),
    kernel_(linearHatKernel::New(mesh))
{}


template<class Type>
Foam::AveragingMethods::LinearHat<Type>::LinearHat
(
    const LinearHat<Type>& am
)
:
    Basic<Type>(am),
    kernel_(am.kernel_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::AveragingMethods::LinearHat<Type>::add
(
    const barycentric& coordinates,
    const tetIndices& tetIs,
    const Type& value
)
{
    kernel_.deposit
    (
        cellDensity(),
        position(coordinates, tetIs),
        tetIs.cell(),
        value
    );
}


template<class Type>
Type Foam::AveragingMethods::LinearHat<Type>::interpolate
(
    const barycentric& coordinates,
    const tetIndices& tetIs
) const
{
    return kernel_.interpolate
    (
        FieldField<Field, Type>::operator[](0),
        position(coordinates, tetIs),
        tetIs.cell()
    );
}


// ************************************************************************* //
