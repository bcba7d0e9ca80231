// SPDX-License-Identifier: GPL-3.0-or-later
/*---------------------------------------------------------------------------*\
Application
    nmmVoronoiGrains

Description
    A polycrystal in a box: the Voronoi tessellation of random seed points,
    clipped to the box, written as a block list for system/nmmMeshDict
    (constant/geometry/<output>) with a preview PNG (<output>.png).

    The box is the sub-dictionary 'box { min (x0 y0); max (x1 y1); }'.
    Seeds are uniform in the box (std::mt19937_64 with the given seed,
    53-bit uniform numbers made by hand, so one seed gives the same file
    on every machine). 'lloydIterations' Lloyd steps then move each seed
    to the centroid of its clipped cell, which evens out the grain sizes
    and lengthens the shortest edges.

    Grain size: meanGrainSize d is the equivalent-circle diameter of the
    mean grain, area per grain = pi d^2/4, so nGrains = round(box area /
    (pi d^2/4)). Give either nGrains or meanGrainSize.

    Neighbouring grains share their boundaries exactly. The cells are
    computed with exact constructions (CGAL's Epeck kernel: the Voronoi
    vertices are the circumcentres of the Delaunay triangles, the cells
    are clipped to the box by Boolean_set_operations_2), every distinct
    exact vertex is rounded to the nearest double once and that double is
    used by every grain that has the vertex. A Voronoi edge that meets the
    box makes one vertex on the box side, held by both grains.

    Tiny edges: vertices closer than mergeTolerance times the mean grain
    size (default 1e-6) are merged in every grain that has them; a vertex
    on the box wins over an interior one, so the box stays straight. The
    shortest remaining edge is reported relative to the mean grain size;
    Lloyd steps are the way to lengthen it.

    Log: number of grains, mean, smallest and largest grain area, the
    coefficient of variation of the areas before each Lloyd step, the
    shortest edge, the files written. Input errors name the file, line
    and keyword (exit code 1).

Usage
    nmmVoronoiGrains [-case <dir>] [-help]

    system/nmmVoronoiGrainsDict:

        box             { min (0 0); max (0.01 0.005); }
        meanGrainSize   1e-3;       // or: nGrains 60;
        seed            1;
        lloydIterations 5;
        material        rock;
        namePrefix      grain;      // grain0, grain1, ...
        output          grains;     // constant/geometry/grains(.png)

    system/nmmMeshDict, relative #include paths being relative to the
    including file:

        blocks ( #include "<constant>/geometry/grains" );
\*---------------------------------------------------------------------------*/

#include "nmmGeometryTools/blockList/blockList.H"
#include "nmmSolid/io/boxExtent/boxExtent.H"
#include "nmmGeometryTools/geometryCase/geometryCase.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/io/dictionary/dictionary.H"
#include "nmmSolid/io/dictionary/keywordTable.H"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <array>
#include <bitset>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{

using kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using point = kernel::Point_2;
using polygon = CGAL::Polygon_2<kernel>;
using polygonWithHoles = CGAL::Polygon_with_holes_2<kernel>;
using delaunay = CGAL::Delaunay_triangulation_2<kernel>;
using vector2 = Eigen::Vector2d;

constexpr double pi = 3.14159265358979323846;


// * * * * * * * * * * * * * * * * Input  * * * * * * * * * * * * * * * * //

