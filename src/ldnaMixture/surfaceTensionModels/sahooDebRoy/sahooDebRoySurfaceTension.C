/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
\*---------------------------------------------------------------------------*/

#include "sahooDebRoySurfaceTension.H"
#include "physicoChemicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace surfaceTensionModels
{
    defineTypeNameAndDebug(sahooDebRoy, 0);
    addToRunTimeSelectionTable(surfaceTensionModel, sahooDebRoy, dictionary);
}
}

namespace
{

// Fe-S, Sahoo, DebRoy & McNallan (1988), Table I
const Foam::scalar defaultSigmaMelting = 1.943;     // [N/m]
const Foam::scalar defaultA = 4.3e-4;               // [N/m/K]
const Foam::scalar defaultTmelting = 1809;          // [K]
const Foam::scalar defaultSurfaceExcess = 1.3e-5;   // [mol/m2]
const Foam::scalar defaultSegregationEntropy = 3.18e-3;
const Foam::scalar defaultAdsorptionEnthalpy = -1.66e5;  // [J/mol]

}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::surfaceTensionModels::sahooDebRoy::readCoeffs
(
    const dictionary& sigmaDict
)
{
    activity_ = sigmaDict.get<scalar>("activity");
    sigmaMelting_ =
        sigmaDict.lookupOrDefault<scalar>("sigmaMelting", defaultSigmaMelting);
    A_ = sigmaDict.lookupOrDefault<scalar>("A", defaultA);
    Tmelting_ = sigmaDict.lookupOrDefault<scalar>("Tmelting", defaultTmelting);
    surfaceExcess_ =
        sigmaDict.lookupOrDefault<scalar>("surfaceExcess", defaultSurfaceExcess);
    segregationEntropy_ = sigmaDict.lookupOrDefault<scalar>
    (
        "segregationEntropy", defaultSegregationEntropy
    );
    adsorptionEnthalpy_ = sigmaDict.lookupOrDefault<scalar>
    (
        "adsorptionEnthalpy", defaultAdsorptionEnthalpy
    );

    if
    (
        activity_ < 0 || sigmaMelting_ <= 0 || A_ < 0 || Tmelting_ <= 0
     || surfaceExcess_ < 0 || segregationEntropy_ < 0
    )
    {
        FatalIOErrorInFunction(sigmaDict)
            << "activity " << activity_ << ", A " << A_
            << ", surfaceExcess " << surfaceExcess_
            << " and segregationEntropy " << segregationEntropy_
            << " must be >= 0; sigmaMelting " << sigmaMelting_
            << " and Tmelting " << Tmelting_ << " > 0"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::surfaceTensionModels::sahooDebRoy::sahooDebRoy
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    temperatureSurfaceTension(dict, mesh),
    activity_(0),
    sigmaMelting_(0),
    A_(0),
    Tmelting_(0),
    surfaceExcess_(0),
    segregationEntropy_(0),
    adsorptionEnthalpy_(0)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::surfaceTensionModels::sahooDebRoy::sigma
(
    const scalar T
) const
{
    // Universal gas constant [J/mol/K]
    const scalar R = constant::physicoChemical::R.value();
    const scalar K =
        segregationEntropy_*exp(-adsorptionEnthalpy_/(R*T));

    return
        sigmaMelting_
      - A_*(T - Tmelting_)
      - R*T*surfaceExcess_*log(1 + K*activity_);
}


bool Foam::surfaceTensionModels::sahooDebRoy::writeData(Ostream& os) const
{
    os.writeEntry("activity", activity_);
    os.writeEntry("sigmaMelting", sigmaMelting_);
    os.writeEntry("A", A_);
    os.writeEntry("Tmelting", Tmelting_);
    os.writeEntry("surfaceExcess", surfaceExcess_);
    os.writeEntry("segregationEntropy", segregationEntropy_);
    os.writeEntry("adsorptionEnthalpy", adsorptionEnthalpy_);
    return os.good();
}


// ************************************************************************* //
