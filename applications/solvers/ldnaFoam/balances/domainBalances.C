/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "domainBalances.H"
#include "fvcVolumeIntegrate.H"
#include "SolverPerformance.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::domainBalances::domainBalances(const fvMesh& mesh)
:
    mesh_(mesh),
    file_(mesh, "balances", "balances"),
    energyIterations_(0),
    energyUnconverged_(0),
    fillerFile_(),
    fillerClipped_(0)
{
    file_.writeHeader
    (
        "Domain totals and solver health per time step: metal mass [kg],"
        " total enthalpy [J], temperature range [K], liquid metal volume"
        " [m3], metal fraction range; energy iteration and linear solves"
        " of the step",
        {
            "metalMass", "totalEnthalpy", "Tmin", "Tmax",
            "liquidMetalVolume", "alphaMin", "alphaMax",
            "energyIterations", "energyUnconverged", "linearSolves",
            "maxLinearIterations", "maxFinalResidual", "nonFiniteSolves"
        }
    );
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
void Foam::domainBalances::addSolves
(
    const entry& e,
    label& solves,
    label& maxIterations,
    scalar& maxFinalResidual,
    label& nonFinite
)
{
    const List<SolverPerformance<Type>> performances(e.stream());
    for (const SolverPerformance<Type>& sp : performances)
    {
        ++solves;
        const typename pTraits<Type>::labelType& iterations =
            sp.nIterations();
        for (direction d = 0; d < pTraits<Type>::nComponents; ++d)
        {
            maxIterations = max(maxIterations, component(iterations, d));
        }
        const scalar initial = cmptMax(sp.initialResidual());
        const scalar final = cmptMax(sp.finalResidual());
        if (!std::isfinite(initial) || !std::isfinite(final))
        {
            ++nonFinite;
        }
        else
        {
            maxFinalResidual = max(maxFinalResidual, final);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::domainBalances::energySolved
(
    const label iterations,
    const bool converged
)
{
    energyIterations_ = max(energyIterations_, iterations);
    if (!converged)
    {
        ++energyUnconverged_;
    }
}


void Foam::domainBalances::write
(
    const metalGasMixture& mixture,
    const volScalarField& T,
    const volScalarField& alpha1
)
{
    const scalar metalMass = mixture.metalMass();
    const scalar totalEnthalpy = mixture.totalEnthalpy();
    const scalar Tmin = gMin(T.primitiveField());
    const scalar Tmax = gMax(T.primitiveField());
    const scalar liquidVolume =
        fvc::domainIntegrate(alpha1*mixture.liquidFraction()).value();
    const scalar alphaMin = gMin(alpha1.primitiveField());
    const scalar alphaMax = gMax(alpha1.primitiveField());

    Info<< "Balance at t = " << mesh_.time().timeName()
        << ": metal mass = " << metalMass
        << " kg, total enthalpy = " << totalEnthalpy << " J"
        << ", min/max T = " << Tmin << " / " << Tmax << " K"
        << ", liquid metal volume = " << liquidVolume << " m3" << endl;

    // The linear solves of this step (the mesh keeps those of the current
    // time step only; before the first step there are none)
    label solves = 0;
    label maxIterations = 0;
    scalar maxFinalResidual = 0;
    label nonFinite = 0;
    if (mesh_.time().timeIndex() > mesh_.time().startTimeIndex())
    {
        for (const entry& e : mesh_.solverPerformanceDict())
        {
            if (mesh_.foundObject<volVectorField>(e.keyword()))
            {
                addSolves<vector>
                (
                    e, solves, maxIterations, maxFinalResidual, nonFinite
                );
            }
            else
            {
                addSolves<scalar>
                (
                    e, solves, maxIterations, maxFinalResidual, nonFinite
                );
            }
        }
    }

    file_.writeRow
    ({
        metalMass, totalEnthalpy, Tmin, Tmax, liquidVolume, alphaMin,
        alphaMax, scalar(energyIterations_), scalar(energyUnconverged_),
        scalar(solves), scalar(maxIterations), maxFinalResidual,
        scalar(nonFinite)
    });

    energyIterations_ = 0;
    energyUnconverged_ = 0;

    if (mixture.twoMetals())
    {
        writeFiller(mixture, alpha1);
    }
}


void Foam::domainBalances::writeFiller
(
    const metalGasMixture& mixture,
    const volScalarField& alpha1
)
{
    if (!fillerFile_.valid())
    {
        fillerFile_.reset(new tableFile(mesh_, "balances", "filler"));
        fillerFile_->writeHeader
        (
            "Filler metal per time step: its volume [m3], the volume the"
            " clip of the filler fraction to [0, 1] added in the run [m3],"
            " the range of the filler fraction in cells with metal",
            {"fillerVolume", "clippedVolume", "fillerMin", "fillerMax"}
        );
    }

    const scalarField& c = mixture.fillerFraction().primitiveField();
    scalar cMin = GREAT;
    scalar cMax = -GREAT;
    forAll(c, celli)
    {
        if (alpha1[celli] > 0)
        {
            cMin = min(cMin, c[celli]);
            cMax = max(cMax, c[celli]);
        }
    }
    reduce(cMin, minOp<scalar>());
    reduce(cMax, maxOp<scalar>());

    const scalar volume = mixture.fillerVolume();
    Info<< "Filler at t = " << mesh_.time().timeName()
        << ": volume = " << volume << " m3, clipped = " << fillerClipped_
        << " m3, filler fraction in [" << cMin << ", " << cMax << "]"
        << endl;
    fillerFile_->writeRow({volume, fillerClipped_, cMin, cMax});
}


// ************************************************************************* //