const nmm::keywordTable& keywords()
{
    static const nmm::keywordTable table = []
    {
        nmm::keywordTable t("nmmVoronoiGrainsDict",
            "Voronoi grains of random seeds, clipped to a box");
        t.subDict("box", "the box the grains fill: { min (x0 y0); max (x1 y1); }")
            .required();
        t.integer("nGrains", "number of grains (or give meanGrainSize)").atLeast(1);
        t.scalar("meanGrainSize", "equivalent-circle diameter of the mean grain, "
            "area per grain pi d^2/4 (or give nGrains)", "m").above(0);
        t.integer("seed", "seed of the random seed points").required().atLeast(0);
        t.integer("lloydIterations", "Lloyd steps (seed to its cell's centroid)")
            .defaultValue(0).atLeast(0);
        t.scalar("mergeTolerance", "vertices closer than this fraction of the "
            "mean grain size are merged").defaultValue(1e-6).range(0, 0.1);
        t.word("material", "material of every grain").required();
        t.word("namePrefix", "grain names are <namePrefix><index>, from 0")
            .defaultValue("grain");
        t.fileName("output", "written to constant/geometry/<output> and <output>.png")
            .defaultValue("grains");
        return t;
    }();
    return table;
}


struct settings
{
    nmm::boxExtent box;
    std::size_t nGrains;
    double meanSize;            // equivalent-circle diameter [m]
    std::uint64_t seed;
    int lloydIterations;
    double mergeTolerance;
    std::string material, namePrefix;
    std::filesystem::path output;
};


//- nGrains and meanGrainSize: exactly one is given, the other follows
void readGrainCount(const nmm::dictionary& dict, settings& s)
{
    const nmm::entry* count = dict.findEntry("nGrains");
    const nmm::entry* size = dict.findEntry("meanGrainSize");
    if (count && size)
    {
        throw size->error("give either 'nGrains' or 'meanGrainSize', not both");
    }
    if (!count && !size)
    {
        throw nmm::IOerror("give one of 'nGrains' (number of grains) or "
            "'meanGrainSize' (equivalent-circle diameter of the mean grain, [m])",
            dict.where(), "nGrains");
    }
    const double area = s.box.area();
    if (count)
    {
        s.nGrains = std::size_t(keywords().get<long long>(dict, "nGrains"));
        s.meanSize = std::sqrt(4*area/(pi*double(s.nGrains)));
        return;
    }
    s.meanSize = keywords().get<double>(dict, "meanGrainSize");
    const double grainArea = pi*s.meanSize*s.meanSize/4;
    if (grainArea > area)
    {
        std::ostringstream os;
        os << "meanGrainSize " << s.meanSize << " is larger than the box: one "
           << "grain of that size (area pi d^2/4 = " << grainArea
           << ") exceeds the box's area " << area;
        throw size->error(os.str());
    }
    s.nGrains = std::size_t(std::max(1.0, std::round(area/grainArea)));
}


settings readSettings(const nmm::dictionary& dict)
{
    keywords().validate(dict);
    settings s;
    s.box = nmm::boxExtent::read(dict.subDict("box"));
    readGrainCount(dict, s);
    s.seed = std::uint64_t(keywords().get<long long>(dict, "seed"));
    s.lloydIterations = int(keywords().get<long long>(dict, "lloydIterations"));
    s.mergeTolerance = keywords().get<double>(dict, "mergeTolerance");
    s.material = keywords().get<std::string>(dict, "material");
    s.namePrefix = keywords().get<std::string>(dict, "namePrefix");
    s.output = keywords().getFileName(dict, "output");
    return s;
}


// * * * * * * * * * * * * * * * * Seeds  * * * * * * * * * * * * * * * * //

//- Uniform in [0, 1) from the top 53 bits: std::uniform_real_distribution
//  differs between standard libraries
double uniform(std::mt19937_64& rng)
{
    return double(rng() >> 11)*0x1.0p-53;
}


std::vector<vector2> drawSeeds(const settings& s)
{
    std::mt19937_64 rng(s.seed);
    const nmm::boxExtent& b = s.box;
    std::vector<vector2> seeds;
    seeds.reserve(s.nGrains);
    while (seeds.size() < s.nGrains)
    {
        const double x = b.x0 + (b.x1 - b.x0)*uniform(rng);
        const double y = b.y0 + (b.y1 - b.y0)*uniform(rng);
        seeds.emplace_back(x, y);
    }
    return seeds;
}


// * * * * * * * * * * * * * * * * Cells  * * * * * * * * * * * * * * * * //

