/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "fusionLine.H"
#include "volFields.H"
#include "cellLinks.H"
#include "ListListOps.H"
#include "SubList.H"
#include <algorithm>
#include "unitConversion.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

// A link from a cell to the cell above it; links across a refinement
// interface lean by up to about 25 degrees (a coarse cell beside a quarter
// of its face), links to a side neighbour by 90
const Foam::scalar Foam::fusionLine::verticalLinkAngle = Foam::degToRad(30);

// Centres of one column differ by round-off only
const Foam::scalar Foam::fusionLine::columnTolerance = 1e-3;

// The section's line is the deepest of several slices' lines, with kinks
// between their columns: 20 points a cell put the area within 1e-3 of the
// exact envelope's for the tests' half-ellipses
const Foam::label Foam::fusionLine::profileResolution = 20;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::fusionLine::crossed(const scalar depth)
{
    return depth > -0.5*GREAT;
}


void Foam::fusionLine::addLink
(
    const point& a,
    const point& b,
    const scalar Ta,
    const scalar Tb,
    const bool metalA,
    const bool metalB,
    DynamicList<vector>& records,
    scalar& surfaceT
) const
{
    const bool metal = metalA && metalB;
    const vector d = b - a;
    const scalar rise = d & verticalDir_;
    if (mag(rise) < Foam::cos(verticalLinkAngle)*mag(d))
    {
        return;
    }

    // Ordered bottom to top
    const bool aBelow = rise > 0;
    const point& low = aBelow ? a : b;
    const scalar Tlow = aBelow ? Ta : Tb;
    const scalar Thigh = aBelow ? Tb : Ta;
    const scalar vLow = low & verticalDir_;
    const scalar vHigh = vLow + mag(rise);

    // The column passes the surface: it exists, crossed or not
    if (vLow < surfaceHeight_ && vHigh >= surfaceHeight_)
    {
        const scalar lambda = (surfaceHeight_ - vLow)/mag(rise);
        const point p = low + lambda*(aBelow ? d : -d);
        records.append(vector(p & transverseDir_, -GREAT, p & weldDir_));

        const bool metalLow = aBelow ? metalA : metalB;
        if (metalLow)
        {
            surfaceT = max(surfaceT, metal ? Tlow + lambda*(Thigh - Tlow) : Tlow);
        }
    }

    // The isotherm in metal, hot side up (the substrate is heated from above)
    if (metal && Thigh >= temperature_ && Tlow < temperature_)
    {
        const scalar lambda = (temperature_ - Tlow)/(Thigh - Tlow);
        const point p = low + lambda*(aBelow ? d : -d);
        records.append
        (
            vector(p & transverseDir_, surfaceHeight_ - (p & verticalDir_), p & weldDir_)
        );
    }
}


Foam::scalar Foam::fusionLine::lineDepth
(
    const scalarList& position,
    const scalarList& depth,
    const scalar t
)
{
    if (position.size() < 2 || t < position.first() || t > position.last())
    {
        return -GREAT;
    }
    const label k = min
    (
        label(std::upper_bound(position.begin(), position.end(), t) - position.begin()) - 1,
        position.size() - 2
    );
    scalar e0 = depth[k];
    scalar e1 = depth[k + 1];
    if (!crossed(e0) && !crossed(e1))
    {
        return -GREAT;
    }
    // Beside a column without a crossing: the fused column's edge half-way,
    // an unfused column's line unfused
    if (!crossed(e0))
    {
        e0 = e1 > 0 ? -e1 : e1;
    }
    if (!crossed(e1))
    {
        e1 = e0 > 0 ? -e0 : e0;
    }
    const scalar s = (t - position[k])/(position[k + 1] - position[k]);
    return (1 - s)*e0 + s*e1;
}


