/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::mfixCollisionDamping::update
(
    const CloudType& cloud,
    const scalarField& cellAlpha
)
{
    const label nCells = cellAlpha.size();

    scalarField weight(nCells, Zero);
    vectorField weightedU(nCells, Zero);
    scalarField sumR3(nCells, Zero);
    scalarField sumR2(nCells, Zero);
    labelList count(nCells, Zero);

    for (const typename CloudType::parcelType& p : cloud)
    {
        const label celli = p.cell();
        const scalar r = 0.5*p.d();
        weight[celli] += p.rho();
        weightedU[celli] += p.rho()*p.U();
        sumR3[celli] += pow3(r);
        sumR2[celli] += sqr(r);
        ++count[celli];
    }

    meanVelocity_.setSize(nCells);
    forAll(meanVelocity_, celli)
    {
        meanVelocity_[celli] =
            weight[celli] > 0 ? weightedU[celli]/weight[celli] : Zero;
    }

    vectorField variance(nCells, Zero);
    for (const typename CloudType::parcelType& p : cloud)
    {
        const label celli = p.cell();
        variance[celli] +=
            p.rho()/weight[celli]
           *cmptSqr(p.U() - meanVelocity_[celli]);
    }

    oneByTau_.setSize(nCells);
    oneByTau_ = Zero;
    forAll(oneByTau_, celli)
    {
        if (count[celli] < 2)
        {
            continue;
        }
        const scalar r32 = sumR3[celli]/(3*sumR2[celli]);
        for (direction k = 0; k < vector::nComponents; ++k)
        {
            const scalar sigma =
                sqrt(variance[celli][k])/(count[celli] - 1);
            oneByTau_[celli][k] = oneByTau(cellAlpha[celli], sigma, r32);
        }
    }
}


// ************************************************************************* //
