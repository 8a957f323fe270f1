/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "sniderStressGradient.H"
#include "gaussGrad.H"
#include "linear.H"
#include "calculatedFvPatchFields.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::sniderStressGradient::anyOtherCell(const fvMesh& mesh)
{
    const linearHatKernel& kernel = linearHatKernel::New(mesh);
    bool any = false;
    for (label celli = 0; celli < mesh.nCells() && !any; ++celli)
    {
        any = !kernel.hexahedral(celli);
    }
    return returnReduce(any, orOp<bool>());
}


void Foam::sniderStressGradient::updateCellGradient()
{
    volScalarField stress
    (
        IOobject
        (
            "sniderStressGradient:stress",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh_,
        dimensionedScalar(dimless, Zero),
        calculatedFvPatchScalarField::typeName
    );
    stress.primitiveFieldRef() = cellStress_;

    // First pass: boundary values from their cells; coupled patches take
    // the neighbours' values
    stress.correctBoundaryConditions();
    volScalarField::Boundary& bf = stress.boundaryFieldRef();
    forAll(bf, patchi)
    {
        if (!bf[patchi].coupled())
        {
            bf[patchi] == bf[patchi].patchInternalField();
        }
    }
    const volVectorField first
    (
        fv::gaussGrad<scalar>::gradf(linearInterpolate(stress), stress.name())
    );

    // Second pass: boundary values extrapolated with the first gradient
    forAll(bf, patchi)
    {
        if (!bf[patchi].coupled())
        {
            const fvPatch& patch = mesh_.boundary()[patchi];
            bf[patchi] ==
                bf[patchi].patchInternalField()
              + (
                    (patch.Cf() - patch.Cn())
                  & first.boundaryField()[patchi].patchInternalField()
                );
        }
    }
    cellGradient_ =
        fv::gaussGrad<scalar>::gradf
        (
            linearInterpolate(stress),
            stress.name()
        )().primitiveField();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::sniderStressGradient::sniderStressGradient(const fvMesh& mesh)
:
    mesh_(mesh),
    kernel_(linearHatKernel::New(mesh)),
    anyOtherCell_(anyOtherCell(mesh)),
    cellStress_(),
    ghostStress_(),
    cellGradient_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::sniderStressGradient::update(const scalarField& cellStress)
{
    cellStress_ = cellStress;
    kernel_.ghostValues(cellStress_, ghostStress_);

    if (anyOtherCell_)
    {
        updateCellGradient();
    }
}


Foam::vector Foam::sniderStressGradient::at
(
    const point& position,
    const label celli
) const
{
    if (kernel_.hexahedral(celli))
    {
        return kernel_.extrapolatedGradient
        (
            cellStress_, ghostStress_, position, celli
        );
    }
    return cellGradient_[celli];
}


void Foam::sniderStressGradient::clear()
{
    cellStress_.clear();
    ghostStress_.clear();
    cellGradient_.clear();
}


// ************************************************************************* //