void Foam::fusionLine::collectSlices
(
    const List<vector>& records,
    List<scalarList>& positions,
    List<scalarList>& depths
)
{
    const scalar tolerance = columnTolerance*shortestLink_;

    // Order every processor count alike: along the weld, then across it,
    // then by depth
    auto before = [&records](const label a, const label b)
    {
        const vector& ra = records[a];
        const vector& rb = records[b];
        if (ra.z() != rb.z()) return ra.z() < rb.z();
        if (ra.x() != rb.x()) return ra.x() < rb.x();
        return ra.y() < rb.y();
    };
    labelList order(identity(records.size()));
    std::sort(order.begin(), order.end(), before);

    DynamicList<scalarList> slicePositions;
    DynamicList<scalarList> sliceDepths;
    DynamicList<scalar> sliceAlong;

    label first = 0;
    while (first < order.size())
    {
        // One slice: positions along the weld within the tolerance
        label last = first;
        while
        (
            last + 1 < order.size()
         && records[order[last + 1]].z() - records[order[first]].z() <= tolerance
        )
        {
            ++last;
        }

        labelList slice(SubList<label>(order, last - first + 1, first));
        std::sort
        (
            slice.begin(), slice.end(),
            [&records](const label a, const label b)
            {
                const vector& ra = records[a];
                const vector& rb = records[b];
                return ra.x() < rb.x() || (ra.x() == rb.x() && ra.y() < rb.y());
            }
        );

        // Its columns: positions across the weld within the tolerance
        DynamicList<scalar> position;
        DynamicList<scalar> depth;
        bool anyCrossing = false;
        for (const label i : slice)
        {
            const vector& r = records[i];
            if (position.empty() || r.x() - position.last() > tolerance)
            {
                position.append(r.x());
                depth.append(r.y());
            }
            else
            {
                depth.last() = max(depth.last(), r.y());
            }
            anyCrossing = anyCrossing || crossed(r.y());
        }

        // A slice without a crossing adds nothing to the section's line
        if (anyCrossing)
        {
            const scalar along = records[order[first]].z();
            forAll(depth, k)
            {
                if (depth[k] > penetration_)
                {
                    penetration_ = depth[k];
                    deepestSection_ = along;
                }
            }
            slicePositions.append(position);
            sliceDepths.append(depth);
        }

        first = last + 1;
    }

    positions.transfer(slicePositions);
    depths.transfer(sliceDepths);
}


