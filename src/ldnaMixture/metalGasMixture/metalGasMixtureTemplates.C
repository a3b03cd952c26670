/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "metalGasMixture.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CellFunction>
Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::evaluate
(
    const word& name,
    const dimensionSet& dims,
    const CellFunction& f
) const
{
    tmp<volScalarField> tresult
    (
        new volScalarField
        (
            IOobject
            (
                name,
                T_.time().timeName(),
                T_.mesh(),
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            T_.mesh(),
            dimensionedScalar(dims, Zero)
        )
    );
    volScalarField& result = tresult.ref();

    const scalarField& Tc = T_.primitiveField();
    const scalarField& glc = liquidFraction_.primitiveField();
    scalarField& rc = result.primitiveFieldRef();
    forAll(rc, celli)
    {
        rc[celli] = f(Tc[celli], glc[celli], fillerFractionAt(celli));
    }

    volScalarField::Boundary& rb = result.boundaryFieldRef();
    forAll(rb, patchi)
    {
        const scalarField& Tp = T_.boundaryField()[patchi];
        const scalarField& glp = liquidFraction_.boundaryField()[patchi];
        fvPatchScalarField& rp = rb[patchi];
        forAll(rp, facei)
        {
            rp[facei] =
                f
                (
                    Tp[facei], glp[facei],
                    fillerFraction_.valid()
                  ? fillerFraction_->boundaryField()[patchi][facei]
                  : scalar(1)
                );
        }
    }

    return tresult;
}


// ************************************************************************* //
