// SPDX-License-Identifier: GPL-3.0-or-later
/*---------------------------------------------------------------------------*\
Application
    nmmPlatelets

Description
    Clay platelets: non-overlapping rectangles or ellipses placed at random
    in a box, written as a block list for system/nmmMeshDict
    (constant/geometry/<output>) with a preview PNG (<output>.png).

    The box is the sub-dictionary 'box { min (x0 y0); max (x1 y1); }'.
    Random sequential addition: for each platelet in turn draw a length
    (length*(1 + lengthSpread*r), r uniform in [-1, 1)), an angle of the
    long axis (orientation + orientationSpread*r degrees from x) and a
    centre, and accept the platelet when it keeps at least minGap from the
    walls and from every platelet placed before; otherwise draw again, at
    most maxAttempts times per platelet. Equivalently, platelets grown by
    minGap/2 do not overlap and stay minGap/2 inside the box. With minGap 0
    they may not touch either. The centre is drawn uniformly in the part of
    the box where the drawn platelet clears the walls, which is the same
    distribution as drawing in the whole box and rejecting, with fewer
    attempts.

    The distance between two platelets is that of their vertices as
    written (doubles): computed in double arithmetic (separating axes for
    an overlap, vertex-to-edge distances otherwise), and when that is
    within 1e-9 (relative to the coordinates) of minGap, exactly by CGAL's
    Polytope_distance_d. A platelet is tested only against those in
    neighbouring cells of a grid, and only when their circumscribed circles
    come within minGap.

    Shapes: thickness = length/aspectRatio; a rectangle is length x
    thickness; an ellipse with semi-axes a = length/2, b = thickness/2 is
    a polygon of ellipseVertices vertices on it (area (n/2) a b sin(2 pi/n),
    below pi a b).

    Random numbers: std::mt19937_64 with the given seed and 53-bit uniform
    numbers made by hand, so one seed gives the same file with every
    standard library.

    When a platelet cannot be placed in maxAttempts draws the utility stops
    (exit code 1) saying how many were placed; it never loops for ever.
    Log: number placed, solid fraction (platelet area / box area), attempts.

Usage
    nmmPlatelets [-case <dir>] [-help]

    system/nmmPlateletsDict:

        box               { min (0 0); max (1e-5 1e-5); }
        shape             rectangle;      // or ellipse (ellipseVertices 16)
        number            40;
        length            2e-6;
        lengthSpread      0.2;
        aspectRatio       10;
        orientation       0;
        orientationSpread 20;
        minGap            5e-8;
        seed              1;
        material          clay;

    system/nmmMeshDict, relative #include paths being relative to the
    including file:

        blocks ( matrix { ... holes ( ... ); } #include "<constant>/geometry/platelets" );
\*---------------------------------------------------------------------------*/

#include "nmmGeometryTools/blockList/blockList.H"
#include "nmmSolid/io/boxExtent/boxExtent.H"
#include "nmmGeometryTools/geometryCase/geometryCase.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/io/dictionary/dictionary.H"
#include "nmmSolid/io/dictionary/keywordTable.H"

#include <CGAL/Polytope_distance_d.h>
#include <CGAL/Polytope_distance_d_traits_2.h>
#include <CGAL/Simple_cartesian.h>
#ifdef CGAL_USE_GMP
#include <CGAL/Gmpzf.h>
#else
#include <CGAL/MP_Float.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{

using vector2 = Eigen::Vector2d;

constexpr double pi = 3.14159265358979323846;


// * * * * * * * * * * * * * * * * Input  * * * * * * * * * * * * * * * * //

