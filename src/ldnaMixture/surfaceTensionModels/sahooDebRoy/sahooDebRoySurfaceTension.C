/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "sahooDebRoySurfaceTension.H"
#include "physicoChemicalConstants.H"
#include "checkedInput.H"
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
    using ldna::interval;
    namespace limits = ldna::limits;

    ldna::checkKeys
    (
        sigmaDict,
        {
            "type", "T", "alpha", "activity", "sigmaMelting", "A", "Tmelting",
            "surfaceExcess", "segregationEntropy", "adsorptionEnthalpy"
        }
    );

    // Activity of the surface-active element in wt%: at most all of it
    const scalar maxActivity = 100;
    // Surface excess at saturation [mol/m2]: a monolayer of atoms holds
    // about 3e-5 mol/m2
    const scalar maxSurfaceExcess = 1e-3;
    // Segregation entropy factor k_1 (dimensionless; 3.18e-3 for S in Fe)
    const scalar maxSegregationEntropy = 1;
    // Standard heat of adsorption [J/mol]: exothermic, -1.66e5 J/mol for S
    // in Fe; beyond -1e6 exp(-dH/(R T)) overflows at room temperature
    const scalar maxAdsorptionEnthalpy = 1e6;

    activity_ = ldna::getChecked<scalar>
    (
        sigmaDict, "activity", interval::closed(0, maxActivity)
    );
    sigmaMelting_ = ldna::getCheckedOrDefault<scalar>
    (
        sigmaDict, "sigmaMelting",
        interval::openClosed(0, limits::surfaceTension), defaultSigmaMelting
    );
    A_ = ldna::getCheckedOrDefault<scalar>
    (
        sigmaDict, "A", interval::closed(0, limits::surfaceTensionSlope),
        defaultA
    );
    Tmelting_ = ldna::getCheckedOrDefault<scalar>
    (
        sigmaDict, "Tmelting", interval::open(0, limits::temperature),
        defaultTmelting
    );
    surfaceExcess_ = ldna::getCheckedOrDefault<scalar>
    (
        sigmaDict, "surfaceExcess", interval::closed(0, maxSurfaceExcess),
        defaultSurfaceExcess
    );
    segregationEntropy_ = ldna::getCheckedOrDefault<scalar>
    (
        sigmaDict, "segregationEntropy",
        interval::closed(0, maxSegregationEntropy), defaultSegregationEntropy
    );
    adsorptionEnthalpy_ = ldna::getCheckedOrDefault<scalar>
    (
        sigmaDict, "adsorptionEnthalpy",
        interval::closed(-maxAdsorptionEnthalpy, 0), defaultAdsorptionEnthalpy
    );
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
