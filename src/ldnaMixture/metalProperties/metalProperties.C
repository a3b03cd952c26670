/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "metalProperties.H"
#include "checkedInput.H"
#include "physicalLimits.H"
#include "tableFile.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::metalProperties::metalProperties
(
    const dictionary& dict,
    const scalar Tmin,
    const scalar Tmax,
    const scalar Tref
)
:
    meltingRange(dict),
    Tref_(Tref)
{
    namespace limits = ldna::limits;
    const scalar Ts = Tsolidus();
    const scalar Tl = Tliquidus();

    // Solid and liquid functions of a property, each on its range of use
    auto readPhases = [&]
    (
        const word& property,
        autoPtr<temperatureTable>& solid,
        autoPtr<temperatureTable>& liquid,
        const scalar maxValue,
        const bool withIntegral
    )
    {
        const dictionary& phases = dict.subDict(property);
        ldna::checkKeys(phases, {"solid", "liquid"});
        solid = temperatureTable::New
        (
            phases, "solid", Tmin, Ts, maxValue, withIntegral
        );
        liquid = temperatureTable::New
        (
            phases, "liquid", Tl, Tmax, maxValue, withIntegral
        );
    };

    readPhases("rho", rhoSolid_, rhoLiquid_, limits::density, false);
    readPhases("Cp", CpSolid_, CpLiquid_, limits::specificHeat, true);
    readPhases
    (
        "kappa", kappaSolid_, kappaLiquid_, limits::conductivity, false
    );
    muLiquid_ = temperatureTable::New(dict, "mu", Tl, Tmax, limits::viscosity);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::metalProperties::Cp(const scalar T) const
{
    const scalar Ts = Tsolidus();
    const scalar Tl = Tliquidus();
    if (T <= Ts)
    {
        return CpSolid_->value(T);
    }
    if (T >= Tl)
    {
        return CpLiquid_->value(T);
    }
    const scalar CpS = CpSolid_->value(Ts);
    const scalar CpL = CpLiquid_->value(Tl);
    return CpS + (CpL - CpS)*(T - Ts)/(Tl - Ts);
}


Foam::scalar Foam::metalProperties::sensibleEnthalpy(const scalar T) const
{
    const scalar Ts = Tsolidus();
    const scalar Tl = Tliquidus();

    if (T <= Ts)
    {
        return CpSolid_->integrate(Tref_, T);
    }

    // Mushy range: Cp linear in T between the solid and liquid values
    const scalar CpS = CpSolid_->value(Ts);
    const scalar CpL = CpLiquid_->value(Tl);
    const scalar hs = CpSolid_->integrate(Tref_, Ts);
    const scalar dT = min(T, Tl) - Ts;
    const scalar hMushy =
        hs + CpS*dT + 0.5*(CpL - CpS)*sqr(dT)/(Tl - Ts);

    if (T < Tl)
    {
        return hMushy;
    }
    return hMushy + CpLiquid_->integrate(Tl, T);
}


Foam::scalar Foam::metalProperties::density
(
    const scalar T,
    const scalar gl
) const
{
    // Each phase's function is used on its own range only
    return
        (1 - gl)*rhoSolid_->value(min(T, Tsolidus()))
      + gl*rhoLiquid_->value(max(T, Tliquidus()));
}


Foam::scalar Foam::metalProperties::conductivity
(
    const scalar T,
    const scalar gl
) const
{
    return
        (1 - gl)*kappaSolid_->value(min(T, Tsolidus()))
      + gl*kappaLiquid_->value(max(T, Tliquidus()));
}


Foam::scalar Foam::metalProperties::viscosity(const scalar T) const
{
    return muLiquid_->value(max(T, Tliquidus()));
}


void Foam::metalProperties::writeTable
(
    const objectRegistry& obr,
    const fileName& prefix,
    const word& tableName,
    const scalar Tmin,
    const scalar Tmax,
    const scalar dT
) const
{
    // Enough digits that a balance computed from the table agrees with the
    // solver's own to well below any test tolerance (1e-9 relative)
    const label precision = 12;

    tableFile table(obr, prefix, tableName);
    if (!table.writeToFile())
    {
        return;
    }
    table.file().precision(precision);
    table.writeHeader
    (
        "Metal properties at equilibrium (liquidFraction of T); "
        "rhoSolid, rhoLiquid: the density at liquid fraction 0 and 1 "
        "(linear in between); enthalpy: sensible from "
      + name(Tref_) + " K plus latent [J/kg]",
        {
            "liquidFraction", "sensibleEnthalpy", "enthalpy",
            "rhoSolid", "rhoLiquid", "Cp", "kappa"
        },
        "T"
    );

    DynamicList<scalar> temperatures;
    for (scalar T = Tmin; T < Tmax + 0.5*dT; T += dT)
    {
        temperatures.append(T);
    }
    // The mushy range's Cp rises linearly from the solid's to the liquid's
    // value over a range that may be only a few kelvin: its enthalpy is
    // tabulated on a finer grid, within dCp (Tl - Ts)/8e4 of the solver's
    const label mushySteps = 100;
    for (label i = 0; i <= mushySteps; ++i)
    {
        temperatures.append
        (
            Tsolidus() + (Tliquidus() - Tsolidus())*i/mushySteps
        );
    }
    Foam::sort(temperatures);

    scalar previous = -GREAT;
    for (const scalar T : temperatures)
    {
        if (T - previous < SMALL*dT)
        {
            continue;
        }
        previous = T;
        const scalar gl = equilibriumLiquidFraction(T);
        const scalar hs = sensibleEnthalpy(T);
        table.writeRow
        (
            T,
            {
                gl, hs, hs + gl*latentHeat(),
                density(T, 0), density(T, 1), Cp(T), conductivity(T, gl)
            }
        );
    }
}


// ************************************************************************* //
