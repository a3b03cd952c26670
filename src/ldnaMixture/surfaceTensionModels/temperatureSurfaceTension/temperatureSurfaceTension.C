/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "temperatureSurfaceTension.H"
#include "checkedInput.H"
#include "volFields.H"
#include "metalGasMixture.H"
#include "fvcSurfaceIntegrate.H"
#include "linear.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::surfaceTensionModels::temperatureSurfaceTension::temperatureSurfaceTension
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    surfaceTensionModel(mesh),
    TName_(dict.lookupOrDefault<word>("T", "T")),
    alphaName_(dict.lookupOrDefault<word>("alpha", "alpha.metal"))
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::surfaceTensionModels::temperatureSurfaceTension::read
(
    const dictionary& sigmaDict
)
{
    TName_ = sigmaDict.lookupOrDefault<word>("T", "T");
    alphaName_ = sigmaDict.lookupOrDefault<word>("alpha", "alpha.metal");
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
Foam::surfaceTensionModels::temperatureSurfaceTension::surfaceTemperature()
const
{
    // Weight of a cell's own temperature where no metal is near: small
    // against any metal fraction a surface holds, so that it only keeps the
    // mean defined (and smooth) in pure gas
    const scalar gasWeight = 1e-6;

    const volScalarField& T = mesh_.lookupObject<volScalarField>(TName_);
    const volScalarField& alpha =
        mesh_.lookupObject<volScalarField>(alphaName_);

    return
        (fvc::surfaceSum(linearInterpolate(alpha*T)) + gasWeight*T)
       /(fvc::surfaceSum(linearInterpolate(alpha)) + gasWeight);
}


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
    const scalarField Tsigma(surfaceTemperature()().primitiveField());

    forAll(Tsigma, celli)
    {
        sigmaField[celli] = sigma(Tsigma[celli]);
    }

    // Boundary faces at their own temperature; the faces between
    // processors take the neighbour cell's sigma(T_sigma) below, as a serial
    // run's internal faces do
    volScalarField::Boundary& sigmaBf = sigmaField.boundaryFieldRef();
    forAll(sigmaBf, patchi)
    {
        if (sigmaBf[patchi].coupled())
        {
            continue;
        }
        const scalarField& Tp = T.boundaryField()[patchi];
        forAll(Tp, facei)
        {
            sigmaBf[patchi][facei] = sigma(Tp[facei]);
        }
    }
    sigmaField.correctBoundaryConditions();

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
