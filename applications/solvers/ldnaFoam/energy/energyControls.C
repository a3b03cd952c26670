/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "energyControls.H"
#include "checkedInput.H"

// * * * * * * * * * * * * * * * Local Constants  * * * * * * * * * * * * * * //

namespace
{

// More than this many iterations of a step's energy equation means it does
// not converge: a larger count only delays the report
const Foam::label maxEnergyCorrectors = 1000;

const Foam::label defaultEnergyCorrectors = 20;
const Foam::scalar defaultLiquidFractionTolerance = 1e-6;

// The liquid fraction only sees cells in the melting range: an iterate that
// still moves a solid, liquid or gas cell by more than this [K] is not
// converged either.  The template's converged steps move a cell by at most
// about 300 K in their last iteration (gas beside droplets); a diverging
// iterate (a fast droplet reaching thin cells) moved one by 5389 K and
// passed the liquid fraction's 1e-3, then sigma(T) failed
const Foam::scalar defaultTemperatureTolerance = 1000;

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::energyControls::energyControls()
:
    nCorrectors_(defaultEnergyCorrectors),
    liquidFractionTolerance_(defaultLiquidFractionTolerance),
    temperatureTolerance_(defaultTemperatureTolerance)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::energyControls::read(const dictionary& pimpleDict)
{
    nCorrectors_ = ldna::getCheckedOrDefault<label>
    (
        pimpleDict, "nEnergyCorrectors",
        ldna::interval::closed(1, maxEnergyCorrectors), defaultEnergyCorrectors
    );
    liquidFractionTolerance_ = ldna::getCheckedOrDefault<scalar>
    (
        pimpleDict, "liquidFractionTolerance",
        ldna::interval::open(0, 1), defaultLiquidFractionTolerance
    );
    temperatureTolerance_ = ldna::getCheckedOrDefault<scalar>
    (
        pimpleDict, "temperatureChangeTolerance",
        ldna::interval::open(0, GREAT), defaultTemperatureTolerance
    );
}

// ************************************************************************* //
