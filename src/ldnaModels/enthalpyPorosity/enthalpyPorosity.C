/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
\*---------------------------------------------------------------------------*/

#include "enthalpyPorosity.H"
#include "fvMatrices.H"
#include "fvmSup.H"
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
    mushyZoneConstant_ = coeffs_.get<scalar>("mushyZoneConstant");
    if (!(mushyZoneConstant_ > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry 'mushyZoneConstant' must be > 0 kg/m3/s, not "
            << mushyZoneConstant_ << exit(FatalIOError);
    }

    porosityEpsilon_ = coeffs_.get<scalar>("porosityEpsilon");
    if (!(porosityEpsilon_ > 0 && porosityEpsilon_ < 1))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry 'porosityEpsilon' must be in (0, 1), not "
            << porosityEpsilon_ << exit(FatalIOError);
    }

    weldingSpeed_ = Function1<scalar>::New("weldingSpeed", coeffs_);
    {
        const scalar vw = weldingSpeed_->value(mesh_.time().value());
        if (!(vw >= 0))
        {
            FatalIOErrorInFunction(coeffs_)
                << "Entry 'weldingSpeed' must be >= 0 m/s (the direction is"
                << " set by 'weldingDirection'), not " << vw
                << " at t = " << mesh_.time().value() << " s"
                << exit(FatalIOError);
        }
    }

    weldingDirection_ = coeffs_.get<vector>("weldingDirection");
    if (mag(weldingDirection_) < VSMALL)
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry 'weldingDirection' must be a non-zero vector, not "
            << weldingDirection_ << exit(FatalIOError);
    }
    weldingDirection_ /= mag(weldingDirection_);

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
    if (!(vw >= 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry 'weldingSpeed' must be >= 0 m/s, not " << vw
            << " at t = " << t << " s" << exit(FatalIOError);
    }
    return vw*weldingDirection_;
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

    // Every cell that holds metal, in proportion to its metal: a thin solid
    // film or a frozen splash is held as firmly per unit of metal as the
    // substrate (a threshold on alpha let films below it drift freely)
    for (const label celli : cells_)
    {
        const scalar metal = min(max(alpha[celli], scalar(0)), scalar(1));
        const scalar gl = min(max(liquidFraction[celli], scalar(0)), scalar(1));
        coeff[celli] =
            metal*mushyZoneConstant_*sqr(1 - gl)/(pow3(gl) + porosityEpsilon_);
    }

    const dimensionedVector Us
    (
        "substrateVelocity",
        dimVelocity,
        substrateVelocity()
    );

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