const nmm::keywordTable& keywords()
{
    static const nmm::keywordTable table = []
    {
        nmm::keywordTable t("nmmPlateletsDict",
            "non-overlapping platelets placed at random in a box");
        t.subDict("box", "the box: { min (x0 y0); max (x1 y1); }").required();
        t.word("shape", "platelet shape").choices({"rectangle", "ellipse"}).required();
        t.integer("ellipseVertices", "vertices of the polygon on an ellipse")
            .defaultValue(16).atLeast(4);
        t.integer("number", "number of platelets").required().atLeast(1);
        t.scalar("length", "mean length (long axis)", "m").required().above(0);
        t.scalar("lengthSpread", "relative spread of the length, uniform "
            "+-lengthSpread*length").defaultValue(0).atLeast(0).below(1);
        t.scalar("aspectRatio", "length/thickness").required().atLeast(1);
        t.scalar("orientation", "mean angle of the long axis from x", "deg")
            .defaultValue(0);
        t.scalar("orientationSpread", "spread of the angle, uniform +-", "deg")
            .defaultValue(0).range(0, 180);
        t.scalar("minGap", "smallest distance between two platelets and "
            "between a platelet and the box", "m").required().atLeast(0);
        t.integer("seed", "seed of the random placement").required().atLeast(0);
        t.integer("maxAttempts", "draws per platelet before giving up")
            .defaultValue(10000).atLeast(1);
        t.word("material", "material of every platelet").required();
        t.word("namePrefix", "platelet names are <namePrefix><index>, from 0")
            .defaultValue("platelet");
        t.fileName("output", "written to constant/geometry/<output> and <output>.png")
            .defaultValue("platelets");
        return t;
    }();
    return table;
}


struct settings
{
    nmm::boxExtent box;
    bool ellipse;
    int ellipseVertices;
    std::size_t number;
    double length, lengthSpread, aspectRatio;
    double orientation, orientationSpread;      // [deg]
    double minGap;
    std::uint64_t seed;
    std::size_t maxAttempts;
    std::string material, namePrefix;
    std::filesystem::path output;
};


settings readSettings(const nmm::dictionary& dict)
{
    const nmm::keywordTable& k = keywords();
    k.validate(dict);
    settings s;
    s.box = nmm::boxExtent::read(dict.subDict("box"));
    s.ellipse = k.get<std::string>(dict, "shape") == "ellipse";
    s.ellipseVertices = int(k.get<long long>(dict, "ellipseVertices"));
    s.number = std::size_t(k.get<long long>(dict, "number"));
    s.length = k.get<double>(dict, "length");
    s.lengthSpread = k.get<double>(dict, "lengthSpread");
    s.aspectRatio = k.get<double>(dict, "aspectRatio");
    s.orientation = k.get<double>(dict, "orientation");
    s.orientationSpread = k.get<double>(dict, "orientationSpread");
    s.minGap = k.get<double>(dict, "minGap");
    s.seed = std::uint64_t(k.get<long long>(dict, "seed"));
    s.maxAttempts = std::size_t(k.get<long long>(dict, "maxAttempts"));
    s.material = k.get<std::string>(dict, "material");
    s.namePrefix = k.get<std::string>(dict, "namePrefix");
    s.output = k.getFileName(dict, "output");
    return s;
}


// * * * * * * * * * * * * * * * Platelets  * * * * * * * * * * * * * * * //

//- Uniform in [0, 1) from the top 53 bits: std::uniform_real_distribution
//  differs between standard libraries
double uniform(std::mt19937_64& rng)
{
    return double(rng() >> 11)*0x1.0p-53;
}


//- Uniform in [-1, 1)
double symmetric(std::mt19937_64& rng)
{
    return 2*uniform(rng) - 1;
}


struct platelet
{
    vector2 centre;
    double radius;              // of the circle around it, from the centre
    nmm::pointLoop loop;        // counter-clockwise
};


//- The outline around the origin, long axis at angle (radians) from x
nmm::pointLoop outline(const settings& s, double length, double angle)
{
    const double a = length/2, b = length/s.aspectRatio/2;
    const vector2 u(std::cos(angle), std::sin(angle)), v(-u.y(), u.x());
    nmm::pointLoop loop;
    if (!s.ellipse)
    {
        const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const auto& c : corners) loop.push_back(c[0]*a*u + c[1]*b*v);
        return loop;
    }
    for (int k = 0; k < s.ellipseVertices; ++k)
    {
        const double phi = 2*pi*k/s.ellipseVertices;
        loop.push_back(a*std::cos(phi)*u + b*std::sin(phi)*v);
    }
    return loop;
}


