/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "upstreamTotals.H"
#include "conservedDensities.H"
#include "volFields.H"
#include "checkedInput.H"
#include "functionObjectKeys.H"
#include "physicalLimits.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(upstreamTotals, 0);
    addToRunTimeSelectionTable(functionObject, upstreamTotals, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::upstreamTotals::readCoeffs(const dictionary& dict)
{
    // Its own entries and those of every function object
    ldna::checkKeys
    (
        dict,
        ldna::functionObjectKeys
        ({
            "section", "weldingDirection"
        })
    );

    const vector weld(1, 0, 0);
    weldDir_ = ldna::getDirection(dict, "weldingDirection", &weld);
    section_ = ldna::getChecked<scalar>
    (
        dict, "section",
        ldna::interval::open(-ldna::limits::length, ldna::limits::length)
    );
}


void Foam::functionObjects::upstreamTotals::selectCells()
{
    const vectorField& C = mesh_.C().primitiveField();
    DynamicList<label> cells(C.size());
    forAll(C, celli)
    {
        if ((C[celli] & weldDir_) < section_)
        {
            cells.append(celli);
        }
    }
    upstreamCells_.transfer(cells);
}


void Foam::functionObjects::upstreamTotals::writeFileHeader(Ostream& os)
{
    if (writtenHeader_)
    {
        return;
    }

    writeHeader(os, "Metal mass and total enthalpy upstream of the section");
    writeHeaderValue(os, "section [m]", section_);
    writeCommented(os, "Time");
    writeTabbed(os, "metalMass");
    writeTabbed(os, "totalEnthalpy");
    os  << endl;

    writtenHeader_ = true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::upstreamTotals::upstreamTotals
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    weldDir_(1, 0, 0),
    section_(0)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::upstreamTotals::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    readCoeffs(dict);
    selectCells();
    return true;
}


bool Foam::functionObjects::upstreamTotals::execute()
{
    return true;
}


bool Foam::functionObjects::upstreamTotals::write()
{
    // The solver's mixture: its metal mass and enthalpy densities, the ones
    // its domain balance sums
    const conservedDensities& mixture =
        lookupObject<conservedDensities>("thermophysicalProperties");

    const scalarField& V = mesh_.V();
    const tmp<volScalarField> tmetalMass(mixture.metalMassDensity());
    const scalarField& metalMassDensity = tmetalMass().primitiveField();
    const tmp<volScalarField> tenthalpy(mixture.volumetricEnthalpy());
    const scalarField& enthalpy = tenthalpy().primitiveField();

    scalar metalMass = 0;
    scalar totalEnthalpy = 0;
    for (const label celli : upstreamCells_)
    {
        metalMass += metalMassDensity[celli]*V[celli];
        totalEnthalpy += enthalpy[celli]*V[celli];
    }
    reduce(metalMass, sumOp<scalar>());
    reduce(totalEnthalpy, sumOp<scalar>());

    Log << type() << " " << name() << ": upstream of " << section_
        << " m metal mass " << metalMass << " kg, total enthalpy "
        << totalEnthalpy << " J" << endl;

    if (writeToFile())
    {
        writeFileHeader(file());
        writeCurrentTime(file());
        file() << tab << metalMass << tab << totalEnthalpy << endl;
    }

    return true;
}


void Foam::functionObjects::upstreamTotals::updateMesh(const mapPolyMesh&)
{
    selectCells();
}


void Foam::functionObjects::upstreamTotals::movePoints(const polyMesh&)
{
    selectCells();
}


// ************************************************************************* //
