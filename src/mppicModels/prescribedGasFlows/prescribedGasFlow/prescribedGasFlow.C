/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "prescribedGasFlow.H"
#include "IOdictionary.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(prescribedGasFlow, 0);
    defineRunTimeSelectionTable(prescribedGasFlow, dictionary);
}

const Foam::word Foam::prescribedGasFlow::dictName
(
    "prescribedGasFlowProperties"
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::prescribedGasFlow::prescribedGasFlow(const dictionary&)
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::prescribedGasFlow> Foam::prescribedGasFlow::New
(
    const dictionary& dict
)
{
    const word flowType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(flowType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "prescribedGasFlow type",
            flowType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    Info<< "Prescribed gas flow " << flowType
        << ": the gas equations are not solved" << endl;

    return autoPtr<prescribedGasFlow>(cstrIter()(dict));
}


Foam::autoPtr<Foam::prescribedGasFlow> Foam::prescribedGasFlow::New
(
    const fvMesh& mesh
)
{
    IOobject io
    (
        dictName,
        mesh.time().constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );

    if (!io.typeHeaderOk<IOdictionary>(true))
    {
        return autoPtr<prescribedGasFlow>();
    }

    return New(IOdictionary(io));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::prescribedGasFlow::correct
(
    volVectorField& U,
    surfaceScalarField& phi,
    const scalar t
) const
{
    const fvMesh& mesh = U.mesh();

    U.primitiveFieldRef() = velocity(mesh.C().primitiveField(), t);
    U.correctBoundaryConditions();

    phi.primitiveFieldRef() =
        velocity(mesh.Cf().primitiveField(), t) & mesh.Sf().primitiveField();

    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        const tmp<vectorField> tUf(velocity(patch.Cf(), t));

        if (!patch.coupled())
        {
            U.boundaryFieldRef()[patchi] == tUf();
        }
        phi.boundaryFieldRef()[patchi] == (tUf() & patch.Sf());
    }
}


// ************************************************************************* //