//- Draw one platelet clear of the walls, or nothing when the drawn size
//  and angle cannot clear them anywhere
bool drawPlatelet(const settings& s, std::mt19937_64& rng, platelet& p)
{
    const double length = s.length*(1 + s.lengthSpread*symmetric(rng));
    const double angle = (s.orientation + s.orientationSpread*symmetric(rng))*pi/180;
    const nmm::pointLoop local = outline(s, length, angle);
    vector2 lo = vector2::Constant(std::numeric_limits<double>::infinity());
    vector2 hi = -lo;
    for (const vector2& q : local)
    {
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
    }
    const nmm::boxExtent& b = s.box;
    const vector2 cLo(b.x0 + s.minGap - lo.x(), b.y0 + s.minGap - lo.y());
    const vector2 cHi(b.x1 - s.minGap - hi.x(), b.y1 - s.minGap - hi.y());
    const double ux = uniform(rng), uy = uniform(rng);
    if (!(cLo.x() <= cHi.x() && cLo.y() <= cHi.y())) return false;

    p.centre = vector2(cLo.x() + (cHi.x() - cLo.x())*ux, cLo.y() + (cHi.y() - cLo.y())*uy);
    p.loop.clear();
    p.radius = 0;
    for (const vector2& q : local)
    {
        p.loop.push_back(p.centre + q);
        p.radius = std::max(p.radius, (p.loop.back() - p.centre).norm());
    }
    // The centre's rounding may take a vertex an ulp too close to a wall
    return std::all_of(p.loop.begin(), p.loop.end(), [&](const vector2& q)
    {
        return q.x() - b.x0 >= s.minGap && b.x1 - q.x() >= s.minGap
            && q.y() - b.y0 >= s.minGap && b.y1 - q.y() >= s.minGap;
    });
}


// * * * * * * * * * * * * * * * * Distance * * * * * * * * * * * * * * * //

#ifdef CGAL_USE_GMP
using exactNumber = CGAL::Gmpzf;
#else
using exactNumber = CGAL::MP_Float;
#endif
using distanceKernel = CGAL::Simple_cartesian<double>;
using polytopeDistance = CGAL::Polytope_distance_d
<
    CGAL::Polytope_distance_d_traits_2<distanceKernel, exactNumber, double>
>;


//- Exact: whether the written doubles of two platelets keep minGap apart
//  (and, for minGap 0, do not touch)
bool apartExact(const platelet& p, const platelet& q, double minGap)
{
    const auto points = [](const nmm::pointLoop& loop)
    {
        std::vector<distanceKernel::Point_2> pts;
        for (const vector2& v : loop) pts.emplace_back(v.x(), v.y());
        return pts;
    };
    const auto pp = points(p.loop), qq = points(q.loop);
    const polytopeDistance d(pp.begin(), pp.end(), qq.begin(), qq.end());
    const exactNumber num = d.squared_distance_numerator();
    const exactNumber gap2 = exactNumber(minGap)*exactNumber(minGap)
        *d.squared_distance_denominator();
    return CGAL::is_positive(num) && !(num < gap2);
}


//- Largest separation of q from p along p's outward edge normals
double separation(const nmm::pointLoop& p, const nmm::pointLoop& q)
{
    double best = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0, n = p.size(); i < n; ++i)
    {
        const vector2 e = p[(i + 1)%n] - p[i];
        const vector2 normal = vector2(e.y(), -e.x()).normalized();
        double nearest = std::numeric_limits<double>::infinity();
        for (const vector2& v : q) nearest = std::min(nearest, normal.dot(v - p[i]));
        best = std::max(best, nearest);
    }
    return best;
}


