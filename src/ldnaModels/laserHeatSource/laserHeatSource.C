/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "laserHeatSource.H"
#include "fvMatrices.H"
#include "fvcGrad.H"
#include "interfaceDelta.H"
#include "treeBoundBox.H"
#include "checkedInput.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(laserHeatSource, 0);
    addToRunTimeSelectionTable(option, laserHeatSource, dictionary);
}
}


namespace
{

// A ray is stopped below this share of its initial power
const Foam::scalar rayPowerCutoff = 1e-9;

// Rays start this share of the mesh's bounding-box diagonal inside the box,
// or before the first cell that acts on them
const Foam::scalar startMargin = 1e-9;

// Bins across the beam's width (each way) of the map of where the rays
// start: finer than the cells of a process zone for beams of a few mm
const Foam::label nStartBins = 64;

// The columns of the power table
const Foam::wordList powerColumns
({
    "targetX", "targetY", "targetZ", "emitted", "absorbedMetal",
    "absorbedGas", "reflected", "escaped", "stopped", "imbalance",
    "absorbedPool", "absorbedDeposit", "absorbedSubstrate"
});

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

const Foam::dictionary& Foam::fv::laserHeatSource::checkedKeys
(
    const dictionary& coeffs
)
{
    wordList known
    ({
        "type", "active", "alpha", "T", "log", "liquidFraction",
        "surfaceHeight", "verticalDirection"
    });
    known.append(laserBeam::keys);
    known.append(laserAbsorptionModel::keys);
    ldna::checkKeys(coeffs, known);
    return coeffs;
}


void Foam::fv::laserHeatSource::readCoeffs()
{
    beam_.read(checkedKeys(coeffs_));
    absorption_ = laserAbsorptionModel::New(coeffs_, mesh_);

    alphaName_ = coeffs_.lookupOrDefault<word>("alpha", "alpha.metal");
    TName_ = coeffs_.lookupOrDefault<word>("T", "T");
    liquidFractionName_ =
        coeffs_.lookupOrDefault<word>("liquidFraction", "liquidFraction");
    log_ = coeffs_.lookupOrDefault<bool>("log", true);

    surfaceHeight_ = ldna::getCheckedOrDefault<scalar>
    (
        coeffs_, "surfaceHeight",
        ldna::interval::open(-ldna::limits::length, ldna::limits::length), 0
    );
    const vector up(0, 0, 1);
    verticalDir_ = ldna::getDirection(coeffs_, "verticalDirection", &up);

    fieldNames_.setSize(1, TName_);
    applied_.setSize(1, false);

    // Force an update with the new coefficients
    updatedTimeIndex_ = -1;
}


Foam::scalarList Foam::fv::laserHeatSource::startDepths
(
    const point& target,
    const vector& d,
    const vector& e1,
    const vector& e2,
    const scalar extent,
    const scalarField& alpha,
    const vectorField& normal
) const
{
    const vectorField& C = mesh_.cellCentres();
    const scalarField& radius = tracer_.cells().radius();

    // Bins of the columns [i0, i1] x [j0, j1] a sphere at (a, b) of radius
    // r overlaps; false if it misses the map
    const auto binRange = [&]
    (
        const scalar a, const scalar b, const scalar r,
        label& i0, label& i1, label& j0, label& j1
    )
    {
        if (mag(a) > extent + r || mag(b) > extent + r)
        {
            return false;
        }
        i0 = startBin(a - r, extent);
        i1 = startBin(a + r, extent);
        j0 = startBin(b - r, extent);
        j1 = startBin(b + r, extent);
        return true;
    };

    scalarList depths(nStartBins*nStartBins, GREAT);
    forAll(C, celli)
    {
        if (!absorption_->acts(alpha[celli]) && magSqr(normal[celli]) < 0.5)
        {
            continue;
        }
        const vector fromTarget = C[celli] - target;
        label i0, i1, j0, j1;
        if
        (
            !binRange
            (
                fromTarget & e1, fromTarget & e2, radius[celli],
                i0, i1, j0, j1
            )
        )
        {
            continue;
        }
        const scalar depth = (C[celli] & d) - radius[celli];
        for (label i = i0; i <= i1; ++i)
        {
            for (label j = j0; j <= j1; ++j)
            {
                scalar& binDepth = depths[i*nStartBins + j];
                binDepth = min(binDepth, depth);
            }
        }
    }

    Pstream::listCombineGather(depths, minEqOp<scalar>());
    Pstream::listCombineScatter(depths);
    return depths;
}


Foam::label Foam::fv::laserHeatSource::startBin
(
    const scalar x,
    const scalar extent
)
{
    const label bin(floor((x + extent)*nStartBins/(2*extent)));
    return min(max(bin, 0), nStartBins - 1);
}


void Foam::fv::laserHeatSource::update()
{
    if (updatedTimeIndex_ == mesh_.time().timeIndex())
    {
        return;
    }
    updatedTimeIndex_ = mesh_.time().timeIndex();

    const scalar t = mesh_.time().value();
    const scalar P = beam_.power(t);
    const point c = beam_.target(t);
    const vector d = beam_.direction(t);
    vector e1, e2;
    beam_.across(t, e1, e2);

    // Rays start where their line enters the bounding box of the whole mesh
    const treeBoundBox bounds(boundBox(mesh_.points(), true));

    // The beam aims at the workpiece: a target off the mesh heats nothing
    // (a typing error in position, offset or oscillation)
    if (!bounds.contains(c))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry 'position' in " << coeffs_.name() << ": the target "
            << c << " m at t = " << t << " s (position + offset +"
            << " oscillation) lies outside the mesh, whose bounds are "
            << bounds << exit(FatalIOError);
    }
    const scalar reach = beam_.sourceDistance() + 2*bounds.mag();

