/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "meltPoolMetrics.H"
#include "volFields.H"
#include "IOdictionary.H"
#include "checkedInput.H"
#include "functionObjectKeys.H"
#include "cellLinks.H"
#include "ListListOps.H"
#include <algorithm>
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(meltPoolMetrics, 0);
    addToRunTimeSelectionTable(functionObject, meltPoolMetrics, dictionary);
}
}




// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

namespace
{

//- The case's material dictionary, read without registering it
Foam::IOdictionary readThermophysicalProperties(const Foam::fvMesh& mesh)
{
    return Foam::IOdictionary
    (
        Foam::IOobject
        (
            "thermophysicalProperties",
            mesh.time().constant(),
            mesh,
            Foam::IOobject::MUST_READ,
            Foam::IOobject::NO_WRITE,
            false
        )
    );
}


} // End anonymous namespace


void Foam::functionObjects::meltPoolMetrics::readCoeffs(const dictionary& dict)
{
    // Its own entries and those of every function object
    ldna::checkKeys
    (
        dict,
        ldna::functionObjectKeys
        ({
            "T", "alpha", "surfaceHeight", "weldingDirection",
            "verticalDirection", "fusionTemperature", "poolTemperature",
            "metalThreshold", "beadSection"
        })
    );

    TName_ = dict.lookupOrDefault<word>("T", "T");

    // Metal phase and fusion isotherm default to the case's material
    const IOdictionary properties(readThermophysicalProperties(mesh_));
    const word metal = properties.get<wordList>("phases").first();

    // The fusion line is the substrate's: its own metal's with two metals
    // The names metalGasMixture gives them (substrateName,
    // fillerFractionName; its header needs the two-phase libraries' paths)
    const word substrate("substrate");
    const bool twoMetals = properties.isDict(substrate);
    const dictionary& metalDict =
        properties.subDict(twoMetals ? substrate : metal);
    fillerFractionName_ = twoMetals ? word("fillerFraction") : word::null;

    alphaName_ = dict.lookupOrDefault<word>("alpha", "alpha." + metal);

    surfaceHeight_ = ldna::getCheckedOrDefault<scalar>
    (
        dict, "surfaceHeight",
        ldna::interval::open(-ldna::limits::length, ldna::limits::length), 0
    );

    const vector weld(1, 0, 0);
    const vector vertical(0, 0, 1);
    weldDir_ = ldna::getDirection(dict, "weldingDirection", &weld);
    verticalDir_ = ldna::getDirection(dict, "verticalDirection", &vertical);

    // Tolerance of the right angle between the two directions
    const scalar orthogonalityTolerance = 1e-6;
    if (mag(weldDir_ & verticalDir_) > orthogonalityTolerance)
    {
        FatalIOErrorInFunction(dict)
            << "weldingDirection " << weldDir_ << " and verticalDirection "
            << verticalDir_ << " must be at right angles (cosine "
            << (weldDir_ & verticalDir_) << ", allowed |cos| <= "
            << orthogonalityTolerance << ")"
            << exit(FatalIOError);
    }
    transverseDir_ = verticalDir_ ^ weldDir_;

    // The substrate bonds where it began to melt; the pool is what flows
    // (liquid fraction above one half)
    const scalar solidus = metalDict.get<scalar>("solidus");
    const scalar liquidus = metalDict.get<scalar>("liquidus");
    fusionTemperature_ = ldna::getCheckedOrDefault<scalar>
    (
        dict, "fusionTemperature",
        ldna::interval::open(0, ldna::limits::temperature), solidus
    );
    poolTemperature_ = ldna::getCheckedOrDefault<scalar>
    (
        dict, "poolTemperature",
        ldna::interval::open(0, ldna::limits::temperature),
        0.5*(solidus + liquidus)
    );
    metalThreshold_ = ldna::getCheckedOrDefault<scalar>
    (
        dict, "metalThreshold", ldna::interval::open(0, 1), 0.5
    );

    fixedBeadSection_ = dict.found("beadSection");
    if (fixedBeadSection_)
    {
        // Checked against the mesh once its slices are known (read())
        beadSection_ = dict.get<scalar>("beadSection");
    }
}