double pointSegmentDistance(const vector2& v, const vector2& a, const vector2& b)
{
    const vector2 e = b - a;
    const double t = std::clamp((v - a).dot(e)/e.squaredNorm(), 0.0, 1.0);
    return (v - a - t*e).norm();
}


//- Distance between convex polygons, in doubles; negative when they
//  overlap (minus the depth: the separating-axis test is exact for
//  convex polygons)
double signedDistance(const nmm::pointLoop& p, const nmm::pointLoop& q)
{
    const double s = std::max(separation(p, q), separation(q, p));
    if (s <= 0) return s;
    double d = std::numeric_limits<double>::infinity();
    for (int pass = 0; pass < 2; ++pass)
    {
        const nmm::pointLoop& a = pass ? q : p;
        const nmm::pointLoop& b = pass ? p : q;
        for (const vector2& v : a)
        {
            for (std::size_t i = 0, n = b.size(); i < n; ++i)
            {
                d = std::min(d, pointSegmentDistance(v, b[i], b[(i + 1)%n]));
            }
        }
    }
    return d;
}


//- Whether two platelets keep minGap apart: the double distance decides
//  unless it is within rounding of minGap, then the exact one does
bool apart(const platelet& p, const platelet& q, double minGap)
{
    // Far apart by their circles (the margin covers the circles' rounding)
    const double reach = (p.radius + q.radius + minGap)*(1 + 1e-9);
    if ((p.centre - q.centre).squaredNorm() > reach*reach) return true;

    const double scale = p.centre.cwiseAbs().maxCoeff() + p.radius + q.radius;
    const double slack = 1e-9*scale;
    const double d = signedDistance(p.loop, q.loop);
    if (d > minGap + slack) return true;
    if (d < minGap - slack) return false;
    return apartExact(p, q, minGap);
}


//- Platelets indexed by the grid cell of their centre; the cells are at
//  least as wide as a platelet's reach, so the 3 x 3 cells around a
//  centre hold every platelet that can come within minGap of it
class plateletGrid
{
    nmm::boxExtent box_;
    double h_;
    int nx_, ny_;
    std::vector<std::vector<std::size_t>> cells_;

    int column(double x) const { return std::clamp(int((x - box_.x0)/h_), 0, nx_ - 1); }
    int row(double y) const { return std::clamp(int((y - box_.y0)/h_), 0, ny_ - 1); }

public:
    plateletGrid(const nmm::boxExtent& b, double reach, std::size_t number)
    :
        box_(b)
    {
        // At most about 4 cells a platelet: a small reach in a large box
        // must not make a huge grid
        const double smallest = std::sqrt(b.area()/(4.0*double(number) + 16));
        h_ = std::max(reach*(1 + 1e-6), smallest);
        nx_ = std::max(1, int(std::ceil((b.x1 - b.x0)/h_)));
        ny_ = std::max(1, int(std::ceil((b.y1 - b.y0)/h_)));
        cells_.resize(std::size_t(nx_)*std::size_t(ny_));
    }

    void insert(const vector2& c, std::size_t i)
    {
        cells_[std::size_t(row(c.y()))*std::size_t(nx_) + std::size_t(column(c.x()))]
            .push_back(i);
    }

    //- Call f(i) for each platelet near c
    template<class F>
    bool allNear(const vector2& c, F f) const
    {
        const int i0 = column(c.x()), j0 = row(c.y());
        for (int j = std::max(0, j0 - 1); j <= std::min(ny_ - 1, j0 + 1); ++j)
        {
            for (int i = std::max(0, i0 - 1); i <= std::min(nx_ - 1, i0 + 1); ++i)
            {
                for (const std::size_t k : cells_[std::size_t(j)*std::size_t(nx_) + std::size_t(i)])
                {
                    if (!f(k)) return false;
                }
            }
        }
        return true;
    }
};


// * * * * * * * * * * * * * * * * Placement  * * * * * * * * * * * * * * //

struct placement
{
    std::vector<platelet> platelets;
    std::size_t attempts = 0, mostAttempts = 0;
};