void Foam::fusionLine::combineSlices
(
    const List<scalarList>& positions,
    const List<scalarList>& depths
)
{
    // The section's line at a position: the deepest of the slices'
    auto sectionDepth = [&positions, &depths](const scalar t)
    {
        scalar deepest = -GREAT;
        forAll(positions, s)
        {
            deepest = max(deepest, lineDepth(positions[s], depths[s], t));
        }
        return deepest;
    };

    // Written at every column position of every slice
    DynamicList<scalar> columns;
    for (const scalarList& position : positions)
    {
        columns.append(position);
    }
    Foam::sort(columns);
    const scalar tolerance = columnTolerance*shortestLink_;
    DynamicList<scalar> distinct;
    for (const scalar t : columns)
    {
        if (distinct.empty() || t - distinct.last() > tolerance)
        {
            distinct.append(t);
        }
    }
    columns_.transfer(distinct);
    depth_.setSize(columns_.size());
    forAll(columns_, k)
    {
        depth_[k] = sectionDepth(columns_[k]);
    }

    // Fused intervals and area on a fine grid across the section
    DynamicList<segment> fused;
    area_ = 0;
    if (columns_.size() > 1)
    {
        const scalar step = shortestLink_/profileResolution;
        const label n = label(std::ceil((columns_.last() - columns_.first())/step)) + 1;
        scalar t0 = columns_.first();
        scalar e0 = sectionDepth(t0);
        for (label i = 1; i < n; ++i)
        {
            const scalar t1 = min(columns_.first() + i*step, columns_.last());
            const scalar e1 = sectionDepth(t1);
            const bool has0 = crossed(e0);
            const bool has1 = crossed(e1);

            scalar from = t0;
            scalar to = t1;
            scalar piece = 0;
            if (has0 && has1 && e0 > 0 && e1 > 0)
            {
                piece = 0.5*(e0 + e1)*(t1 - t0);
            }
            else if (has0 && has1 && (e0 > 0 || e1 > 0))
            {
                // The edge, where the line passes the surface
                const scalar edge = t0 + (t1 - t0)*e0/(e0 - e1);
                if (e0 > 0)
                {
                    to = edge;
                    piece = 0.5*e0*(edge - t0);
                }
                else
                {
                    from = edge;
                    piece = 0.5*e1*(t1 - edge);
                }
            }

            if (piece > 0)
            {
                area_ += piece;
                if (fused.size() && fused.last().second() >= from)
                {
                    fused.last().second() = to;
                }
                else
                {
                    fused.append(segment(from, to));
                }
            }
            t0 = t1;
            e0 = e1;
        }
    }
    fused_.transfer(fused);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fusionLine::fusionLine
(
    const fvMesh& mesh,
    const vector& weldDir,
    const vector& verticalDir,
    const scalar surfaceHeight,
    const scalar temperature
)
:
    mesh_(mesh),
    weldDir_(weldDir),
    transverseDir_(verticalDir ^ weldDir),
    verticalDir_(verticalDir),
    surfaceHeight_(surfaceHeight),
    temperature_(temperature),
    shortestLink_(GREAT),
    penetration_(0),
    deepestSection_(0),
    area_(0),
    peakSurfaceTemperature_(0)
{
    // The shortest vertical link sets the tolerance of a column
    const vectorField& C = mesh_.C();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    forAll(nei, facei)
    {
        const vector d = C[nei[facei]] - C[own[facei]];
        const scalar rise = mag(d & verticalDir_);
        if (rise >= Foam::cos(verticalLinkAngle)*mag(d))
        {
            shortestLink_ = min(shortestLink_, rise);
        }
    }
    reduce(shortestLink_, minOp<scalar>());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fusionLine::update
(
    const volScalarField& T,
    const volScalarField& alpha,
    const scalar metalThreshold
)
{
    DynamicList<vector> records;
    scalar surfaceT = 0;
    ldna::forAllCellLinks
    (
        mesh_, T.primitiveField(), alpha.primitiveField(),
        [&](const point& a, const point& b, const scalar Ta, const scalar Tb,
            const scalar alphaA, const scalar alphaB)
        {
            addLink
            (
                a, b, Ta, Tb,
                alphaA >= metalThreshold, alphaB >= metalThreshold,
                records, surfaceT
            );
        }
    );

    peakSurfaceTemperature_ = returnReduce(surfaceT, maxOp<scalar>());

    List<List<vector>> all(Pstream::nProcs());
    all[Pstream::myProcNo()].transfer(records);
    Pstream::gatherList(all);
    Pstream::scatterList(all);

    penetration_ = 0;
    deepestSection_ = 0;
    List<scalarList> positions;
    List<scalarList> depths;
    collectSlices
    (
        ListListOps::combine<List<vector>>(all, accessOp<List<vector>>()),
        positions,
        depths
    );
    combineSlices(positions, depths);
}


Foam::scalar
Foam::fusionLine::fusedWidth(const scalar left, const scalar right) const
{
    scalar width = 0;
    for (const segment& s : fused_)
    {
        width += max(scalar(0), min(s.second(), right) - max(s.first(), left));
    }
    return width;
}


void Foam::fusionLine::writeProfile(Ostream& os, const string& time) const
{
    forAll(columns_, k)
    {
        if (crossed(depth_[k]))
        {
            os  << time.c_str() << tab << columns_[k] << tab << depth_[k] << nl;
        }
    }
    os.flush();
}


// ************************************************************************* //
