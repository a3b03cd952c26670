/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "linearSurfaceTension.H"
#include "checkedInput.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace surfaceTensionModels
{
    defineTypeNameAndDebug(linear, 0);
    addToRunTimeSelectionTable(surfaceTensionModel, linear, dictionary);
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::surfaceTensionModels::linear::readCoeffs(const dictionary& sigmaDict)
{
    using ldna::interval;
    namespace limits = ldna::limits;

    ldna::checkKeys(sigmaDict, {"type", "T", "alpha", "sigma0", "dSigmadT", "Tref"});

    sigma0_ = ldna::getChecked<scalar>
    (
        sigmaDict, "sigma0", interval::openClosed(0, limits::surfaceTension)
    );
    dSigmadT_ = ldna::getChecked<scalar>
    (
        sigmaDict, "dSigmadT",
        interval::closed
        (
            -limits::surfaceTensionSlope, limits::surfaceTensionSlope
        )
    );
    Tref_ = ldna::getChecked<scalar>
    (
        sigmaDict, "Tref", interval::open(0, limits::temperature)
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::surfaceTensionModels::linear::linear
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    temperatureSurfaceTension(dict, mesh),
    sigma0_(0),
    dSigmadT_(0),
    Tref_(0)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::surfaceTensionModels::linear::sigma(const scalar T) const
{
    return sigma0_ + dSigmadT_*(T - Tref_);
}


bool Foam::surfaceTensionModels::linear::writeData(Ostream& os) const
{
    os.writeEntry("sigma0", sigma0_);
    os.writeEntry("dSigmadT", dSigmadT_);
    os.writeEntry("Tref", Tref_);
    return os.good();
}


// ************************************************************************* //