//- Largest distance from a centre at which two platelets can interact
double interactionReach(const settings& s)
{
    const double longest = s.length*(1 + s.lengthSpread);
    return std::hypot(longest, longest/s.aspectRatio) + s.minGap;
}


placement place(const settings& s, const nmm::dictionary& dict)
{
    std::mt19937_64 rng(s.seed);
    placement result;
    plateletGrid grid(s.box, interactionReach(s), s.number);
    auto& placed = result.platelets;
    while (placed.size() < s.number)
    {
        std::size_t tries = 0;
        platelet p;
        bool ok = false;
        while (!ok && tries < s.maxAttempts)
        {
            ++tries;
            ok = drawPlatelet(s, rng, p) && grid.allNear(p.centre,
                [&](std::size_t k) { return apart(p, placed[k], s.minGap); });
        }
        result.attempts += tries;
        result.mostAttempts = std::max(result.mostAttempts, tries);
        if (!ok)
        {
            throw dict.lookupEntry("number").error("placed "
                + std::to_string(placed.size()) + " of " + std::to_string(s.number)
                + " platelets: they do not fit; lower 'number' or 'length', or "
                "raise the box (platelet " + std::to_string(placed.size())
                + " found no place in maxAttempts " + std::to_string(s.maxAttempts)
                + " draws)");
        }
        grid.insert(p.centre, placed.size());
        placed.push_back(std::move(p));
    }
    return result;
}


// * * * * * * * * * * * * * * * * Output * * * * * * * * * * * * * * * * //

template<class T>
void row(const std::string& name, const T& value)
{
    std::cout << "    " << std::left << std::setw(24) << (name + ":") << std::right
        << value << "\n";
}


std::string fileComment(const settings& s)
{
    std::ostringstream os;
    os << "nmmPlatelets: " << s.number << ' '
       << (s.ellipse ? "ellipses (" + std::to_string(s.ellipseVertices) + "-gons)"
                     : std::string("rectangles"))
       << " of material " << s.material << ", length " << s.length
       << " +-" << s.lengthSpread << ", aspectRatio " << s.aspectRatio << "\n"
       << "orientation " << s.orientation << " +-" << s.orientationSpread
       << " deg, minGap " << s.minGap << ", seed " << s.seed;
    return os.str();
}


int run(int argc, char* argv[])
{
    nmm::argList args("nmmPlatelets",
        "Non-overlapping platelets at random in a box, as blocks for nmmMeshDict");
    args.addKeywordHelp("system/nmmPlateletsDict", keywords());
    args.addKeywordHelp("system/nmmPlateletsDict, 'box'", nmm::boxExtent::keywords());
    args.setDocumentation
    (
        "Reads system/nmmPlateletsDict and places 'number' rectangles or "
        "ellipses (polygons) one after another at random in the box, each at "
        "least minGap from the walls and from the others (random sequential "
        "addition, at most maxAttempts draws per platelet), then writes "
        "constant/geometry/<output> (include it in nmmMeshDict's 'blocks') "
        "and <output>.png. Exit code 1 when they do not fit."
    );
    if (args.parse(argc, argv) == nmm::argList::parseResult::done) return 0;
    args.printBanner(std::cout);

    const fs::path casePath = args.casePath();
    const nmm::dictionary dict = nmm::readUtilityDict(casePath, "nmmPlateletsDict");
    const settings s = readSettings(dict);

    const placement result = place(s, dict);
    nmm::blockList blocks;
    for (std::size_t i = 0; i < result.platelets.size(); ++i)
    {
        blocks.add({s.namePrefix + std::to_string(i), s.material,
            result.platelets[i].loop, {}});
    }

    std::cout << "Platelets\n" << std::setprecision(6);
    row("placed", blocks.size());
    row("solid fraction", blocks.materialArea()/s.box.area());
    row("attempts", result.attempts);
    row("most for one platelet", std::to_string(result.mostAttempts)
        + " (maxAttempts " + std::to_string(s.maxAttempts) + ")");

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
