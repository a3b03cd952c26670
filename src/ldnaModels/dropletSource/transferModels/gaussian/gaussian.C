/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "gaussian.H"
#include "cellSource.H"
#include "metalGasMixture.H"
#include "boundBox.H"
#include "addToRunTimeSelectionTable.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace dropletTransferModels
{
    defineTypeNameAndDebug(gaussian, 0);
    addToRunTimeSelectionTable(dropletTransferModel, gaussian, dropletSource);
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::dropletTransferModels::gaussian::footprint
Foam::dropletTransferModels::gaussian::footprintOf
(
    const fv::dropletSource::wireStream& wire,
    const vector& centre,
    const scalar R
) const
{
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();

    // exp(-3 r^2/R^2) is 6e-6 at twice the radius
    const scalar cutoff2 = sqr(2*R);

    DynamicList<label> cells;
    DynamicList<scalar> weights;
    forAll(C, celli)
    {
        const scalar r2 = magSqr(C[celli] - centre);
        if (r2 < cutoff2)
        {
            cells.append(celli);
            weights.append(exp(-3*r2/sqr(R)));
        }
    }

    scalar total = 0;
    forAll(cells, i)
    {
        total += weights[i]*V[cells[i]];
    }
    reduce(total, sumOp<scalar>());

    // A droplet smaller than the cells: the cell containing its centre
    const bool resolved = total > 0;
    if (!resolved)
    {
        cells.clear();
        weights.clear();
        const label celli = mesh_.findCell(centre);
        if (celli != -1)
        {
            cells.append(celli);
            weights.append(1);
            total = V[celli];
        }
        reduce(total, sumOp<scalar>());
    }

    if (!(total > 0))
    {
        FatalIOErrorInFunction(source_.coeffs())
            << "The droplet source of wire " << wire.name << " at " << centre
            << " m is outside the mesh, whose bounds are "
            << boundBox(mesh_.points(), true) << exit(FatalIOError);
    }

    footprint fp;
    fp.cells.transfer(cells);
    fp.weights.transfer(weights);
    fp.weights /= total;

    // The discrete integral over the analytic one, pi^1.5 R^3/(3 sqrt 3)
    const scalar analytic = pow(pi, 1.5)*pow3(R)/(3*sqrt(3.0));
    Info<< "    " << source_.name() << " wire " << wire.name << ": droplet of radius "
        << R << " m on " << returnReduce(fp.cells.size(), sumOp<label>())
        << " cells, discrete/analytic Gaussian integral "
        << (resolved ? total/analytic : 0)
        << (resolved ? "" : " (unresolved: one cell)") << endl;

    return fp;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletTransferModels::gaussian::gaussian
(
    const fv::dropletSource& source,
    const fvMesh& mesh
)
:
    dropletTransferModel(source, mesh),
    massSource_(mesh.nCells(), Zero),
    enthalpySource_(mesh.nCells(), Zero),
    momentumSource_(mesh.nCells(), Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::dropletTransferModels::gaussian::fieldNames
(
    const word& alphaName,
    const word& UName,
    const word& TName
) const
{
    wordList names(nSourceFields);
    names[alphaFieldi] = alphaName;
    names[UFieldi] = UName;
    names[TFieldi] = TName;
    return names;
}


void Foam::dropletTransferModels::gaussian::setUp(const label wirei)
{
    const fv::dropletSource::wireStream& wire = source_.wires()[wirei];
    regular_.setSize(source_.wires().size());
    irregular_.setSize(source_.wires().size());

    regular_[wirei] = footprintOf(wire, wire.position, wire.dropletRadius);
    if (source_.irregularStart())
    {
        irregular_[wirei] = footprintOf
        (
            wire,
            wire.irregularPosition,
            source_.irregularDiameterFactor()*wire.dropletRadius
        );
    }
}


void Foam::dropletTransferModels::gaussian::clearSources()
{
    massSource_ = 0;
    enthalpySource_ = 0;
    momentumSource_ = Zero;
}


void Foam::dropletTransferModels::gaussian::spread
(
    const label wirei,
    const bool irregular,
    const scalar massRate,
    const vector& velocity,
    const scalar enthalpy
)
{
    const footprint& fp = irregular ? irregular_[wirei] : regular_[wirei];
    forAll(fp.cells, i)
    {
        const label celli = fp.cells[i];
        const scalar S = massRate*fp.weights[i];
        massSource_[celli] += S;
        momentumSource_[celli] += S*velocity;
        enthalpySource_[celli] += S*enthalpy;
    }
}


void Foam::dropletTransferModels::gaussian::addSup
(
    fvMatrix<scalar>& eqn,
    const label fieldi
)
{
    const word& name = source_.name();
    if (fieldi == alphaFieldi)
    {
        // Metal mass [kg/m3/s]
        eqn += cellSource(eqn, name + ":massSource", massSource_);
    }
    else if (fieldi == TFieldi)
    {
        // The solver lets added metal arrive at the enthalpy h1 of the cell
        // at the current iterate; the droplet brings h1(T_d): the difference
        // S (h1(T_d) - h1), explicit, so that the energy added in the step
        // is exactly S h1(T_d) and the liquid-fraction projection of the
        // solver decides how the cell melts
        const metalGasMixture& mixture =
            mesh_.lookupObject<metalGasMixture>("thermophysicalProperties");
        const volScalarField h1(mixture.h1());

        eqn += cellSource
        (
            eqn,
            name + ":enthalpySource",
            scalarField(enthalpySource_ - massSource_*h1.primitiveField())
        );
    }
}


void Foam::dropletTransferModels::gaussian::addSup
(
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    eqn += cellSource(eqn, source_.name() + ":momentumSource", momentumSource_);
}

// ************************************************************************* //
