/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "dragLaws.H"
#include "boundedCoefficient.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace dragLaws
{
    defineTypeNameAndDebug(GidaspowDrag, 0);
    defineTypeNameAndDebug(HillKochLaddDrag, 0);
    defineTypeNameAndDebug(BVKDrag, 0);
    defineTypeNameAndDebug(SyamlalOBrienDrag, 0);
    defineTypeNameAndDebug(StokesDrag, 0);
    defineTypeNameAndDebug(ConstantCdDrag, 0);
    defineTypeNameAndDebug(LinearRelaxationDrag, 0);

    const wordList GidaspowDrag::keywords({"switchFraction", "blend"});
    const wordList HillKochLaddDrag::keywords;
    const wordList BVKDrag::keywords;
    const wordList SyamlalOBrienDrag::keywords({"c1", "d1"});
    const wordList StokesDrag::keywords({"voidageExponent"});
    const wordList ConstantCdDrag::keywords({"Cd"});
    const wordList LinearRelaxationDrag::keywords({"C"});
}
}

namespace Foam
{
    namespace coeff = mppicCoefficients;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dragLaws::GidaspowDrag::GidaspowDrag(const dictionary& coeffs)
:
    switchFraction_
    (
        coeff::read(coeffs, "switchFraction", 0.8, coeff::bounds::open(0, 1))
    ),
    blend_(coeffs.lookupOrDefault("blend", false))
{}


Foam::dragLaws::HillKochLaddDrag::HillKochLaddDrag(const dictionary&)
{}


Foam::dragLaws::BVKDrag::BVKDrag(const dictionary&)
{}


Foam::dragLaws::SyamlalOBrienDrag::SyamlalOBrienDrag(const dictionary& coeffs)
:
    c1_(coeff::read(coeffs, "c1", 0.8, coeff::bounds::above(0))),
    d1_(coeff::read(coeffs, "d1", 2.65, coeff::bounds::above(0)))
{}


Foam::dragLaws::StokesDrag::StokesDrag(const dictionary& coeffs)
:
    voidageExponent_
    (
        coeff::read
        (
            coeffs, "voidageExponent", 2.65, coeff::bounds::atLeast(0)
        )
    )
{}


Foam::dragLaws::ConstantCdDrag::ConstantCdDrag(const dictionary& coeffs)
:
    Cd_(coeff::read(coeffs, "Cd", coeff::bounds::atLeast(0)))
{}


Foam::dragLaws::LinearRelaxationDrag::LinearRelaxationDrag
(
    const dictionary& coeffs
)
:
    C_(coeff::read(coeffs, "C", coeff::bounds::atLeast(0)))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dragLaws::GidaspowDrag::Sp(const dragState& s) const
{
    const scalar phi =
        blend_
      ? dragCorrelations::gidaspowBlendWeight(s.alphag, switchFraction_)
      : scalar(s.alphag >= switchFraction_ ? 1 : 0);

    scalar K = 0;
    if (phi > 0)
    {
        K += phi*dragCorrelations::wenYuK(s);
    }
    if (phi < 1)
    {
        K += (1 - phi)*dragCorrelations::ergunK(s);
    }
    return voidageSp(s, K);
}


Foam::scalar Foam::dragLaws::HillKochLaddDrag::Sp(const dragState& s) const
{
    return voidageSp(s, dragCorrelations::hillKochLaddK(s));
}


Foam::scalar Foam::dragLaws::BVKDrag::Sp(const dragState& s) const
{
    return voidageSp(s, dragCorrelations::bvkK(s));
}


Foam::scalar Foam::dragLaws::SyamlalOBrienDrag::Sp(const dragState& s) const
{
    return voidageSp(s, dragCorrelations::syamlalOBrienK(s, c1_, d1_));
}


Foam::scalar Foam::dragLaws::StokesDrag::Sp(const dragState& s) const
{
    return voidageSp(s, dragCorrelations::stokesK(s, voidageExponent_));
}


Foam::scalar Foam::dragLaws::ConstantCdDrag::Sp(const dragState& s) const
{
    return s.mass*dragCorrelations::constantCdK(s, Cd_)/s.rhop;
}


Foam::scalar Foam::dragLaws::LinearRelaxationDrag::Sp(const dragState& s) const
{
    return C_*s.mass;
}


// ************************************************************************* //
