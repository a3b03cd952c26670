/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "metalComposition.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::metalComposition::metalComposition
(
    const dictionary& fillerDict,
    const dictionary* baseDict,
    const scalar Tmin,
    const scalar Tmax,
    const scalar Tref
)
:
    filler_(new metalProperties(fillerDict, Tmin, Tmax, Tref)),
    fillerDensity_(metalDensityModel::New(fillerDict)),
    base_(),
    baseDensity_(),
    fillerReferenceDensity_(0),
    baseReferenceDensity_(0)
{
    // The cold solid's density of mass: the density models' at Tref
    fillerReferenceDensity_ =
        fillerDensity_->massDensity(filler_->density(Tref, 0));

    if (baseDict)
    {
        base_.reset(new metalProperties(*baseDict, Tmin, Tmax, Tref));
        baseDensity_ = metalDensityModel::New(*baseDict);
        baseReferenceDensity_ =
            baseDensity_->massDensity(base_->density(Tref, 0));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::metalComposition::fillerMassShare(const scalar c) const
{
    if (!base_.valid())
    {
        return 1;
    }
    const scalar filler = c*fillerReferenceDensity_;
    return filler/(filler + (1 - c)*baseReferenceDensity_);
}


Foam::meltingRange Foam::metalComposition::range(const scalar c) const
{
    if (!base_.valid())
    {
        return *filler_;
    }
    return filler_->blend(fillerMassShare(c), *base_);
}


Foam::scalar Foam::metalComposition::density
(
    const scalar T,
    const scalar gl,
    const scalar c
) const
{
    if (!base_.valid())
    {
        return filler_->density(T, gl);
    }
    return c*filler_->density(T, gl) + (1 - c)*base_->density(T, gl);
}


Foam::scalar Foam::metalComposition::massDensity
(
    const scalar T,
    const scalar gl,
    const scalar c
) const
{
    const scalar filler = fillerDensity_->massDensity(filler_->density(T, gl));
    if (!base_.valid())
    {
        return filler;
    }
    return
        c*filler
      + (1 - c)*baseDensity_->massDensity(base_->density(T, gl));
}


Foam::scalar Foam::metalComposition::Cp(const scalar T, const scalar c) const
{
    if (!base_.valid())
    {
        return filler_->Cp(T);
    }
    const scalar w = fillerMassShare(c);
    return w*filler_->Cp(T) + (1 - w)*base_->Cp(T);
}


Foam::scalar Foam::metalComposition::sensibleEnthalpy
(
    const scalar T,
    const scalar c
) const
{
    if (!base_.valid())
    {
        return filler_->sensibleEnthalpy(T);
    }
    const scalar w = fillerMassShare(c);
    return
        w*filler_->sensibleEnthalpy(T) + (1 - w)*base_->sensibleEnthalpy(T);
}


Foam::scalar Foam::metalComposition::conductivity
(
    const scalar T,
    const scalar gl,
    const scalar c
) const
{
    if (!base_.valid())
    {
        return filler_->conductivity(T, gl);
    }
    return
        c*filler_->conductivity(T, gl) + (1 - c)*base_->conductivity(T, gl);
}


Foam::scalar Foam::metalComposition::viscosity
(
    const scalar T,
    const scalar c
) const
{
    if (!base_.valid())
    {
        return filler_->viscosity(T);
    }
    return c*filler_->viscosity(T) + (1 - c)*base_->viscosity(T);
}


void Foam::metalComposition::writeTables
(
    const objectRegistry& obr,
    const fileName& prefix,
    const scalar Tmin,
    const scalar Tmax,
    const scalar dT
) const
{
    filler_->writeTable(obr, prefix, "metal", Tmin, Tmax, dT);
    if (base_.valid())
    {
        base_->writeTable(obr, prefix, "substrate", Tmin, Tmax, dT);
    }
}


// ************************************************************************* //
