/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type, class Weights>
Type Foam::linearHatKernel::interpolate
(
    const UList<Type>& cellValues,
    const UList<Type>& ghostValues,
    const point& position,
    const label celli
) const
{
    Weights w;
    evaluate(position, celli, w);

    Type sum = w.values[0]*value(cellValues, ghostValues, w.cells[0]);
    for (label k = 1; k < w.values.size(); ++k)
    {
        sum += w.values[k]*value(cellValues, ghostValues, w.cells[k]);
    }
    return sum;
}


template<class Type, class Weights>
void Foam::linearHatKernel::deposit
(
    UList<Type>& cellDensity,
    UList<Type>& ghostDensity,
    const point& position,
    const label celli,
    const Type& value
) const
{
    Weights w;
    evaluate(position, celli, w);

    const scalarField& V = mesh().V();
    const label nCells = V.size();
    for (label k = 0; k < w.values.size(); ++k)
    {
        const label cellk = w.cells[k];
        if (cellk < nCells)
        {
            cellDensity[cellk] += (w.values[k]/V[cellk])*value;
        }
        else
        {
            const label slot = cellk - nCells;
            ghostDensity[slot] += (w.values[k]/ghostVolumes_[slot])*value;
        }
    }
}


// ************************************************************************* //
