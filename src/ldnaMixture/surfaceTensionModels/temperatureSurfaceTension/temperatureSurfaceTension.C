/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "temperatureSurfaceTension.H"
#include "checkedInput.H"
#include "volFields.H"
#include "metalGasMixture.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::surfaceTensionModels::temperatureSurfaceTension::temperatureSurfaceTension
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    surfaceTensionModel(mesh),
    TName_(dict.lookupOrDefault<word>("T", "T"))
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::surfaceTensionModels::temperatureSurfaceTension::read
(
    const dictionary& sigmaDict
)
{
    TName_ = sigmaDict.lookupOrDefault<word>("T", "T");
    readCoeffs(sigmaDict);

    const scalar Tmin = metalGasMixture::propertyCheckTmin;
    const scalar Tmax = metalGasMixture::propertyCheckTmax;
    const label nSamples = 200;
    for (label i = 0; i <= nSamples; ++i)
    {
        const scalar T = Tmin + (Tmax - Tmin)*i/nSamples;
        ldna::checkValue
        (
            sigmaDict, "sigma", sigma(T),
            ldna::interval::openClosed(0, ldna::limits::surfaceTension),
            "the surface tension [N/m] at T = " + Foam::name(T)
          + " K of [" + Foam::name(Tmin) + ", " + Foam::name(Tmax)
          + "] K that its coefficients give"
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volScalarField>
Foam::surfaceTensionModels::temperatureSurfaceTension::sigma() const
{
    auto tsigma = tmp<volScalarField>::New
    (
        IOobject
        (
            "sigma",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh_,
        dimSigma
    );
    volScalarField& sigmaField = tsigma.ref();

    const volScalarField& T = mesh_.lookupObject<volScalarField>(TName_);

    forAll(T, celli)
    {
        sigmaField[celli] = sigma(T[celli]);
    }

    volScalarField::Boundary& sigmaBf = sigmaField.boundaryFieldRef();
    forAll(sigmaBf, patchi)
    {
        const scalarField& Tp = T.boundaryField()[patchi];
        forAll(Tp, facei)
        {
            sigmaBf[patchi][facei] = sigma(Tp[facei]);
        }
    }

    return tsigma;
}


bool Foam::surfaceTensionModels::temperatureSurfaceTension::readDict
(
    const dictionary& dict
)
{
    read(surfaceTensionModel::sigmaDict(dict));
    return true;
}


// ************************************************************************* //
