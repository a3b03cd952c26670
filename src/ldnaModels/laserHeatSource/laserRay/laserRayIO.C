/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
\*---------------------------------------------------------------------------*/

#include "laserRay.H"
#include "IOstreams.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

Foam::string Foam::laserRay::propertyList_ = Foam::laserRay::propertyList();

const std::size_t Foam::laserRay::sizeofFields_
(
    sizeof(laserRay) - sizeof(particle)
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::laserRay::laserRay
(
    const polyMesh& mesh,
    Istream& is,
    bool readFields,
    bool newFormat
)
:
    particle(mesh, is, readFields, newFormat),
    p0_(Zero),
    p1_(Zero),
    surfaceNormal_(Zero),
    power_(0),
    nEvents_(0),
    reflectedCell_(-1)
{
    if (readFields)
    {
        if (is.format() == IOstream::ASCII)
        {
            is >> p0_ >> p1_ >> surfaceNormal_ >> power_ >> nEvents_
                >> reflectedCell_;
        }
        else if (!is.checkLabelSize<>() || !is.checkScalarSize<>())
        {
            is.beginRawRead();
            readRawScalar(is, p0_.data(), vector::nComponents);
            readRawScalar(is, p1_.data(), vector::nComponents);
            readRawScalar(is, surfaceNormal_.data(), vector::nComponents);
            readRawScalar(is, &power_);
            readRawLabel(is, &nEvents_);
            readRawLabel(is, &reflectedCell_);
            is.endRawRead();
        }
        else
        {
            is.read(reinterpret_cast<char*>(&p0_), sizeofFields_);
        }
    }

    // Cell labels are local to the processor the ray came from
    reflectedCell_ = -1;

    is.check(FUNCTION_NAME);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::laserRay::writeProperties
(
    Ostream& os,
    const wordRes& filters,
    const word& delim,
    const bool namesOnly
) const
{
    particle::writeProperties(os, filters, delim, namesOnly);

    #undef  writeProp
    #define writeProp(Name, Value)                                            \
        particle::writeProperty(os, Name, Value, namesOnly, delim, filters)

    writeProp("p0", p0_);
    writeProp("p1", p1_);
    writeProp("surfaceNormal", surfaceNormal_);
    writeProp("power", power_);
    writeProp("nEvents", nEvents_);
    writeProp("reflectedCell", reflectedCell_);

    #undef writeProp
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

Foam::Ostream& Foam::operator<<(Ostream& os, const laserRay& p)
{
    if (os.format() == IOstream::ASCII)
    {
        os  << static_cast<const particle&>(p)
            << token::SPACE << p.p0_
            << token::SPACE << p.p1_
            << token::SPACE << p.surfaceNormal_
            << token::SPACE << p.power_
            << token::SPACE << p.nEvents_
            << token::SPACE << p.reflectedCell_;
    }
    else
    {
        os  << static_cast<const particle&>(p);
        os.write
        (
            reinterpret_cast<const char*>(&p.p0_),
            laserRay::sizeofFields_
        );
    }

    os.check(FUNCTION_NAME);
    return os;
}


// ************************************************************************* //
