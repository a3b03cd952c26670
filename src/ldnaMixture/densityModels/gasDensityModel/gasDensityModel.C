/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "gasDensityModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(gasDensityModel, 0);
    defineRunTimeSelectionTable(gasDensityModel, dictionary);
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::gasDensityModel> Foam::gasDensityModel::New
(
    const dictionary& gasDict
)
{
    const word model
    (
        gasDict.lookupOrDefault<word>("densityModel", "idealGas")
    );
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(model);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            gasDict, "densityModel", model, *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    Info<< "    " << gasDict.dictName() << " density: " << model;
    autoPtr<gasDensityModel> density(cstrIter()(gasDict));
    Info<< endl;
    return density;
}


// ************************************************************************* //
