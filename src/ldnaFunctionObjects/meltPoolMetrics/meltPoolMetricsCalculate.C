/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "meltPoolMetrics.H"
#include "volFields.H"
#include "cellLinks.H"
#include "ListListOps.H"
#include <algorithm>

// * * * * * * * * * * * * * * * Local Constants  * * * * * * * * * * * * * * //

// Cell centres of one row of the bead section differ by round-off only
// (relative to the cell length)
static const Foam::scalar rowHeightTolerance = 1e-3;

// Relative difference of two slice areas taken as round-off: the bead of a
// uniform cross-section has equal areas in all its slices
static const Foam::scalar sliceAreaTolerance = 1e-6;


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::label Foam::functionObjects::meltPoolMetrics::slice(const scalar w) const
{
    const label i = label(std::floor((w - sliceOrigin_)/sliceLength_));
    return min(max(i, 0), nSlices_ - 1);
}


Foam::labelPair Foam::functionObjects::meltPoolMetrics::slices
(
    const boundBox& cellBounds
) const
{
    // Slice i's centre plane lies at origin + (i + 1/2) L: inside the cell
    // for i from ceil(min/L - 1/2) to ceil(max/L - 1/2) - 1
    const auto first = [&](const scalar w)
    {
        return label(std::ceil((w - sliceOrigin_)/sliceLength_ - 0.5));
    };
    return labelPair
    (
        max(first(cellBounds.min().x()), 0),
        min(first(cellBounds.max().x()) - 1, nSlices_ - 1)
    );
}


Foam::scalar
Foam::functionObjects::meltPoolMetrics::sliceCentre(const label i) const
{
    return sliceOrigin_ + (i + 0.5)*sliceLength_;
}


Foam::label Foam::functionObjects::meltPoolMetrics::largestSlice
(
    const scalarList& areas
) const
{
    // Of slices equal to round-off (a uniform bead), the most downstream
    const scalar largest = max(areas);
    label i = areas.size() - 1;
    while (i > 0 && areas[i] < (1 - sliceAreaTolerance)*largest)
    {
        --i;
    }
    return i;
}


Foam::point
Foam::functionObjects::meltPoolMetrics::weldFrame(const point& p) const
{
    return point(p & weldDir_, p & transverseDir_, p & verticalDir_);
}


template<class LinkOp>
void Foam::functionObjects::meltPoolMetrics::forAllLinks
(
    const volScalarField& T,
    const volScalarField& alpha,
    const LinkOp& op
) const
{
    ldna::forAllCellLinks
    (
        mesh_, T.primitiveField(), alpha.primitiveField(),
        [&](const point& a, const point& b, const scalar Ta, const scalar Tb,
            const scalar alphaA, const scalar alphaB)
        {
            op(weldFrame(a), weldFrame(b), Ta, Tb, alphaA, alphaB);
        }
    );
}