//- The double nearest to an exact number (ties to even). CGAL::to_double
//  of a lazy number may return the middle of an interval 1e-5 wide, and
//  the exact types round or truncate depending on the library.
template<class exactNumber>
double nearestDouble(const exactNumber& x)
{
    const auto evenMantissa = [](double v)
    {
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        return (bits & 1u) == 0;
    };
    const double d = CGAL::to_double(x);
    const double inf = std::numeric_limits<double>::infinity();
    double best = d;
    exactNumber bestError = CGAL::abs(x - exactNumber(d));
    for (const double c : {std::nextafter(d, -inf), std::nextafter(d, inf)})
    {
        const exactNumber error = CGAL::abs(x - exactNumber(c));
        if (error < bestError || (error == bestError && evenMantissa(c)))
        {
            best = c;
            bestError = error;
        }
    }
    return best;
}


vector2 rounded(const point& p)
{
    return {nearestDouble(CGAL::exact(p.x())), nearestDouble(CGAL::exact(p.y()))};
}


polygon boxPolygon(const nmm::boxExtent& b)
{
    const std::vector<point> corners
    {
        {b.x0, b.y0}, {b.x1, b.y0}, {b.x1, b.y1}, {b.x0, b.y1}
    };
    return polygon(corners.begin(), corners.end());
}


//- Delaunay triangulation of the seeds and four far points: the far
//  points close every seed's cell without changing it inside the box
//  (they are more than a box diagonal farther from any point of the box
//  than the nearest seed). Returns the seeds' vertices, in order.
std::vector<delaunay::Vertex_handle> triangulate
(
    delaunay& dt,
    const std::vector<vector2>& seeds,
    const nmm::boxExtent& b
)
{
    const double cx = (b.x0 + b.x1)/2, cy = (b.y0 + b.y1)/2;
    const double far = 10*std::hypot(b.x1 - b.x0, b.y1 - b.y0);
    for (const double sx : {-far, far})
    {
        for (const double sy : {-far, far}) dt.insert(point(cx + sx, cy + sy));
    }
    std::vector<delaunay::Vertex_handle> vertices;
    vertices.reserve(seeds.size());
    delaunay::Face_handle hint;
    for (const vector2& s : seeds)
    {
        const std::size_t before = dt.number_of_vertices();
        const auto v = dt.insert(point(s.x(), s.y()), hint);
        if (dt.number_of_vertices() == before)
        {
            std::ostringstream os;
            os << std::setprecision(17) << "two seed points coincide at ("
               << s.x() << ' ' << s.y() << "); try another seed";
            throw nmm::fatalError(os.str());
        }
        vertices.push_back(v);
        hint = v->face();
    }
    return vertices;
}


//- Voronoi cell of an interior vertex: the circumcentres of its
//  triangles, counter-clockwise (cocircular seeds repeat a centre)
polygon voronoiCell(const delaunay& dt, delaunay::Vertex_handle v)
{
    std::vector<point> pts;
    auto f = dt.incident_faces(v);
    const auto end = f;
    do
    {
        const point c = dt.dual(f);
        if (pts.empty() || c != pts.back()) pts.push_back(c);
    } while (++f != end);
    while (pts.size() > 1 && pts.front() == pts.back()) pts.pop_back();
    return polygon(pts.begin(), pts.end());
}


polygon clipToBox(const polygon& cell, const polygon& boxPoly, const nmm::boxExtent& b)
{
    const kernel::Iso_rectangle_2 rect(b.x0, b.y0, b.x1, b.y1);
    const bool inside = std::none_of(cell.vertices_begin(), cell.vertices_end(),
        [&](const point& p) { return rect.has_on_unbounded_side(p); });
    if (inside) return cell;

    std::vector<polygonWithHoles> parts;
    CGAL::intersection(cell, boxPoly, std::back_inserter(parts));
    if (parts.size() != 1 || parts.front().has_holes())
    {
        // A convex cell around a seed inside the box meets it in one piece
        throw nmm::fatalError("clipping a Voronoi cell to the box gave "
            + std::to_string(parts.size()) + " pieces");
    }
    return parts.front().outer_boundary();
}


