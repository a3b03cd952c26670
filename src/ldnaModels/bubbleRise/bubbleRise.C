/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "bubbleRise.H"
#include "uniformDimensionedFields.H"
#include "upwind.H"
#include "checkedInput.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(bubbleRise, 0);
    addToRunTimeSelectionTable(option, bubbleRise, dictionary);
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fv::bubbleRise::readCoeffs()
{
    ldna::checkKeys(coeffs_, {"type", "active", "riseVelocity", "log"});

    riseVelocity_ = ldna::getChecked<scalar>
    (
        coeffs_, "riseVelocity", ldna::interval::openClosed(0, 10)
    );
    log_ = coeffs_.lookupOrDefault<bool>("log", true);

    // The drift enters the metal fraction's flux, no equation's source
    fieldNames_.clear();
    applied_.clear();
}


Foam::vector Foam::fv::bubbleRise::up() const
{
    const uniformDimensionedVectorField& g =
        mesh_.time().lookupObject<uniformDimensionedVectorField>("g");
    const scalar magG = mag(g.value());
    if (!(magG > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "fvOption " << name_ << " (bubbleRise): entry 'value' of"
            << " constant/g is " << g.value() << ": gas rises against"
            << " gravity, so |g| must lie in (0, inf)" << exit(FatalIOError);
    }
    return -g.value()/magG;
}


Foam::tmp<Foam::volScalarField> Foam::fv::bubbleRise::halfToFull
(
    const volScalarField& alpha
)
{
    return max(2*alpha - 1, scalar(0));
}


Foam::tmp<Foam::volScalarField> Foam::fv::bubbleRise::metalBeneath
(
    const volScalarField& alpha1
) const
{
    const vectorField& Sf = mesh_.Sf();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vector eUp = up();

    // Sums of the metal fraction across each cell's downward faces, weighted
    // by their vertical area, and of the weights
    scalarField sum(mesh_.nCells(), Zero);
    scalarField weight(mesh_.nCells(), Zero);

    forAll(own, facei)
    {
        const scalar upArea = eUp & Sf[facei];
        if (upArea > 0)
        {
            // The face is the neighbour's bottom
            sum[nei[facei]] += upArea*alpha1[own[facei]];
            weight[nei[facei]] += upArea;
        }
        else
        {
            sum[own[facei]] -= upArea*alpha1[nei[facei]];
            weight[own[facei]] -= upArea;
        }
    }

    forAll(alpha1.boundaryField(), patchi)
    {
        const fvPatchScalarField& alphap = alpha1.boundaryField()[patchi];
        const scalarField across
        (
            alphap.coupled()
          ? alphap.patchNeighbourField()()
          : scalarField(alphap)
        );
        const vectorField& Sfp = mesh_.Sf().boundaryField()[patchi];
        const labelUList& faceCells = alphap.patch().faceCells();

        forAll(across, facei)
        {
            const scalar downArea = -(eUp & Sfp[facei]);
            if (downArea > 0)
            {
                sum[faceCells[facei]] += downArea*across[facei];
                weight[faceCells[facei]] += downArea;
            }
        }
    }

    tmp<volScalarField> tbeneath
    (
        new volScalarField
        (
            IOobject
            (
                name_ + ":metalBeneath",
                mesh_.time().timeName(),
                mesh_,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh_,
            dimensionedScalar(dimless, Zero)
        )
    );
    volScalarField& beneath = tbeneath.ref();
    forAll(beneath, celli)
    {
        if (weight[celli] > 0)
        {
            beneath[celli] = sum[celli]/weight[celli];
        }
    }
    beneath.correctBoundaryConditions();

    return tbeneath;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::bubbleRise::bubbleRise
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    riseVelocity_(0),
    log_(true),
    loggedTimeIndex_(-1),
    driftFile_(mesh, name, "drift")
{
    readCoeffs();

    driftFile_.writeHeader
    (
        "Metal moved down by the rise of enclosed gas through the melt"
        " [m3/s]",
        {"metalDown"}
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::surfaceScalarField> Foam::fv::bubbleRise::metalDriftFlux
(
    const volScalarField& alpha1,
    const volScalarField& liquidFraction
) const
{
    // The vertical area of each face, positive where the neighbour lies above
    const surfaceScalarField upArea
    (
        "upArea",
        dimensionedVector("up", dimless, up()) & mesh_.Sf()
    );
    const surfaceScalarField downArea("downArea", -upArea);

    // Melt that can sink into the cell below, and gas that lies on metal and
    // can rise; each ramps from none at half metal to all, so that neither a
    // smeared free surface nor a droplet's underside counts
    const volScalarField melt
    (
        "melt",
        halfToFull(alpha1)*min(max(liquidFraction, scalar(0)), scalar(1))
    );
    const volScalarField gasOnMetal
    (
        "gasOnMetal",
        (1 - alpha1)*halfToFull(metalBeneath(alpha1))
    );

    tmp<surfaceScalarField> tdrift
    (
        surfaceScalarField::New
        (
            name_ + ":metalDriftFlux",
           -dimensionedScalar("riseVelocity", dimVelocity, riseVelocity_)*upArea
           *upwind<scalar>(mesh_, downArea).interpolate(melt)
           *upwind<scalar>(mesh_, upArea).interpolate(gasOnMetal)
        )
    );
    surfaceScalarField& drift = tdrift.ref();
    for (fvsPatchScalarField& driftp : drift.boundaryFieldRef())
    {
        if (!driftp.coupled())
        {
            driftp == 0;
        }
    }

    if (log_ && loggedTimeIndex_ != mesh_.time().timeIndex())
    {
        loggedTimeIndex_ = mesh_.time().timeIndex();

        // Every face once: a processor face is on both of its ranks
        scalar metalDown = sum(mag(drift.primitiveField()));
        for (const fvsPatchScalarField& driftp : drift.boundaryField())
        {
            if (driftp.coupled())
            {
                metalDown += 0.5*sum(mag(driftp));
            }
        }
        driftFile_.writeRow({returnReduce(metalDown, sumOp<scalar>())});
    }

    return tdrift;
}


bool Foam::fv::bubbleRise::read(const dictionary& dict)
{
    if (option::read(dict))
    {
        readCoeffs();
        return true;
    }
    return false;
}


// ************************************************************************* //
