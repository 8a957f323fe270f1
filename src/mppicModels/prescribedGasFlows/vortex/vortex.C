/*---------------------------------------------------------------------------*\
    mppicModels: MFiX-PIC dense-particle models for OpenFOAM
    This file is part of the mppicModels project, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "vortex.H"
#include "boundedCoefficient.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePrescribedGasFlow(vortex);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::prescribedGasFlows::vortex::vortex(const dictionary& dict)
:
    prescribedGasFlow(dict),
    period_
    (
        mppicCoefficients::read
        (
            dict,
            "period",
            mppicCoefficients::bounds::above(0)
        )
    ),
    origin_(dict.getOrDefault<point>("origin", Zero)),
    length_
    (
        mppicCoefficients::read
        (
            dict,
            "length",
            1,
            mppicCoefficients::bounds::above(0)
        )
    )
{
    Info<< "    period " << period_ << " s, periodic cube at " << origin_
        << " of side " << length_ << " m" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::vectorField> Foam::prescribedGasFlows::vortex::velocity
(
    const vectorField& x,
    const scalar t
) const
{
    using constant::mathematical::pi;

    const scalar timeFactor = Foam::cos(pi*t/period_);

    auto tU = tmp<vectorField>::New(x.size());
    vectorField& U = tU.ref();

    forAll(x, i)
    {
        const vector X((x[i] - origin_)/length_);

        // sin(pi X) and sin(2 pi X) per component
        const vector s1
        (
            Foam::sin(pi*X.x()),
            Foam::sin(pi*X.y()),
            Foam::sin(pi*X.z())
        );
        const vector s2
        (
            Foam::sin(2*pi*X.x()),
            Foam::sin(2*pi*X.y()),
            Foam::sin(2*pi*X.z())
        );

        U[i] = timeFactor*vector
        (
            2*sqr(s1.x())*s2.y()*s2.z(),
          - s2.x()*sqr(s1.y())*s2.z(),
          - s2.x()*s2.y()*sqr(s1.z())
        );
    }

    return tU;
}


// ************************************************************************* //