void Foam::functionObjects::meltPoolMetrics::calcCellBounds()
{
    const pointField& points = mesh_.points();
    const labelListList& cellPoints = mesh_.cellPoints();

    cellBounds_.setSize(mesh_.nCells());

    scalar wMin = GREAT;
    scalar wMax = -GREAT;
    sliceLength_ = GREAT;

    forAll(cellPoints, celli)
    {
        boundBox bb(boundBox::invertedBox);
        for (const label pointi : cellPoints[celli])
        {
            const point& p = points[pointi];
            bb.add(point(p & weldDir_, p & transverseDir_, p & verticalDir_));
        }
        cellBounds_[celli] = bb;

        wMin = min(wMin, bb.min().x());
        wMax = max(wMax, bb.max().x());
        sliceLength_ = min(sliceLength_, bb.span().x());
    }

    reduce(wMin, minOp<scalar>());
    reduce(wMax, maxOp<scalar>());
    reduce(sliceLength_, minOp<scalar>());

    sliceOrigin_ = wMin;
    nSlices_ = max(1, label(std::ceil((wMax - wMin)/sliceLength_ - SMALL)));

    fusionLine_.reset
    (
        new fusionLine
        (
            mesh_, weldDir_, verticalDir_, surfaceHeight_, fusionTemperature_
        )
    );
}


void Foam::functionObjects::meltPoolMetrics::writeFileHeader(Ostream& os)
{
    if (writtenHeader_)
    {
        return;
    }

    writeHeader(os, "Melt pool and bead metrics");
    writeHeaderValue(os, "fusion temperature [K]", fusionTemperature_);
    writeHeaderValue(os, "pool temperature [K]", poolTemperature_);
    writeHeaderValue(os, "surface height [m]", surfaceHeight_);
    writeHeaderValue(os, "slice length [m]", sliceLength_);
    writeCommented(os, "Time");
    for
    (
        const char* column :
        {
            "poolLength", "poolWidth", "penetration", "poolVolume",
            "beadWidth", "beadHeight", "beadArea", "fusedArea", "dilution",
            "peakTemperature", "beadSection", "fusedSection", "bondedWidth",
            "unbondedWidth", "peakSurfaceTemperature"
        }
    )
    {
        writeTabbed(os, column);
    }
    if (!fillerFractionName_.empty())
    {
        writeTabbed(os, "chemicalDilution");
    }
    os  << endl;

    writtenHeader_ = true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::meltPoolMetrics::meltPoolMetrics
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    surfaceHeight_(0),
    fusionTemperature_(0),
    fillerFractionName_(),
    poolTemperature_(0),
    metalThreshold_(0.5),
    fixedBeadSection_(false),
    beadSection_(0),
    sliceOrigin_(0),
    sliceLength_(1),
    nSlices_(1)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::meltPoolMetrics::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    readCoeffs(dict);
    calcCellBounds();

    // A section off the mesh would measure its first or last slice
    const scalar sliceEnd = sliceOrigin_ + nSlices_*sliceLength_;
    if (fixedBeadSection_)
    {
        ldna::checkValue
        (
            dict, "beadSection", beadSection_,
            ldna::interval::closed(sliceOrigin_, sliceEnd),
            "a position along weldingDirection on the mesh"
        );
    }

    return true;
}


bool Foam::functionObjects::meltPoolMetrics::execute()
{
    return true;
}


bool Foam::functionObjects::meltPoolMetrics::write()
{
    const metrics m = calculate();

    Log << type() << " " << name() << ": pool length " << m.poolLength
        << " m, width " << m.poolWidth << " m, penetration " << m.penetration
        << " m; bead width " << m.beadWidth << " m, height " << m.beadHeight
        << " m, bonded width " << m.bondedWidth << " m, dilution "
        << m.dilution << "; peak T " << m.peakTemperature << " K" << endl;

    if (writeToFile())
    {
        writeFileHeader(file());
        writeCurrentTime(file());
        for
        (
            const scalar value :
            {
                m.poolLength, m.poolWidth, m.penetration, m.poolVolume,
                m.beadWidth, m.beadHeight, m.beadArea, m.fusedArea,
                m.dilution, m.peakTemperature, m.beadSection, m.fusedSection,
                m.bondedWidth, m.unbondedWidth, m.peakSurfaceTemperature
            }
        )
        {
            file() << tab << value;
        }
        if (!fillerFractionName_.empty())
        {
            file() << tab << m.chemicalDilution;
        }
        file() << endl;

        if (!fusionLineFile_.valid())
        {
            fusionLineFile_ = createFile("fusionLine");
            if (fusionLineFile_.valid())
            {
                OFstream& os = fusionLineFile_();
                writeHeader(os, "Fusion line: depth of the fusion isotherm per column");
                writeHeaderValue(os, "fusion temperature [K]", fusionTemperature_);
                writeCommented(os, "Time");
                writeTabbed(os, "transverse");
                writeTabbed(os, "depth");
                os  << endl;
            }
        }
        if (fusionLineFile_.valid())
        {
            fusionLine_->writeProfile(fusionLineFile_(), mesh_.time().timeName());
        }
    }

    return true;
}


void Foam::functionObjects::meltPoolMetrics::updateMesh(const mapPolyMesh&)
{
    calcCellBounds();
}


void Foam::functionObjects::meltPoolMetrics::movePoints(const polyMesh&)
{
    calcCellBounds();
}


// ************************************************************************* //
