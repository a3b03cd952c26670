/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "metalSources.H"
#include "metalInsertion.H"
#include "optionsImplementing.H"
#include "fieldIO.H"
#include "fvMatrices.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::metalSources::metalSources(const fvMesh& mesh)
:
    mesh_(mesh),
    massSource_
    (
        ldna::stepOnly("metalMassSource", mesh),
        mesh,
        dimensionedScalar(dimDensity/dimTime, Zero)
    ),
    volumeSourceInFlux_
    (
        ldna::handedOn("metalVolumeSourceInFlux", mesh),
        mesh,
        dimensionedScalar(dimless/dimTime, Zero)
    ),
    volumeSourceInAlpha_
    (
        ldna::stepOnly("metalVolumeSourceInAlpha", mesh),
        mesh,
        dimensionedScalar(dimless/dimTime, Zero)
    ),
    volumeCorrection_
    (
        ldna::handedOn("metalVolumeCorrection", mesh),
        mesh,
        dimensionedScalar(dimless, Zero)
    ),
    deferredVolume_
    (
        ldna::handedOn("deferredMetalVolume", mesh),
        mesh,
        dimensionedScalar(dimless, Zero)
    ),
    deferredVolumeNext_
    (
        ldna::stepOnly("deferredMetalVolumeNext", mesh),
        mesh,
        dimensionedScalar(dimless, Zero)
    ),
    deferredEnthalpy_
    (
        ldna::handedOn("deferredMetalEnthalpy", mesh),
        mesh,
        dimensionedScalar(dimEnergy/dimMass, Zero)
    ),
    addedVolume_
    (
        ldna::stepOnly("addedMetalVolume", mesh),
        mesh,
        dimensionedScalar(dimless/dimTime, Zero)
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::metalSources::collect
(
    fv::options& fvOptions,
    const volScalarField& rho1,
    volScalarField& alpha1
)
{
    // The fvOptions acting on the metal fraction with the metal density:
    // S = Su + Sp*alpha1
    massSource_.primitiveFieldRef() =
        (fvOptions(rho1, alpha1) & alpha1)().primitiveField();
}


void Foam::metalSources::alphaSources
(
    const volScalarField& alpha1,
    const volScalarField& rho1,
    const volScalarField::Internal& metalCompression,
    const volScalarField::Internal& gasCompression,
    volScalarField::Internal& Sp,
    volScalarField::Internal& Su
)
{
    // Fractions below this are treated as this when dividing by them
    const scalar alphaFloor = 1e-4;

    // Largest share of a cell's metal a sink removes in one step (the
    // implicit rate for all of it would be infinite)
    const scalar maxLossFraction = 0.999;
    const scalar rDeltaTValue = 1/mesh_.time().deltaTValue();
    const scalarField& alpha10 = alpha1.oldTime().primitiveField();

    forAll(Sp, celli)
    {
        // Metal compression: a gain acts on the gas part (Su + Sp alpha1 =
        // rate (1 - alpha1), nothing in a full cell), a loss on the metal
        // part (compressionSink <= 0)
        const scalar g = -(1 - alpha1[celli])*metalCompression[celli];
        scalar compressionSink = 0;
        if (g > 0)
        {
            const scalar rate = g/max(1 - alpha1[celli], alphaFloor);
            Sp[celli] -= rate;
            Su[celli] += rate;
        }
        else if (g < 0)
        {
            compressionSink = g/max(alpha1[celli], alphaFloor);
            Sp[celli] += compressionSink;
        }

        volumeSourceInAlpha_[celli] = massSource_[celli]/rho1[celli];
        const scalar gain =
            volumeSourceInAlpha_[celli]
          + (volumeCorrection_[celli] + deferredVolume_[celli])*rDeltaTValue;

        // Room in the cell in this step: the largest net source for which
        // alpha1 = 1 still satisfies the upwind predictor with all
        // neighbours full, so that by the maximum principle of its M-matrix
        // no cell exceeds 1.  It is the empty part plus what the flux makes
        // for the source, less the volume the gas compression takes back
        // (gasCompression enters divU), plus what the compression sink
        // removes.  It is negative where the pressure flux would push more
        // metal into a full cell than it can hold
        const scalar room =
            (1 - alpha10[celli])*rDeltaTValue
          + volumeSourceInFlux_[celli]
          - gasCompression[celli]
          - compressionSink;

        // Net source as alpha1 = 1 sees it: a gain explicitly, a loss
        // implicitly (in proportion to the metal in the cell).  The implicit
        // rate is that which removes exactly the share f = -gain dt/alpha10
        // in the step: alpha1 (1 + s dt) = alpha10 gives alpha10 (1 - f) for
        // s = f/(dt (1 - f)) (with s = f/dt it would remove f/(1 + f))
        scalar netSource = gain;
        if (gain < 0)
        {
            const scalar f = min
            (
                -gain/(max(alpha10[celli], alphaFloor)*rDeltaTValue),
                maxLossFraction
            );
            netSource = -f*rDeltaTValue/(1 - f);
            Sp[celli] += netSource;
        }
        else
        {
            Su[celli] += gain;
        }

        // What would overfill the cell is held back and added when there is
        // room, so the metal is neither lost nor squeezed above alpha1 = 1
        const scalar heldBack = max(netSource - room, scalar(0));
        Su[celli] -= heldBack;
        deferredVolumeNext_[celli] = heldBack/rDeltaTValue;
        addedVolume_[celli] = gain > 0 ? gain - heldBack : scalar(0);
    }
}


Foam::tmp<Foam::volScalarField::Internal>
Foam::metalSources::volumeSource(const volScalarField& rho1) const
{
    return (massSource_/rho1)() + volumeCorrection_/mesh_.time().deltaT();
}


void Foam::metalSources::setVolumeSourceInFlux
(
    const volScalarField::Internal& source
)
{
    volumeSourceInFlux_ = source;
}


Foam::tmp<Foam::volScalarField::Internal>
Foam::metalSources::deferredEnthalpySource
(
    const dimensionedScalar& rDeltaT,
    const volScalarField& rho1,
    const volScalarField& h1
) const
{
    return rDeltaT*deferredVolume_*rho1()*(deferredEnthalpy_ - h1());
}


void Foam::metalSources::endStep
(
    const volScalarField& rho1,
    const volScalarField& h1
)
{
    volumeCorrection_ =
        ((massSource_/rho1)() - volumeSourceInAlpha_)*mesh_.time().deltaT();

    deferredVolume_ = deferredVolumeNext_;
    deferredEnthalpy_ = h1.internalField();
}


bool Foam::metalSources::insert
(
    fv::options& fvOptions,
    metalGasMixture& mixture,
    volVectorField& U
)
{
    bool inserted = false;
    for
    (
        metalInsertion& source
      : ldna::optionsImplementing<metalInsertion>(fvOptions)
    )
    {
        if (source.insert(mixture, U))
        {
            inserted = true;
        }
    }

    return returnReduce(inserted, orOp<bool>());
}


// ************************************************************************* //
