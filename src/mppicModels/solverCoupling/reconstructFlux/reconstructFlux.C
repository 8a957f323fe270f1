/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "reconstructFlux.H"
#include "fvcSurfaceIntegrate.H"
#include "extrapolatedCalculatedFvPatchFields.H"
#include "MeshObject.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
namespace mppicReconstruct
{

//- The mesh's part of the reconstruction, n_f = S_f/|S_f| and
//  inv(sum_f n_f S_f), kept with the mesh (the solvers reconstruct two or
//  three times a step; these depend on the geometry only)
class reconstructionGeometry
:
    public MeshObject<fvMesh, MoveableMeshObject, reconstructionGeometry>
{
    //- Unit face normals
    autoPtr<surfaceVectorField> SfHat_;

    //- inv(sum_f n_f S_f) of each cell
    tensorField invTensor_;

    void calculate()
    {
        const fvMesh& mesh = this->mesh_;
        SfHat_.reset(new surfaceVectorField(mesh.Sf()/mesh.magSf()));
        const volTensorField faceTensor(fvc::surfaceSum(SfHat_()*mesh.Sf()));
        invTensor_ = inv(faceTensor)().primitiveField();
    }

public:

    TypeName("mppicReconstructionGeometry");

    explicit reconstructionGeometry(const fvMesh& mesh)
    :
        MeshObject<fvMesh, MoveableMeshObject, reconstructionGeometry>(mesh)
    {
        calculate();
    }

    const surfaceVectorField& SfHat() const
    {
        return SfHat_();
    }

    const tensorField& invTensor() const
    {
        return invTensor_;
    }

    virtual bool movePoints()
    {
        calculate();
        return true;
    }
};

defineTypeNameAndDebug(reconstructionGeometry, 0);

} // End namespace mppicReconstruct
} // End namespace Foam

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

Foam::tmp<Foam::volVectorField>
Foam::mppicReconstruct::reconstructFlux(const surfaceScalarField& flux)
{
    const fvMesh& mesh = flux.mesh();

    const surfaceVectorField SfHat(mesh.Sf()/mesh.magSf());

    // Named fields, so that no operation writes into its own operand: the
    // inverse of a named field is a new field (with OpenFOAM's handling of
    // the empty direction of 2-D meshes), the product goes cell by cell
    // into a third one
    const volTensorField faceTensor(fvc::surfaceSum(SfHat*mesh.Sf()));
    const volTensorField invTensor(inv(faceTensor));
    const volVectorField fluxSum(fvc::surfaceSum(SfHat*flux));

    tmp<volVectorField> tresult
    (
        new volVectorField
        (
            IOobject
            (
                "reconstruct(" + flux.name() + ')',
                flux.instance(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            mesh,
            dimensionedVector(flux.dimensions()/dimArea, Zero),
            extrapolatedCalculatedFvPatchVectorField::typeName
        )
    );

    volVectorField& result = tresult.ref();
    forAll(result, celli)
    {
        result[celli] = invTensor[celli] & fluxSum[celli];
    }
    result.correctBoundaryConditions();

    return tresult;
}


Foam::tmp<Foam::volVectorField>
Foam::mppicReconstruct::reconstructFlux
(
    const tmp<surfaceScalarField>& tflux
)
{
    tmp<volVectorField> tresult(reconstructFlux(tflux()));
    tflux.clear();
    return tresult;
}


// ************************************************************************* //
