/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "cloudPhases.H"
#include "gravityMeshObject.H"
#include "basicKinematicMPPICCloud.H"
#include "basicReactingMPPICCloud.H"
#include "cloudPhasesTemplates.C"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::cloudPhases::cloudPhases
(
    const fvMesh& mesh,
    const word& prefix,
    const word& cloudName,
    const bool writeToFile
)
:
    writeFile(mesh, prefix, "phases", writeToFile),
    mesh_(mesh),
    cloudName_(cloudName)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::cloudPhases::reducePhases
(
    const labelList& indices,
    const List<phase>& local,
    const scalarList& massHeight
)
{
    // Every processor's indices, merged in ascending order
    List<labelList> allIndices(Pstream::nProcs());
    allIndices[Pstream::myProcNo()] = indices;
    Pstream::gatherList(allIndices);
    Pstream::scatterList(allIndices);

    labelHashSet merged;
    for (const labelList& procIndices : allIndices)
    {
        merged.insert(procIndices);
    }
    const labelList sorted(merged.sortedToc());

    labelList nParcels(sorted.size(), Zero);
    scalarList mass(sorted.size(), Zero);
    scalarList height(sorted.size(), Zero);
    forAll(indices, i)
    {
        const label k = sorted.find(indices[i]);
        nParcels[k] = local[i].nParcels;
        mass[k] = local[i].mass;
        height[k] = massHeight[i];
    }
    Pstream::listCombineGather(nParcels, plusEqOp<label>());
    Pstream::listCombineGather(mass, plusEqOp<scalar>());
    Pstream::listCombineGather(height, plusEqOp<scalar>());
    Pstream::listCombineScatter(nParcels);
    Pstream::listCombineScatter(mass);
    Pstream::listCombineScatter(height);

    phases_.setSize(sorted.size());
    forAll(sorted, k)
    {
        phases_[k].index = sorted[k];
        phases_[k].nParcels = nParcels[k];
        phases_[k].mass = mass[k];
        phases_[k].meanHeight = mass[k] > 0 ? height[k]/mass[k] : 0;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::functionObjects::cloudPhases::update()
{
    const vector& g = meshObjects::gravity::New(mesh_.time()).value();
    const vector up(mag(g) > 0 ? -g/mag(g) : vector(0, 1, 0));

    // Another kind of cloud (not MPPIC) has no phases to report
    if
    (
        !sumPhases<basicKinematicMPPICCloud>(up)
     && !sumPhases<basicReactingMPPICCloud>(up)
    )
    {
        phases_.clear();
    }
}


void Foam::functionObjects::cloudPhases::write
(
    Ostream& os,
    const scalar time
) const
{
    for (const phase& ph : phases_)
    {
        os  << time << tab << ph.index << tab << ph.nParcels << tab
            << ph.mass << tab << ph.meanHeight << endl;
    }
}


void Foam::functionObjects::cloudPhases::evaluate()
{
    update();

    for (const phase& ph : phases_)
    {
        Info<< "    phase " << ph.index << ": parcels " << ph.nParcels
            << ", mass " << ph.mass << " kg, mean height " << ph.meanHeight
            << " m" << nl;
    }

    if (phases_.empty() || !Pstream::master() || !writeToFile())
    {
        return;
    }
    if (!filePtr_.valid())
    {
        resetFile("phases");
        writeHeader(file(), "Solids phases of cloud " + cloudName_);
        writeCommented(file(), "Time");
        file()
            << tab << "phase" << tab << "nParcels" << tab << "mass"
            << tab << "meanHeight" << endl;
    }
    write(file(), mesh_.time().value());
}


// ************************************************************************* //
