/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
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
    energyUnconverged_(0)
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
}


// ************************************************************************* //
