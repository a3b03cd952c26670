/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "marangoniForce.H"
#include "metalGasMixture.H"
#include "interfaceDelta.H"
#include "cellSource.H"
#include "fvMatrices.H"
#include "fvcGrad.H"
#include "checkedInput.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(marangoniForce, 0);
    addToRunTimeSelectionTable(option, marangoniForce, dictionary);
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fv::marangoniForce::readCoeffs()
{
    ldna::checkKeys
    (
        coeffs_,
        {"type", "active", "alpha", "liquidFraction", "U", "mixture", "log"}
    );

    alphaName_ = coeffs_.lookupOrDefault<word>("alpha", "alpha.metal");
    liquidFractionName_ =
        coeffs_.lookupOrDefault<word>("liquidFraction", "liquidFraction");
    UName_ = coeffs_.lookupOrDefault<word>("U", "U");
    mixtureName_ =
        coeffs_.lookupOrDefault<word>("mixture", "thermophysicalProperties");
    log_ = coeffs_.lookupOrDefault<bool>("log", true);

    fieldNames_.setSize(1, UName_);
    applied_.setSize(1, false);
}


Foam::tmp<Foam::vectorField> Foam::fv::marangoniForce::force()
{
    const volScalarField& alpha =
        mesh_.lookupObject<volScalarField>(alphaName_);
    const volScalarField& liquidFraction =
        mesh_.lookupObject<volScalarField>(liquidFractionName_);
    const metalGasMixture& mixture =
        mesh_.lookupObject<metalGasMixture>(mixtureName_);

    const volVectorField gradSigma(fvc::grad(mixture.sigma()));
    const volVectorField gradAlpha(fvc::grad(alpha));
    const scalarField delta
    (
        metalSurfaceDelta(alpha, gradAlpha)().primitiveField()
    );

    tmp<vectorField> tf(new vectorField(mesh_.nCells(), Zero));
    vectorField& f = tf.ref();

    forAll(f, celli)
    {
        const scalar magGradAlpha = mag(gradAlpha[celli]);
        if (delta[celli] > 0 && magGradAlpha > VSMALL)
        {
            const vector n = gradAlpha[celli]/magGradAlpha;
            const vector tangentialGradSigma =
                gradSigma[celli] - (n & gradSigma[celli])*n;
            const scalar gl = min(max(liquidFraction[celli], scalar(0)), 1);

            f[celli] = gl*delta[celli]*tangentialGradSigma;
        }
    }

    if (loggedTimeIndex_ != mesh_.time().timeIndex())
    {
        loggedTimeIndex_ = mesh_.time().timeIndex();

        // The tangential stress integrated over the surface [N] and the
        // largest stress [N/m2]
        scalar maxStress = 0;
        forAll(f, celli)
        {
            if (delta[celli] > 0)
            {
                maxStress = max(maxStress, mag(f[celli])/delta[celli]);
            }
        }
        reduce(maxStress, maxOp<scalar>());
        const vector total = gSum(f*mesh_.V());

        if (log_)
        {
            Info<< type() << ' ' << name_ << ": total force = " << total
                << " N, max tangential stress = " << maxStress << " N/m2"
                << endl;
        }
        forceFile_.writeRow({total.x(), total.y(), total.z(), maxStress});
    }

    return tf;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::marangoniForce::marangoniForce
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    log_(true),
    loggedTimeIndex_(-1),
    forceFile_(mesh, name, "force")
{
    readCoeffs();

    forceFile_.writeHeader
    (
        "Marangoni force on the metal surface [N] and largest tangential"
        " stress [N/m2]",
        {"force_x", "force_y", "force_z", "maxTangentialStress"}
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fv::marangoniForce::addSup
(
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    eqn += cellSource(eqn, name_ + ":force", force()());
}


void Foam::fv::marangoniForce::addSup
(
    const volScalarField& rho,
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    addSup(eqn, fieldi);
}


bool Foam::fv::marangoniForce::read(const dictionary& dict)
{
    if (option::read(dict))
    {
        readCoeffs();
        return true;
    }
    return false;
}


// ************************************************************************* //
