/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "PstreamBuffers.H"
#include "UIndirectList.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::linearHatHalo::ghostValues
(
    const UList<Type>& cellValues,
    List<Type>& ghosts
) const
{
    ghosts.setSize(size());
    if (!Pstream::parRun())
    {
        return;
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(sendCells_, proci)
    {
        if (sendCells_[proci].size())
        {
            UOPstream toNbr(proci, buffers);
            const labelList& cells = sendCells_[proci];
            toNbr << List<Type>(UIndirectList<Type>(cellValues, cells));
        }
    }
    buffers.finishedSends();

    forAll(slotsFrom_, proci)
    {
        if (slotsFrom_[proci].size())
        {
            UIPstream fromNbr(proci, buffers);
            const List<Type> received(fromNbr);
            UIndirectList<Type>(ghosts, slotsFrom_[proci]) = received;
        }
    }
}


template<class Type>
void Foam::linearHatHalo::addGhostDeposits
(
    UList<Type>& cellValues,
    UList<Type>& ghosts
) const
{
    if (!Pstream::parRun())
    {
        return;
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(slotsFrom_, proci)
    {
        if (slotsFrom_[proci].size())
        {
            UOPstream toOwner(proci, buffers);
            toOwner
                << List<Type>(UIndirectList<Type>(ghosts, slotsFrom_[proci]));
        }
    }
    buffers.finishedSends();

    forAll(sendCells_, proci)
    {
        if (sendCells_[proci].size())
        {
            UIPstream fromNbr(proci, buffers);
            const List<Type> received(fromNbr);
            const labelList& cells = sendCells_[proci];
            forAll(received, i)
            {
                cellValues[cells[i]] += received[i];
            }
        }
    }

    ghosts = Zero;
}


// ************************************************************************* //
