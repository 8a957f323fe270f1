/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "PackSupport.H"
#include "cellFaceGeometry.H"
#include "wallPolyPatch.H"
#include "wordRes.H"
#include "syncTools.H"
#include "unitConversion.H"
#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::PackSupport::PackSupport(const fvMesh& mesh, const dictionary& coeffs)
:
    mesh_(mesh),
    supportPatch_(mesh.boundaryMesh().size(), false),
    cosSupportAngle_(Foam::cos(degToRad(supportAngle))),
    gHat_(Zero),
    lowerFaces_(),
    lowerWeights_(),
    lowerSlopes_(),
    bottomUp_(),
    held_()
{
    readSupportPatches(coeffs);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::PackSupport::readSupportPatches(const dictionary& coeffs)
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();

    if (!coeffs.found("supportPatches"))
    {
        forAll(patches, patchi)
        {
            supportPatch_[patchi] = isA<wallPolyPatch>(patches[patchi]);
        }
        return;
    }

    const wordRes names(coeffs.get<wordRes>("supportPatches"));

    wordList allowed;
    for (const polyPatch& pp : patches)
    {
        if (!pp.coupled())
        {
            allowed.append(pp.name());
        }
    }

    for (const wordRe& name : names)
    {
        bool matched = false;
        forAll(patches, patchi)
        {
            if (!patches[patchi].coupled() && name.match(patches[patchi].name()))
            {
                supportPatch_[patchi] = true;
                matched = true;
            }
        }

        if (!matched)
        {
            FatalIOErrorInFunction(coeffs)
                << "Dictionary " << coeffs.name()
                << ", keyword supportPatches: value " << name
                << " matches no patch; allowed: the non-coupled patches "
                << allowed << exit(FatalIOError);
        }
    }
}


void Foam::PackSupport::setGeometry(const vector& gHat)
{
    gHat_ = gHat;

    lowerFaces_.setSize(mesh_.nCells());
    lowerWeights_.setSize(mesh_.nCells());
    lowerSlopes_.setSize(mesh_.nCells());

    scalarField height(mesh_.nCells());

    forAll(lowerFaces_, celli)
    {
        DynamicList<label> faces;
        DynamicList<scalar> weights;
        DynamicList<scalar> slopes;

        for (const label facei : mesh_.cells()[celli])
        {
            const scalar down =
                cellFaceGeometry::outwardNormal(mesh_, celli, facei) & gHat;

            if (down > 0.1)
            {
                faces.append(facei);
                weights.append(mag(mesh_.faceAreas()[facei])*down);
                slopes.append(down);
            }
        }

        lowerFaces_[celli].transfer(faces);
        lowerWeights_[celli].transfer(weights);
        lowerSlopes_[celli].transfer(slopes);
        height[celli] = -(mesh_.cellCentres()[celli] & gHat);
    }

    bottomUp_ = identity(mesh_.nCells());
    std::stable_sort
    (
        bottomUp_.begin(),
        bottomUp_.end(),
        [&height](const label a, const label b)
        {
            return height[a] < height[b];
        }
    );
}


bool Foam::PackSupport::restsOnSupport
(
    const label celli,
    const boolList& nbrHeld
) const
{
    const label nInternal = mesh_.nInternalFaces();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();

    scalar total = 0;
    scalar supported = 0;

    forAll(lowerFaces_[celli], i)
    {
        const label facei = lowerFaces_[celli][i];
        const scalar weight = lowerWeights_[celli][i];
        total += weight;

        bool support = false;
        if (facei < nInternal)
        {
            support = held_[cellFaceGeometry::cellAcross(mesh_, celli, facei)];
        }
        else
        {
            const label patchi = patches.whichPatch(facei);
            support =
                patches[patchi].coupled()
              ? nbrHeld[facei - nInternal]
              : supportPatch_[patchi]
             && lowerSlopes_[celli][i] >= cosSupportAngle_;
        }

        if (support)
        {
            supported += weight;
        }
    }

    return total > 0 && supported >= 0.5*total;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::PackSupport::update(const vector& g, const boolList& full)
{
    const scalar magG = mag(g);

    held_.setSize(mesh_.nCells());
    held_ = false;

    if (magG < VSMALL)
    {
        return;
    }

    if (lowerFaces_.size() != mesh_.nCells() || mag(g/magG - gHat_) > 1e-12)
    {
        setGeometry(g/magG);
    }

    // Held cells only ever join: sweep bottom-up until none joins (one
    // sweep on a mesh whose lower neighbours lie lower, one more to see
    // it; across processors each sweep moves one processor further up)
    boolList nbrHeld;
    bool changed = true;
    while (changed)
    {
        syncTools::swapBoundaryCellList(mesh_, held_, nbrHeld);

        changed = false;
        for (const label celli : bottomUp_)
        {
            if (full[celli] && !held_[celli] && restsOnSupport(celli, nbrHeld))
            {
                held_[celli] = true;
                changed = true;
            }
        }

        reduce(changed, orOp<bool>());
    }
}


Foam::label Foam::PackSupport::nHeld() const
{
    label n = 0;
    for (const bool h : held_)
    {
        if (h)
        {
            ++n;
        }
    }
    return n;
}


// ************************************************************************* //