//- The seeds' Voronoi cells clipped to the box, exact, in seed order
std::vector<polygon> clippedCells(const std::vector<vector2>& seeds, const nmm::boxExtent& b)
{
    delaunay dt;
    const auto vertices = triangulate(dt, seeds, b);
    const polygon boxPoly = boxPolygon(b);
    std::vector<polygon> cells;
    cells.reserve(vertices.size());
    for (const auto& v : vertices)
    {
        cells.push_back(clipToBox(voronoiCell(dt, v), boxPoly, b));
    }
    return cells;
}


double loopCentroidArea(const nmm::pointLoop& loop, vector2& centroid)
{
    double twiceArea = 0;
    vector2 moment = vector2::Zero();
    for (std::size_t i = 0, n = loop.size(); i < n; ++i)
    {
        const vector2& p = loop[i];
        const vector2& q = loop[(i + 1)%n];
        const double c = p.x()*q.y() - q.x()*p.y();
        twiceArea += c;
        moment += c*(p + q);
    }
    centroid = moment/(3*twiceArea);
    return twiceArea/2;
}


double coefficientOfVariation(const std::vector<double>& values)
{
    const double n = double(values.size());
    const double mean = std::accumulate(values.begin(), values.end(), 0.0)/n;
    double sq = 0;
    for (const double v : values) sq += (v - mean)*(v - mean);
    return std::sqrt(sq/n)/mean;
}


//- One Lloyd step: each seed to its clipped cell's centroid; returns the
//  coefficient of variation of the cell areas before the step
double lloydStep(std::vector<vector2>& seeds, const std::vector<polygon>& cells)
{
    std::vector<double> areas;
    for (std::size_t i = 0; i < cells.size(); ++i)
    {
        nmm::pointLoop loop;
        for (const point& p : cells[i].vertices()) loop.push_back(rounded(p));
        areas.push_back(loopCentroidArea(loop, seeds[i]));
    }
    return coefficientOfVariation(areas);
}


// * * * * * * * * * * * * * * * Shared vertices * * * * * * * * * * * * * //

enum boxSide : unsigned { onLeft = 1, onRight = 2, onBottom = 4, onTop = 8 };


//- The grains as indices into one list of distinct points
struct tessellation
{
    std::vector<vector2> points;
    std::vector<unsigned> sides;            // boxSide bits of each point
    std::vector<std::vector<std::size_t>> cells;
};


unsigned sidesOf(const point& p, const nmm::boxExtent& b)
{
    using FT = kernel::FT;
    return (p.x() == FT(b.x0) ? onLeft : 0u) | (p.x() == FT(b.x1) ? onRight : 0u)
        | (p.y() == FT(b.y0) ? onBottom : 0u) | (p.y() == FT(b.y1) ? onTop : 0u);
}


//- Index the distinct exact vertices and round each once, so that every
//  grain holding a vertex holds the same double
tessellation shareVertices(const std::vector<polygon>& cells, const nmm::boxExtent& b)
{
    const auto less = [](const point& p, const point& q)
    {
        return CGAL::compare_xy(p, q) == CGAL::SMALLER;
    };
    std::map<point, std::size_t, decltype(less)> index(less);
    tessellation t;
    for (const polygon& cell : cells)
    {
        std::vector<std::size_t> loop;
        for (const point& p : cell.vertices())
        {
            const auto [it, fresh] = index.try_emplace(p, t.points.size());
            if (fresh)
            {
                t.points.push_back(rounded(p));
                t.sides.push_back(sidesOf(p, b));
            }
            loop.push_back(it->second);
        }
        t.cells.push_back(std::move(loop));
    }
    return t;
}


//- Union-find whose root is the point that stays: the one on more box
//  sides (a corner, then a side point), then the lower index
class pointMerger
{
    std::vector<std::size_t> parent_;
    const std::vector<unsigned>& sides_;

