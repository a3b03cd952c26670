/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
\*---------------------------------------------------------------------------*/

#include "linearSurfaceTension.H"
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
    sigma0_ = sigmaDict.get<scalar>("sigma0");
    dSigmadT_ = sigmaDict.get<scalar>("dSigmadT");
    Tref_ = sigmaDict.get<scalar>("Tref");

    if (sigma0_ <= 0 || Tref_ <= 0)
    {
        FatalIOErrorInFunction(sigmaDict)
            << "sigma0 " << sigma0_ << " N/m and Tref " << Tref_
            << " K must be > 0" << exit(FatalIOError);
    }
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