Foam::functionObjects::meltPoolMetrics::metrics
Foam::functionObjects::meltPoolMetrics::calculate()
{
    const volScalarField& T = lookupObject<volScalarField>(TName_);
    const volScalarField& alpha = lookupObject<volScalarField>(alphaName_);
    const scalarField& V = mesh_.V();

    metrics m;

    // Pass 1: the pool, the peak temperature and the bead area of each slice
    boundBox pool(boundBox::invertedBox);
    scalarList beadArea(nSlices_, Zero);
    scalarList baseArea(nSlices_, Zero);
    const volScalarField* fillerPtr =
        fillerFractionName_.empty()
      ? nullptr
      : &lookupObject<volScalarField>(fillerFractionName_);

    forAll(V, celli)
    {
        const boundBox& bb = cellBounds_[celli];
        const point c = bb.centre();
        const bool isMetal = alpha[celli] >= metalThreshold_;

        if (isMetal)
        {
            m.peakTemperature = max(m.peakTemperature, T[celli]);
        }
        if (isMetal && T[celli] >= poolTemperature_)
        {
            pool.add(weldFrame(mesh_.C()[celli]));
            m.poolVolume += alpha[celli]*V[celli];
        }
        if (c.z() >= surfaceHeight_)
        {
            const scalar area = alpha[celli]*V[celli]/bb.span().x();
            const labelPair cut = slices(bb);
            for (label i = cut.first(); i <= cut.second(); ++i)
            {
                beadArea[i] += area;
                if (fillerPtr)
                {
                    baseArea[i] += (1 - (*fillerPtr)[celli])*area;
                }
            }
        }
    }

    // The pool's edge between cell centres: where the pool isotherm crosses
    // a link from a pool cell to a metal cell outside it (T linear along
    // the link; links to gas end at the surface)
    forAllLinks
    (
        T, alpha,
        [&](const point& a, const point& b, const scalar Ta, const scalar Tb,
            const scalar alphaA, const scalar alphaB)
        {
            if
            (
                alphaA >= metalThreshold_ && alphaB >= metalThreshold_
             && (Ta >= poolTemperature_) != (Tb >= poolTemperature_)
            )
            {
                pool.add(a + ((poolTemperature_ - Ta)/(Tb - Ta))*(b - a));
            }
        }
    );

    reduce(pool.min(), minOp<point>());
    reduce(pool.max(), maxOp<point>());
    reduce(m.poolVolume, sumOp<scalar>());
    reduce(m.peakTemperature, maxOp<scalar>());
    Pstream::listCombineGather(beadArea, plusEqOp<scalar>());
    Pstream::listCombineScatter(beadArea);
    Pstream::listCombineGather(baseArea, plusEqOp<scalar>());
    Pstream::listCombineScatter(baseArea);

    if (m.poolVolume > 0)
    {
        m.poolLength = pool.span().x();
        m.poolWidth = pool.span().y();
    }

    // The fusion line between cell centres
    fusionLine_->update(T, alpha, metalThreshold_);
    m.penetration = fusionLine_->penetration();
    m.fusedArea = fusionLine_->area();
    m.fusedSection = fusionLine_->deepestSection();
    m.peakSurfaceTemperature = fusionLine_->peakSurfaceTemperature();

    // The bead section: given, or the slice of largest bead area
    const label beadSlice =
        fixedBeadSection_ ? slice(beadSection_) : largestSlice(beadArea);
    m.beadSection = sliceCentre(beadSlice);
    m.beadArea = beadArea[beadSlice];

    // Pass 2: the bead in its section.  Each row of the section's shortest
    // cells above the surface reaches from toe to toe, where the metal
    // fraction crosses metalThreshold on a link across the weld (linear
    // along the link); the toes on the surface are extrapolated linearly
    // from the two lowest rows (a toe is a wedge, which the lowest row's
    // centres see half a cell up), then widened to the metal of the longer
    // cells the section cuts on the surface; the top is where the fraction
    // crosses on a vertical link, or the highest metal centre
    const scalar rowTolerance = rowHeightTolerance*sliceLength_;
    enum sectionCell : label { outside, shortCell, longCell, longSurfaceCell };
    scalarField section(V.size(), scalar(outside));
    forAll(V, celli)
    {
        const boundBox& bb = cellBounds_[celli];
        const labelPair cut = slices(bb);
        if
        (
            bb.centre().z() >= surfaceHeight_
         && cut.first() <= beadSlice && beadSlice <= cut.second()
        )
        {
            section[celli] =
                bb.span().x() <= sliceLength_ + rowTolerance ? shortCell
              : mag(bb.min().z() - surfaceHeight_) <= rowTolerance
              ? longSurfaceCell
              : longCell;
        }
    }

    DynamicList<vector2D> rowPoints;   // (height, across)
    scalar top = -GREAT;
    scalar longLeftToe = GREAT;
    scalar longRightToe = -GREAT;
    forAll(V, celli)
    {
        const point c = weldFrame(mesh_.C()[celli]);
        if (alpha[celli] >= metalThreshold_ && section[celli] != outside)
        {
            top = max(top, c.z());
            if (section[celli] == shortCell)
            {
                rowPoints.append(vector2D(c.z(), c.y()));
            }
            else if (section[celli] == longSurfaceCell)
            {
                longLeftToe = min(longLeftToe, c.y());
                longRightToe = max(longRightToe, c.y());
            }
        }
    }
    ldna::forAllCellLinks
    (
        mesh_, section, alpha.primitiveField(),
        [&](const point& pa, const point& pb, const scalar sa, const scalar sb,
            const scalar alphaA, const scalar alphaB)
        {
            if
            (
                sa == outside || sb == outside
             || (alphaA >= metalThreshold_) == (alphaB >= metalThreshold_)
            )
            {
                return;
            }
            const point a = weldFrame(pa);
            const point b = weldFrame(pb);
            const point p =
                a + ((metalThreshold_ - alphaA)/(alphaB - alphaA))*(b - a);
            if (mag(b.z() - a.z()) > rowTolerance)
            {
                if (mag(b.z() - a.z()) >= 0.5*mag(b - a))
                {
                    top = max(top, p.z());
                }
            }
            else if (sa == shortCell && sb == shortCell)
            {
                rowPoints.append(vector2D(p.z(), p.y()));
            }
            else if (sa == longSurfaceCell && sb == longSurfaceCell)
            {
                longLeftToe = min(longLeftToe, p.y());
                longRightToe = max(longRightToe, p.y());
            }
        }
    );
    reduce(longLeftToe, minOp<scalar>());
    reduce(longRightToe, maxOp<scalar>());
    reduce(top, maxOp<scalar>());

    List<List<vector2D>> allRowPoints(Pstream::nProcs());
    allRowPoints[Pstream::myProcNo()].transfer(rowPoints);
    Pstream::gatherList(allRowPoints);
    Pstream::scatterList(allRowPoints);
    List<vector2D> points
    (
        ListListOps::combine<List<vector2D>>
        (
            allRowPoints, accessOp<List<vector2D>>()
        )
    );

    if (points.size() || longLeftToe <= longRightToe)
    {
        // The two lowest rows: height and extent across the weld
        std::sort
        (
            points.begin(), points.end(),
            [](const vector2D& a, const vector2D& b) { return a.x() < b.x(); }
        );
        FixedList<vector, 2> rows(vector(GREAT, GREAT, -GREAT));
        label nRows = 0;
        for (const vector2D& pt : points)
        {
            if (nRows == 0 || pt.x() - rows[nRows - 1].x() > rowTolerance)
            {
                if (nRows == rows.size())
                {
                    break;
                }
                rows[nRows++] = vector(pt.x(), pt.y(), pt.y());
            }
            vector& row = rows[nRows - 1];
            row.y() = min(row.y(), pt.y());
            row.z() = max(row.z(), pt.y());
        }

        scalar leftToe = nRows ? rows[0].y() : GREAT;
        scalar rightToe = nRows ? rows[0].z() : -GREAT;
        if (nRows == 2)
        {
            const scalar s =
                (rows[0].x() - surfaceHeight_)/(rows[1].x() - rows[0].x());
            leftToe -= s*(rows[1].y() - rows[0].y());
            rightToe += s*(rows[0].z() - rows[1].z());
        }
        leftToe = min(leftToe, longLeftToe);
        rightToe = max(rightToe, longRightToe);

        m.beadWidth = max(rightToe - leftToe, scalar(0));
        m.beadHeight = top - surfaceHeight_;
        m.bondedWidth = fusionLine_->fusedWidth(leftToe, rightToe);
        m.unbondedWidth = m.beadWidth - m.bondedWidth;
        // Of a bead only: traces of metal over a bare section are no clad
        m.chemicalDilution = baseArea[beadSlice]/m.beadArea;
    }

    const scalar depositedArea = m.fusedArea + m.beadArea;
    if (depositedArea > 0)
    {
        m.dilution = m.fusedArea/depositedArea;
    }

    return m;
}


// ************************************************************************* //
