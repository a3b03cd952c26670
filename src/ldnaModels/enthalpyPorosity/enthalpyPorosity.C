/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "enthalpyPorosity.H"
#include "fvMatrices.H"
#include "fvmSup.H"
#include "checkedInput.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(enthalpyPorosity, 0);
    addToRunTimeSelectionTable(option, enthalpyPorosity, dictionary);
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fv::enthalpyPorosity::readCoeffs()
{
    using ldna::interval;

    ldna::checkKeys
    (
        coeffs_,
        {
            "type", "active", "selectionMode", "cellSet", "cellZone",
            "points", "timeStart", "duration", "mushyZoneConstant",
            "porosityEpsilon", "weldingSpeed", "weldingDirection", "alpha",
            "liquidFraction", "U"
        }
    );

    mushyZoneConstant_ = ldna::getChecked<scalar>
    (
        coeffs_, "mushyZoneConstant",
        interval::openClosed(0, ldna::limits::mushyZoneConstant)
    );
    porosityEpsilon_ = ldna::getChecked<scalar>
    (
        coeffs_, "porosityEpsilon", interval::open(0, 1)
    );

    weldingSpeed_ = Function1<scalar>::New("weldingSpeed", coeffs_);
    weldingDirection_ = ldna::getDirection(coeffs_, "weldingDirection");
    substrateVelocity();

    alphaName_ = coeffs_.lookupOrDefault<word>("alpha", "alpha.metal");
    liquidFractionName_ =
        coeffs_.lookupOrDefault<word>("liquidFraction", "liquidFraction");
    UName_ = coeffs_.lookupOrDefault<word>("U", "U");

    fieldNames_.setSize(1, UName_);
    applied_.setSize(fieldNames_.size(), false);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::enthalpyPorosity::enthalpyPorosity
(
    const word& sourceName,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    cellSetOption(sourceName, modelType, dict, mesh),
    mushyZoneConstant_(0),
    porosityEpsilon_(0),
    weldingSpeed_(),
    weldingDirection_(Zero)
{
    readCoeffs();
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::vector Foam::fv::enthalpyPorosity::substrateVelocity() const
{
    const scalar t = mesh_.time().value();
    const scalar vw = weldingSpeed_->value(t);
    ldna::checkValue
    (
        coeffs_, "weldingSpeed", vw,
        ldna::interval::closedOpen(0, ldna::limits::speed),
        "at t = " + Foam::name(t) + " s; the direction is weldingDirection"
    );
    return vw*weldingDirection_;
}


void Foam::fv::enthalpyPorosity::checkInletVelocity(const vector& Us) const
{
    // The substrate enters the moving frame on the patches where U is
    // fixed and metal flows in: there U must be the welding velocity, or
    // the solid would be pushed or pulled against the porosity sink
    const volVectorField& U = mesh_.lookupObject<volVectorField>(UName_);
    const volScalarField& alpha =
        mesh_.lookupObject<volScalarField>(alphaName_);

    // A relative difference above round-off of the dictionaries' numbers
    const scalar tolerance = 1e-6;
    const scalar scale = max(mag(Us), SMALL);

    forAll(U.boundaryField(), patchi)
    {
        const fvPatchVectorField& Up = U.boundaryField()[patchi];
        if (!Up.fixesValue() || Up.coupled())
        {
            continue;
        }
        const fvPatchScalarField& alphap = alpha.boundaryField()[patchi];
        const vectorField n(Up.patch().nf());

        scalar worst = 0;
        vector worstU = Zero;
        forAll(Up, facei)
        {
            const bool metalInflow =
                alphap[facei] > 0.5 && (Up[facei] & n[facei]) < 0;
            if (metalInflow && mag(Up[facei] - Us) > worst)
            {
                worst = mag(Up[facei] - Us);
                worstU = Up[facei];
            }
        }
        reduce(worst, maxOp<scalar>());
        if (worst > tolerance*scale)
        {
            FatalIOErrorInFunction(coeffs_)
                << "Entries 'weldingSpeed' and 'weldingDirection' in "
                << coeffs_.name() << " give the substrate velocity " << Us << " m/s at t = "
                << mesh_.time().value() << " s, but metal enters through"
                << " patch " << Up.patch().name() << " of " << UName_
                << " at up to " << worstU << " m/s (a difference of "
                << worst << " m/s): the inlet velocity must be the welding"
                << " velocity (give both from one value, e.g. $weldingSpeed"
                << " of system/caseParameters)" << exit(FatalIOError);
        }
    }
}


void Foam::fv::enthalpyPorosity::addSup
(
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    const volScalarField& alpha =
        mesh_.lookupObject<volScalarField>(alphaName_);
    const volScalarField& liquidFraction =
        mesh_.lookupObject<volScalarField>(liquidFractionName_);

    volScalarField::Internal coeff
    (
        IOobject
        (
            name_ + ":coeff",
            mesh_.time().timeName(),
            mesh_
        ),
        mesh_,
        dimensionedScalar(dimDensity/dimTime, Zero)
    );

    // Every cell that holds solid metal, through the cell's solid fraction
    // s = alpha (1 - g_l) as the porous medium's (Voller & Prakash 1987, as
    // OpenFOAM's icoReactingMultiphaseInterFoam does for a solid phase): a
    // full metal cell takes the Carman-Kozeny sink of its liquid fraction,
    // a cell whose solid is a sliver beside gas lets the gas and the liquid
    // through.  Linear in alpha, a cell with 0.1 % frozen metal was rigid
    // and kept its gas under the deposit (docs/journal/bead-2026-11.md)
    for (const label celli : cells_)
    {
        const scalar metal = min(max(alpha[celli], scalar(0)), scalar(1));
        const scalar gl = min(max(liquidFraction[celli], scalar(0)), scalar(1));
        const scalar solid = metal*(1 - gl);
        coeff[celli] =
            mushyZoneConstant_*sqr(solid)/(pow3(1 - solid) + porosityEpsilon_);
    }

    const dimensionedVector Us
    (
        "substrateVelocity",
        dimVelocity,
        substrateVelocity()
    );
    checkInletVelocity(Us.value());

    eqn -= fvm::Sp(coeff, eqn.psi());
    eqn += coeff*Us;
}


void Foam::fv::enthalpyPorosity::addSup
(
    const volScalarField& rho,
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    addSup(eqn, fieldi);
}


bool Foam::fv::enthalpyPorosity::read(const dictionary& dict)
{
    if (cellSetOption::read(dict))
    {
        readCoeffs();
        return true;
    }

    return false;
}


// ************************************************************************* //
