/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "tableFile.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::tableFile::tableFile
(
    const objectRegistry& obr,
    const fileName& prefix,
    const word& name
)
:
    functionObjects::writeFile(obr, prefix, name, dictionary())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::tableFile::writeHeader
(
    const string& description,
    const wordList& columns,
    const word& firstColumn
)
{
    if (writeToFile())
    {
        OFstream& os = file();
        functionObjects::writeFile::writeHeader(os, description);
        writeCommented(os, firstColumn);
        for (const word& column : columns)
        {
            writeTabbed(os, column);
        }
        os  << endl;
    }
}


void Foam::tableFile::writeRow(const scalarList& values)
{
    if (writeToFile())
    {
        writeCurrentTime(file());
        writeValues(values);
    }
}


void Foam::tableFile::writeRow(const scalar x, const scalarList& values)
{
    if (writeToFile())
    {
        file() << x;
        writeValues(values);
    }
}


void Foam::tableFile::writeValues(const scalarList& values)
{
    OFstream& os = file();
    for (const scalar value : values)
    {
        os  << tab << value;
    }
    os  << endl;
}


// ************************************************************************* //