    bool better(std::size_t a, std::size_t b) const
    {
        const auto na = std::bitset<4>(sides_[a]).count();
        const auto nb = std::bitset<4>(sides_[b]).count();
        return na != nb ? na > nb : a < b;
    }

public:
    explicit pointMerger(const std::vector<unsigned>& sides)
    :
        parent_(sides.size()),
        sides_(sides)
    {
        std::iota(parent_.begin(), parent_.end(), std::size_t(0));
    }

    std::size_t root(std::size_t i)
    {
        while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
        return i;
    }

    //- False when a and b were merged already
    bool merge(std::size_t a, std::size_t b)
    {
        a = root(a);
        b = root(b);
        if (a == b) return false;
        if (better(a, b)) parent_[b] = a; else parent_[a] = b;
        return true;
    }
};


//- Merge the ends of every edge no longer than tol in all grains; a
//  merged point keeps the box sides of all it replaces. Returns the
//  number of points merged away.
std::size_t mergeShortEdges(tessellation& t, double tol)
{
    pointMerger m(t.sides);
    std::size_t merged = 0;
    for (bool again = true; again;)
    {
        again = false;
        for (const auto& cell : t.cells)
        {
            for (std::size_t i = 0, n = cell.size(); i < n; ++i)
            {
                const std::size_t a = m.root(cell[i]), b = m.root(cell[(i + 1)%n]);
                if (a != b && (t.points[a] - t.points[b]).norm() <= tol && m.merge(a, b))
                {
                    ++merged;
                    again = true;
                }
            }
        }
    }
    if (merged == 0) return 0;

    std::vector<unsigned> sides(t.sides.size(), 0u);
    for (std::size_t i = 0; i < t.points.size(); ++i) sides[m.root(i)] |= t.sides[i];
    for (auto& cell : t.cells)
    {
        std::vector<std::size_t> loop;
        for (const std::size_t i : cell)
        {
            const std::size_t r = m.root(i);
            if (loop.empty() || loop.back() != r) loop.push_back(r);
        }
        while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
        cell = std::move(loop);
    }
    t.sides = std::move(sides);
    return merged;
}


//- Points merged across a corner take the box's coordinates
void snapToBox(tessellation& t, const nmm::boxExtent& b)
{
    for (std::size_t i = 0; i < t.points.size(); ++i)
    {
        if (t.sides[i] & onLeft) t.points[i].x() = b.x0;
        if (t.sides[i] & onRight) t.points[i].x() = b.x1;
        if (t.sides[i] & onBottom) t.points[i].y() = b.y0;
        if (t.sides[i] & onTop) t.points[i].y() = b.y1;
    }
}


double shortestEdge(const tessellation& t)
{
    double shortest = std::numeric_limits<double>::infinity();
    for (const auto& cell : t.cells)
    {
        for (std::size_t i = 0, n = cell.size(); i < n; ++i)
        {
            shortest = std::min(shortest,
                (t.points[cell[i]] - t.points[cell[(i + 1)%n]]).norm());
        }
    }
    return shortest;
}


// * * * * * * * * * * * * * * * * Output * * * * * * * * * * * * * * * * //

nmm::blockList makeBlocks(const tessellation& t, const settings& s)
{
    nmm::blockList blocks;
    for (std::size_t g = 0; g < t.cells.size(); ++g)
    {
        const auto& cell = t.cells[g];
        if (cell.size() < 3)
        {
            throw nmm::fatalError("grain " + std::to_string(g) + " has fewer "
                "than three vertices after merging short edges; lower "
                "'mergeTolerance' or raise 'lloydIterations'");
        }
        nmm::pointLoop loop;
        for (const std::size_t i : cell) loop.push_back(t.points[i]);
        blocks.add({s.namePrefix + std::to_string(g), s.material, std::move(loop), {}});
    }
    return blocks;
}


