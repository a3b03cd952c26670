/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "metalDensityModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(metalDensityModel, 0);
    defineRunTimeSelectionTable(metalDensityModel, dictionary);
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::metalDensityModel> Foam::metalDensityModel::New
(
    const dictionary& metalDict
)
{
    const word model
    (
        metalDict.lookupOrDefault<word>("densityModel", "Boussinesq")
    );
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(model);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            metalDict, "densityModel", model, *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    Info<< "    " << metalDict.dictName() << " density: " << model;
    autoPtr<metalDensityModel> density(cstrIter()(metalDict));
    Info<< endl;
    return density;
}


// ************************************************************************* //
