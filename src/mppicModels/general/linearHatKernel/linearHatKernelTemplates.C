/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
Type Foam::linearHatKernel::interpolate
(
    const UList<Type>& cellValues,
    const point& position,
    const label celli
) const
{
    weights w;
    evaluate(position, celli, w);

    Type sum = w.values[0]*cellValues[w.cells[0]];
    for (label k = 1; k < 8; ++k)
    {
        sum += w.values[k]*cellValues[w.cells[k]];
    }
    return sum;
}


template<class Type>
void Foam::linearHatKernel::deposit
(
    UList<Type>& cellDensity,
    const point& position,
    const label celli,
    const Type& value
) const
{
    weights w;
    evaluate(position, celli, w);

    const scalarField& V = mesh().V();
    for (label k = 0; k < 8; ++k)
    {
        const label cellk = w.cells[k];
        cellDensity[cellk] += (w.values[k]/V[cellk])*value;
    }
}


// ************************************************************************* //