template<class T>
void row(const std::string& name, const T& value)
{
    std::cout << "    " << std::left << std::setw(26) << (name + ":") << std::right
        << value << "\n";
}


void reportAreas(const nmm::blockList& blocks, const nmm::boxExtent& b)
{
    std::vector<double> areas;
    for (const auto& s : blocks.shapes()) areas.push_back(nmm::loopArea(s.outer));
    const auto [lo, hi] = std::minmax_element(areas.begin(), areas.end());
    const double total = blocks.materialArea();
    std::cout << std::setprecision(6);
    row("grains", blocks.size());
    row("mean grain area", total/double(areas.size()));
    row("smallest grain area", *lo);
    row("largest grain area", *hi);
    row("area coefficient of var.", coefficientOfVariation(areas));
    row("grain area / box area", total/b.area());
}


std::string fileComment(const settings& s)
{
    std::ostringstream os;
    os << "nmmVoronoiGrains: " << s.nGrains << " Voronoi grains of material "
       << s.material << " in the box " << s.box.text() << "\n"
       << "seed " << s.seed << ", lloydIterations " << s.lloydIterations
       << ", mean grain size (equivalent-circle diameter) "
       << std::setprecision(6) << s.meanSize;
    return os.str();
}


int run(int argc, char* argv[])
{
    nmm::argList args("nmmVoronoiGrains",
        "Voronoi grains of random seeds in a box, as blocks for nmmMeshDict");
    args.addKeywordHelp("system/nmmVoronoiGrainsDict", keywords());
    args.addKeywordHelp("system/nmmVoronoiGrainsDict, 'box'", nmm::boxExtent::keywords());
    args.setDocumentation
    (
        "Reads system/nmmVoronoiGrainsDict, draws nGrains seeds uniformly in "
        "the box (or as many as meanGrainSize, the equivalent-circle diameter, "
        "gives), relaxes them by Lloyd steps, clips their Voronoi cells to "
        "the box with exact arithmetic and writes constant/geometry/<output> "
        "(include it in nmmMeshDict's 'blocks') and <output>.png. "
        "Neighbouring grains share their vertices bit for bit."
    );
    if (args.parse(argc, argv) == nmm::argList::parseResult::done) return 0;
    args.printBanner(std::cout);

    const fs::path casePath = args.casePath();
    const nmm::dictionary dict = nmm::readUtilityDict(casePath, "nmmVoronoiGrainsDict");
    const settings s = readSettings(dict);
    std::cout << "Box " << s.box.text() << ", " << s.nGrains << " grains, mean "
        << "grain size (equivalent-circle diameter) " << s.meanSize << " m\n";

    std::vector<vector2> seeds = drawSeeds(s);
    std::vector<polygon> cells = clippedCells(seeds, s.box);
    for (int it = 1; it <= s.lloydIterations; ++it)
    {
        const double cv = lloydStep(seeds, cells);
        cells = clippedCells(seeds, s.box);
        std::cout << "Lloyd step " << it << ": area coefficient of variation "
            << std::setprecision(4) << cv << " before it\n";
    }

    tessellation t = shareVertices(cells, s.box);
    const std::size_t merged = mergeShortEdges(t, s.mergeTolerance*s.meanSize);
    snapToBox(t, s.box);
    const nmm::blockList blocks = makeBlocks(t, s);

    std::cout << "\nGrains\n";
    reportAreas(blocks, s.box);
    const double shortest = shortestEdge(t);
    row("vertices merged", merged);
    std::ostringstream edge;
    edge << std::setprecision(4) << shortest << " m (" << shortest/s.meanSize
        << " of the mean grain size)";
    row("shortest edge", edge.str());

    const auto w = nmm::writeGeometry(casePath, s.output, blocks, fileComment(s));
    std::cout << "\nWritten\n    " << w.file.lexically_relative(casePath).string()
        << "\n    " << w.preview.lexically_relative(casePath).string() << "\n\nEnd\n";
    return 0;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    return nmm::catchFatalErrors([&] { return run(argc, argv); });
}
