/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
\*---------------------------------------------------------------------------*/

#include "metalProperties.H"
#include "checkedInput.H"
#include "physicalLimits.H"

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


// ************************************************************************* //