    DynamicList<vector2D> across;
    DynamicList<scalar> shares;
    absorption_->rays(beam_, mesh_.time().timeIndex(), across, shares);

    const volScalarField& alpha =
        mesh_.lookupObject<volScalarField>(alphaName_);
    const volScalarField& T = mesh_.lookupObject<volScalarField>(TName_);
    // Interface normals out of the metal, if the absorption model uses them
    vectorField normal(mesh_.nCells(), Zero);
    if (absorption_->usesSurfaceNormal())
    {
        normal = -metalInterfaceNormal(fvc::grad(alpha)());
    }

    // Nothing happens to a ray before the first cell in its way that the
    // absorption model acts on (or that holds an interface): each ray
    // starts just before the first such cell over its bin of a map across
    // the beam, not at the top of the mesh
    scalar extent = SMALL*bounds.mag();
    for (const vector2D& offset : across)
    {
        extent = max(extent, mag(offset));
    }
    const scalarList depths
    (
        startDepths(c, d, e1, e2, extent, alpha.primitiveField(), normal)
    );

    DynamicList<laserRay> rays(across.size());
    scalar started = 0;
    forAll(across, rayi)
    {
        const point onAxis = c + across[rayi].x()*e1 + across[rayi].y()*e2;
        const point start = onAxis - beam_.sourceDistance()*d;

        point entry;
        if (!bounds.intersects(start, start + reach*d, entry))
        {
            continue;
        }
        point inside = entry + startMargin*bounds.mag()*d;
        const scalar depth =
            depths
            [
                startBin(across[rayi].x(), extent)*nStartBins
              + startBin(across[rayi].y(), extent)
            ]
          - startMargin*bounds.mag();
        const point first = onAxis + (depth - (onAxis & d))*d;
        if ((first & d) > (inside & d) && bounds.contains(first))
        {
            inside = first;
        }
        const label celli = tracer_.startCell(inside);
        if (celli < 0)
        {
            continue;
        }

        const scalar rayPower = P*shares[rayi];
        rays.append(laserRay(inside, celli, d, rayPower));
        started += rayPower;
    }
    reduce(started, sumOp<scalar>());

    // Random numbers of scattering, different per processor
    Random scatterGen(mesh_.time().timeIndex() + 7919*Pstream::myProcNo());

