/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "gasMassSources.H"
#include "boundedCoefficient.H"
#include "fvmSup.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- constant/gasMassSources, or a dictionary with no sources if it is absent
Foam::dictionary readSources(const Foam::fvMesh& mesh)
{
    Foam::IOobject io
    (
        "gasMassSources",
        mesh.time().constant(),
        mesh,
        Foam::IOobject::MUST_READ,
        Foam::IOobject::NO_WRITE
    );

    if (io.typeHeaderOk<Foam::IOdictionary>(true))
    {
        return Foam::IOdictionary(io);
    }

    Foam::dictionary none;
    none.add("sources", Foam::dictionary());
    return none;
}

//- A field of the sources, not read or written
Foam::IOobject sourceField(const Foam::fvMesh& mesh, const Foam::word& name)
{
    return Foam::IOobject
    (
        name,
        mesh.time().timeName(),
        mesh,
        Foam::IOobject::NO_READ,
        Foam::IOobject::NO_WRITE
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::gasMassSources::addSource
(
    const fvMesh& mesh,
    const dictionary& dict
)
{
    using namespace mppicCoefficients;

    checkKeywords
    (
        dict,
        {"centre", "radius", "volumetricFlowRate", "velocity"},
        "gasMassSources"
    );

    const point centre(dict.get<point>("centre"));
    const scalar radius = read(dict, "radius", bounds::above(0));
    const scalar Q = read(dict, "volumetricFlowRate", bounds::atLeast(0));
    const vector velocity
    (
        dict.lookupOrDefault<vector>("velocity", Zero)
    );

    const vectorField& C = mesh.C();
    const scalarField& V = mesh.V();

    labelList cells(C.size());
    label n = 0;
    scalar volume = 0;
    forAll(C, celli)
    {
        if (mag(C[celli] - centre) <= radius)
        {
            cells[n++] = celli;
            volume += V[celli];
        }
    }
    cells.setSize(n);

    const label nTotal = returnReduce(n, sumOp<label>());
    reduce(volume, sumOp<scalar>());

    if (nTotal == 0)
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ": no cell centre lies within"
            << " radius " << radius << " m of centre " << centre
            << "; the radius must be larger than the distance to the nearest"
            << " cell centre" << exit(FatalIOError);
    }

    const scalar rate = Q/volume;
    for (const label celli : cells)
    {
        volumeRate_[celli] += rate;
        momentumRate_[celli] += rate*velocity;
    }

    Info<< "    " << dict.dictName() << ": " << Q << " m3/s over "
        << nTotal << " cells, " << volume << " m3, within " << radius
        << " m of " << centre << "; velocity " << velocity << " m/s"
        << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasMassSources::gasMassSources
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    volumeRate_
    (
        sourceField(mesh, "gasMassSourceRate"),
        mesh,
        dimensionedScalar(dimless/dimTime, Zero)
    ),
    momentumRate_
    (
        sourceField(mesh, "gasMassSourceMomentum"),
        mesh,
        dimensionedVector(dimVelocity/dimTime, Zero)
    )
{
    const dictionary& sources = dict.subDict("sources");

    if (sources.size())
    {
        Info<< "Gas mass sources (" << dict.name() << "):" << endl;
    }

    for (const entry& e : sources)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(sources)
                << "Dictionary " << sources.name() << ", entry "
                << e.keyword() << ": not a sub-dictionary (centre, radius,"
                << " volumetricFlowRate, velocity)" << exit(FatalIOError);
        }
        addSource(mesh, e.dict());
    }
}


Foam::gasMassSources::gasMassSources(const fvMesh& mesh)
:
    gasMassSources(mesh, readSources(mesh))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::fvVectorMatrix> Foam::gasMassSources::momentumSource
(
    const volVectorField& U
) const
{
    return momentumRate_ - fvm::Sp(volumeRate_, U);
}


// ************************************************************************* //
