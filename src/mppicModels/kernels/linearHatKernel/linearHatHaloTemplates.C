/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "PstreamBuffers.H"
#include "UIndirectList.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class Type, class CombineOp>
void Foam::linearHatHalo::exchange
(
    const labelListList& sendAt,
    const UList<Type>& sendValues,
    const labelListList& receiveAt,
    UList<Type>& receiveValues,
    const CombineOp& cop
)
{
    if (!Pstream::parRun())
    {
        return;
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(sendAt, proci)
    {
        if (sendAt[proci].size())
        {
            UOPstream toNbr(proci, buffers);
            toNbr << List<Type>(UIndirectList<Type>(sendValues, sendAt[proci]));
        }
    }
    buffers.finishedSends();

    forAll(receiveAt, proci)
    {
        if (receiveAt[proci].size())
        {
            UIPstream fromNbr(proci, buffers);
            const List<Type> received(fromNbr);
            const labelList& entries = receiveAt[proci];
            forAll(received, i)
            {
                cop(receiveValues[entries[i]], received[i]);
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::linearHatHalo::ghostValues
(
    const UList<Type>& cellValues,
    List<Type>& ghosts
) const
{
    ghosts.setSize(size());
    exchange(sendCells_, cellValues, slotsFrom_, ghosts, eqOp<Type>());
}


template<class Type>
void Foam::linearHatHalo::addGhostDeposits
(
    UList<Type>& cellValues,
    UList<Type>& ghosts
) const
{
    exchange(slotsFrom_, ghosts, sendCells_, cellValues, plusEqOp<Type>());
    ghosts = Zero;
}


// ************************************************************************* //