    scalarField absorbed(mesh_.nCells(), Zero);
    laserRay::trackingData td
    (
        mesh_,
        tracer_.cells(),
        absorption_(),
        alpha.primitiveField(),
        T.primitiveField(),
        normal,
        SMALL*bounds.mag(),
        rayPowerCutoff*P/max(across.size(), 1),
        scatterGen,
        absorbed
    );
    tracer_.trace(rays, td);

    powerDensity_.primitiveFieldRef() = absorbed/mesh_.V();
    powerDensity_.correctBoundaryConditions();

    // The balance
    const scalarField alphaClipped
    (
        min(max(alpha.primitiveField(), scalar(0)), scalar(1))
    );
    const scalar byMetal = gSum(alphaClipped*absorbed);
    const scalar byGas = gSum((1 - alphaClipped)*absorbed);
    const scalar reflected = returnReduce(td.reflected, sumOp<scalar>());
    // Rays that found no cell of the mesh missed the domain
    const scalar escaped =
        returnReduce(td.escaped, sumOp<scalar>()) + (P - started);
    const scalar stopped = returnReduce(td.stopped, sumOp<scalar>());
    const scalar imbalance = P - byMetal - byGas - reflected - escaped - stopped;

    // Where the metal's part went: the pool, the solid deposit above the
    // substrate surface, the solid substrate below it
    const volScalarField& liquidFraction =
        mesh_.lookupObject<volScalarField>(liquidFractionName_);
    const vectorField& C = mesh_.C();
    scalar byPool = 0;
    scalar byDeposit = 0;
    scalar bySubstrate = 0;
    forAll(absorbed, celli)
    {
        const scalar byCellMetal = alphaClipped[celli]*absorbed[celli];
        if (liquidFraction[celli] > 0)
        {
            byPool += byCellMetal;
        }
        else if ((C[celli] & verticalDir_) >= surfaceHeight_)
        {
            byDeposit += byCellMetal;
        }
        else
        {
            bySubstrate += byCellMetal;
        }
    }
    reduce(byPool, sumOp<scalar>());
    reduce(byDeposit, sumOp<scalar>());
    reduce(bySubstrate, sumOp<scalar>());

    if (log_)
    {
        Info<< type() << ' ' << name_ << ": t = " << t
            << " s, target = " << c
            << ", emitted = " << P
            << " W, absorbed by metal = " << byMetal
            << " W (pool " << byPool << ", deposit " << byDeposit
            << ", substrate " << bySubstrate << ")"
            << " W, by gas = " << byGas
            << " W, reflected = " << reflected
            << " W, escaped = " << escaped
            << " W, stopped = " << stopped
            << " W, imbalance = " << imbalance << " W" << endl;
    }

    powerFile_.writeRow
    ({
        c.x(), c.y(), c.z(), P, byMetal, byGas, reflected, escaped, stopped,
        imbalance, byPool, byDeposit, bySubstrate
    });
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::laserHeatSource::laserHeatSource
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    beam_(checkedKeys(coeffs_)),
    absorption_(),
    log_(true),
    surfaceHeight_(0),
    verticalDir_(0, 0, 1),
    powerDensity_
    (
        IOobject
        (
            name + "PowerDensity",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar(dimPower/dimVolume, Zero)
    ),
    updatedTimeIndex_(-1),
    tracer_(mesh),
    powerFile_(mesh, name, "power")
{
    readCoeffs();

    powerFile_.writeHeader
    (
        "Laser target [m] and power balance [W]", powerColumns
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fv::laserHeatSource::addSup
(
    fvMatrix<scalar>& eqn,
    const label fieldi
)
{
    update();
    eqn += powerDensity_;
}


void Foam::fv::laserHeatSource::addSup
(
    const volScalarField& rho,
    fvMatrix<scalar>& eqn,
    const label fieldi
)
{
    addSup(eqn, fieldi);
}


bool Foam::fv::laserHeatSource::read(const dictionary& dict)
{
    if (option::read(dict))
    {
        readCoeffs();
        return true;
    }
    return false;
}


// ************************************************************************* //
