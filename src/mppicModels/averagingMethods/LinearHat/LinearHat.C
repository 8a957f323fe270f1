/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "LinearHat.H"
#include "fvcGrad.H"
#include "zeroGradientFvPatchField.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class Type>
Foam::AveragingMethods::LinearHat<Type>::LinearHat
(
    const IOobject& io,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    LinearHat<Type>(io, dict, mesh, false, false)
{}


template<class Type>
Foam::AveragingMethods::LinearHat<Type>::LinearHat
(
    const IOobject& io,
    const dictionary& dict,
    const fvMesh& mesh,
    const bool cornerNodes,
    const bool depositAtCellCentres
)
:
    AveragingMethod<Type>(io, dict, mesh, labelList(1, mesh.nCells())),
    kernel_(linearHatKernel::New(mesh)),
    data_(FieldField<Field, Type>::operator[](0)),
    dataGrad_(mesh.nCells()),
    ghostDeposits_(kernel_.nGhosts(), Zero),
    ghostValues_(kernel_.nGhosts(), Zero),
    cornerNodes_(cornerNodes),
    depositAtCellCentres_(depositAtCellCentres)
{}


template<class Type>
Foam::AveragingMethods::LinearHat<Type>::LinearHat
(
    const LinearHat<Type>& am
)
:
    AveragingMethod<Type>(am),
    kernel_(am.kernel_),
    data_(FieldField<Field, Type>::operator[](0)),
    dataGrad_(am.dataGrad_),
    ghostDeposits_(am.ghostDeposits_),
    ghostValues_(am.ghostValues_),
    cornerNodes_(am.cornerNodes_),
    depositAtCellCentres_(am.depositAtCellCentres_)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
void Foam::AveragingMethods::LinearHat<Type>::updateGrad()
{
    kernel_.ghostValues(data_, ghostValues_);

    // The gradient as basic computes it: zero gradient at the boundaries
    GeometricField<Type, fvPatchField, volMesh> cellData
    (
        IOobject
        (
            "LinearHat::cellData",
            this->mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        this->mesh_,
        dimensioned<Type>(dimless, Zero),
        zeroGradientFvPatchField<Type>::typeName
    );
    cellData.primitiveFieldRef() = data_;
    cellData.correctBoundaryConditions();
    dataGrad_ = fvc::grad(cellData)->primitiveField();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::AveragingMethods::LinearHat<Type>::add
(
    const barycentric& coordinates,
    const tetIndices& tetIs,
    const Type& value
)
{
    const point x =
        depositAtCellCentres_
      ? this->mesh_.cellCentres()[tetIs.cell()]
      : position(coordinates, tetIs);
    if (cornerNodes_)
    {
        kernel_.template deposit<Type, linearHatKernel::cornerNodeWeights>
        (
            data_, ghostDeposits_, x, tetIs.cell(), value
        );
    }
    else
    {
        kernel_.deposit(data_, ghostDeposits_, x, tetIs.cell(), value);
    }
}


template<class Type>
Type Foam::AveragingMethods::LinearHat<Type>::interpolate
(
    const barycentric& coordinates,
    const tetIndices& tetIs
) const
{
    const point x = position(coordinates, tetIs);
    return
        cornerNodes_
      ? kernel_.template interpolate<Type, linearHatKernel::cornerNodeWeights>
        (
            data_, ghostValues_, x, tetIs.cell()
        )
      : kernel_.interpolate(data_, ghostValues_, x, tetIs.cell());
}


template<class Type>
typename Foam::AveragingMethods::LinearHat<Type>::TypeGrad
Foam::AveragingMethods::LinearHat<Type>::interpolateGrad
(
    const barycentric& coordinates,
    const tetIndices& tetIs
) const
{
    return dataGrad_[tetIs.cell()];
}


template<class Type>
void Foam::AveragingMethods::LinearHat<Type>::average()
{
    kernel_.addGhostDeposits(data_, ghostDeposits_);
    AveragingMethod<Type>::average();
}


template<class Type>
void Foam::AveragingMethods::LinearHat<Type>::average
(
    const AveragingMethod<scalar>& weight
)
{
    kernel_.addGhostDeposits(data_, ghostDeposits_);
    AveragingMethod<Type>::average(weight);
}


template<class Type>
Foam::tmp<Foam::Field<Type>>
Foam::AveragingMethods::LinearHat<Type>::primitiveField() const
{
    return tmp<Field<Type>>(data_);
}


// ************************************************************************* //
