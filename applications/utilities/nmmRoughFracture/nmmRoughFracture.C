/*---------------------------------------------------------------------------*\
Application
    nmmRoughFracture

Description
    Two blocks, 'lower' and 'upper', split by a rough fracture, read from
    system/nmmRoughFractureDict, written to constant/geometry/<output>
    (a list that nmmMeshDict's 'blocks' includes) with a preview
    constant/geometry/<output>.png.

    Each face is a profile z(x) about the mean plane y = meanHeight:
      - points:     measured (x z) pairs, x increasing, linear in between,
                    cut to the box's width;
      - asperities: a sum of bumps (x height width), cosine or triangle;
      - selfAffine: a sum of cosines with random phases whose amplitudes
                    fall as k^-(H + 1/2) (power spectrum k^-(1 + 2H), the
                    self-affine profile of Hurst exponent H), scaled to the
                    given RMS height;
      - mated:      the upper face only: a copy of the lower face moved by
                    'shift' along x (a sheared, once mated fracture).
    The upper face is then lifted so that the faces' smallest vertical gap
    is 'aperture' (0: they touch at one point). The log gives where that
    point is, and the mean aperture.

    The two faces are also written as patches, 'lowerFace' and
    'upperFace', to constant/geometry/<output>Patches, for nmmMeshDict's
    'patches' to include: the mean closure of the fracture is the
    difference of their mean displacements (function object
    patchDisplacement).

    'columns' adds a confining column of another material on each side,
    'leftColumn' and 'rightColumn', as tall as the box, with a vertex where
    each face meets it so that both blocks share its edge.

Usage
    nmmRoughFracture [-case <dir>] [-help]
\*---------------------------------------------------------------------------*/
// SPDX-License-Identifier: GPL-3.0-or-later

#include "nmmGeometryTools/blockList/blockList.H"
#include "nmmSolid/io/boxExtent/boxExtent.H"
#include "nmmGeometryTools/geometryCase/geometryCase.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/io/dictionary/dictionary.H"
#include "nmmSolid/io/dictionary/keywordTable.H"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <vector>

namespace fs = std::filesystem;

namespace
{

using profile = std::vector<Eigen::Vector2d>;   // (x, z), x increasing
using xyList = std::vector<std::array<double, 2>>;

constexpr double pi = 3.14159265358979323846;

const nmm::keywordTable& keywords()
{
    static const nmm::keywordTable table = []
    {
        nmm::keywordTable t("nmmRoughFractureDict", "two blocks split by a rough fracture");
        t.subDict("box", "the two blocks' extent: min (x0 y0); max (x1 y1)").required();
        t.scalar("meanHeight", "y of the fracture's mean plane", "m").required();
        t.scalar("aperture", "smallest vertical gap between the faces", "m")
            .required().atLeast(0);
        t.word("material", "material of the two blocks").required();
        t.subDict("lower", "profile of the lower block's face").required();
        t.subDict("upper", "profile of the upper block's face").required();
        t.subDict("columns", "optional confining columns: width, material");
        t.fileName("output", "name of the file under constant/geometry")
            .defaultValue("fracture");
        return t;
    }();
    return table;
}

const nmm::keywordTable& profileKeywords()
{
    static const nmm::keywordTable table = []
    {
        nmm::keywordTable t("lower/upper", "a face's profile z(x) about the mean plane");
        t.word("type", "where the profile comes from")
            .required().choices({"points", "asperities", "selfAffine", "mated"});
        t.list("points", "points: measured (x z) pairs, x increasing [m]");
        t.list("asperities", "asperities: (x height width) of each bump [m]");
        t.word("shape", "asperities: shape of a bump")
            .choices({"cosine", "triangle"}).defaultValue("cosine");
        t.integer("nPoints", "asperities, selfAffine: points along the face")
            .atLeast(3);
        t.scalar("hurst", "selfAffine: Hurst exponent H", "").range(0, 1);
        t.scalar("rmsHeight", "selfAffine: RMS of z", "m").atLeast(0);
        t.integer("seed", "selfAffine: seed of the random phases");
        t.scalar("shift", "mated (upper only): move of the lower face along x", "m");
        return t;
    }();
    return table;
}

const nmm::keywordTable& columnKeywords()
{
    static const nmm::keywordTable table = []
    {
        nmm::keywordTable t("columns", "confining columns on both sides");
        t.scalar("width", "width of each column", "m").required().above(0);
        t.word("material", "the columns' material").required();
        return t;
    }();
    return table;
}


//- A keyword that the profile's type needs
template<class T>
T need(const nmm::dictionary& d, const std::string& key, const std::string& type)
{
    if (!d.found(key))
    {
        throw nmm::IOerror("a '" + type + "' profile needs '" + key + "'",
            d.where(), key);
    }
    return profileKeywords().get<T>(d, key);
}


//- z at x of a profile, held constant beyond its ends
double zAt(const profile& p, double x)
{
    if (x <= p.front().x()) return p.front().y();
    if (x >= p.back().x()) return p.back().y();
    const auto hi = std::upper_bound(p.begin(), p.end(), x,
        [](double v, const Eigen::Vector2d& q) { return v < q.x(); });
    const auto lo = hi - 1;
    const double s = (x - lo->x())/(hi->x() - lo->x());
    return (1 - s)*lo->y() + s*hi->y();
}


//- The points of p inside [x0, x1], with the ends interpolated
profile cut(const profile& p, double x0, double x1)
{
    profile out{{x0, zAt(p, x0)}};
    for (const auto& q : p)
    {
        if (q.x() > x0 && q.x() < x1) out.push_back(q);
    }
    out.emplace_back(x1, zAt(p, x1));
    return out;
}


profile measured(const nmm::dictionary& d, double x0, double x1)
{
    const auto& e = d.lookupEntry("points");
    const xyList xz = need<xyList>(d, "points", "points");
    if (xz.size() < 2)
    {
        throw e.error("a measured profile needs at least two points, found "
            + std::to_string(xz.size()));
    }
    profile p;
    for (std::size_t i = 0; i < xz.size(); ++i)
    {
        if (i > 0 && !(xz[i][0] > xz[i - 1][0]))
        {
            throw e.error("x must increase: point " + std::to_string(i)
                + " is not right of point " + std::to_string(i - 1));
        }
        p.emplace_back(xz[i][0], xz[i][1]);
    }
    if (p.front().x() > x0 || p.back().x() < x1)
    {
        std::ostringstream os;
        os << "the points span x = " << p.front().x() << " to " << p.back().x()
            << ", less than the box's " << x0 << " to " << x1;
        throw e.error(os.str());
    }
    return cut(p, x0, x1);
}


profile asperities(const nmm::dictionary& d, double x0, double x1)
{
    const auto bumps = need<std::vector<std::array<double, 3>>>(d, "asperities", "asperities");
    const int n = need<int>(d, "nPoints", "asperities");
    const bool cosine = profileKeywords().get<std::string>(d, "shape") == "cosine";
    for (const auto& b : bumps)
    {
        if (!(b[2] > 0))
        {
            throw d.lookupEntry("asperities").error("an asperity's width must be positive");
        }
    }
    profile p;
    for (int i = 0; i < n; ++i)
    {
        const double x = x0 + (x1 - x0)*i/(n - 1);
        double z = 0;
        for (const auto& [xc, h, w] : bumps)
        {
            const double s = std::abs(x - xc)/(0.5*w);
            if (s < 1) z += cosine ? 0.5*h*(1 + std::cos(pi*s)) : h*(1 - s);
        }
        p.emplace_back(x, z);
    }
    return p;
}


//- A uniform number in [0, 1) that is the same on every machine
double uniform(std::mt19937_64& rng)
{
    return double(rng() >> 11)*0x1.0p-53;
}


profile selfAffine(const nmm::dictionary& d, double x0, double x1)
{
    const int n = need<int>(d, "nPoints", "selfAffine");
    const double H = need<double>(d, "hurst", "selfAffine");
    const double rms = need<double>(d, "rmsHeight", "selfAffine");
    std::mt19937_64 rng(std::uint64_t(need<int>(d, "seed", "selfAffine")));

    std::vector<double> phase;
    for (int k = 1; 2*k < n; ++k) phase.push_back(2*pi*uniform(rng));

    profile p;
    for (int i = 0; i < n; ++i)
    {
        double z = 0;
        for (std::size_t k = 1; k <= phase.size(); ++k)
        {
            z += std::pow(double(k), -(H + 0.5))
                *std::cos(2*pi*double(k)*i/(n - 1) + phase[k - 1]);
        }
        p.emplace_back(x0 + (x1 - x0)*i/(n - 1), z);
    }
    double mean = 0, square = 0;
    for (const auto& q : p) mean += q.y()/n;
    for (const auto& q : p) square += (q.y() - mean)*(q.y() - mean)/n;
    const double scale = square > 0 ? rms/std::sqrt(square) : 0;
    for (auto& q : p) q.y() = (q.y() - mean)*scale;
    return p;
}


profile mated(const nmm::dictionary& d, const profile& lower, double x0, double x1)
{
    const double shift = need<double>(d, "shift", "mated");
    profile moved;
    for (const auto& q : lower) moved.emplace_back(q.x() + shift, q.y());
    return cut(moved, x0, x1);
}


profile readProfile
(
    const nmm::dictionary& d,
    double x0,
    double x1,
    const profile* lower
)
{
    profileKeywords().validate(d);
    const std::string type = profileKeywords().get<std::string>(d, "type");
    if (type == "points") return measured(d, x0, x1);
    if (type == "asperities") return asperities(d, x0, x1);
    if (type == "selfAffine") return selfAffine(d, x0, x1);
    if (!lower)
    {
        throw nmm::IOerror("'mated' copies the lower face: only the upper "
            "face can be mated", d.lookupEntry("type").where(), "type");
    }
    return mated(d, *lower, x0, x1);
}


//- The x of every vertex of both faces: piecewise linear gaps have
//  their extremes there
std::vector<double> knots(const profile& a, const profile& b)
{
    std::vector<double> x;
    for (const auto& q : a) x.push_back(q.x());
    for (const auto& q : b) x.push_back(q.x());
    std::sort(x.begin(), x.end());
    x.erase(std::unique(x.begin(), x.end()), x.end());
    return x;
}


struct apertureSummary { double xFirstContact, mean, max; };

apertureSummary summarise(const profile& lower, const profile& upper)
{
    const std::vector<double> x = knots(lower, upper);
    apertureSummary s{x.front(), 0, 0};
    double smallest = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < x.size(); ++i)
    {
        const double g = zAt(upper, x[i]) - zAt(lower, x[i]);
        if (g < smallest) { smallest = g; s.xFirstContact = x[i]; }
        s.max = std::max(s.max, g);
        if (i > 0)
        {
            const double g0 = zAt(upper, x[i - 1]) - zAt(lower, x[i - 1]);
            s.mean += 0.5*(g0 + g)*(x[i] - x[i - 1]);
        }
    }
    s.mean /= x.back() - x.front();
    return s;
}


//- Lift the upper face so that the smallest gap is the aperture
void lift(profile& upper, const profile& lower, double aperture)
{
    double overlap = -std::numeric_limits<double>::max();
    for (double x : knots(lower, upper))
    {
        overlap = std::max(overlap, zAt(lower, x) - zAt(upper, x));
    }
    for (auto& q : upper) q.y() += overlap + aperture;
}


void checkInside(const profile& face, const nmm::boxExtent& b, const nmm::dictionary& d, const std::string& who)
{
    for (const auto& q : face)
    {
        if (!(q.y() > b.y0 && q.y() < b.y1))
        {
            std::ostringstream os;
            os << "the " << who << " face reaches y = " << q.y() << " at x = " << q.x()
                << ", outside the box's " << b.y0 << " to " << b.y1
                << ": lower the roughness or the aperture, or move meanHeight";
            throw nmm::IOerror(os.str(), d.subDict(who).where(), who);
        }
    }
}


nmm::blockList makeBlocks
(
    const profile& lower,
    const profile& upper,
    const nmm::boxExtent& b,
    const std::string& material
)
{
    nmm::pointLoop lowerLoop{{b.x0, b.y0}, {b.x1, b.y0}};
    for (auto it = lower.rbegin(); it != lower.rend(); ++it) lowerLoop.push_back(*it);

    nmm::pointLoop upperLoop(upper.begin(), upper.end());
    upperLoop.emplace_back(b.x1, b.y1);
    upperLoop.emplace_back(b.x0, b.y1);

    nmm::blockList blocks;
    blocks.add({"lower", material, lowerLoop, {}});
    blocks.add({"upper", material, upperLoop, {}});
    return blocks;
}


void addColumns
(
    nmm::blockList& blocks,
    const nmm::dictionary& d,
    const profile& lower,
    const profile& upper,
    const nmm::boxExtent& b
)
{
    columnKeywords().validate(d);
    const double w = columnKeywords().get<double>(d, "width");
    const std::string material = columnKeywords().get<std::string>(d, "material");
    blocks.add({"leftColumn", material,
        {{b.x0 - w, b.y0}, {b.x0, b.y0}, lower.front(), upper.front(),
         {b.x0, b.y1}, {b.x0 - w, b.y1}}, {}});
    blocks.add({"rightColumn", material,
        {{b.x1, b.y0}, {b.x1 + w, b.y0}, {b.x1 + w, b.y1}, {b.x1, b.y1},
         upper.back(), lower.back()}, {}});
}


//- The faces as 'edges' patches: the lower block's loop runs along the
//  bottom, then back along its face; the upper block's starts on its face
std::string facePatches(std::size_t nLower, std::size_t nUpper)
{
    std::ostringstream os;
    os << "lowerFace { type edges; edges (";
    for (std::size_t i = 2; i < nLower + 1; ++i) os << " (lower " << i << ")";
    os << " ); }\nupperFace { type edges; edges (";
    for (std::size_t i = 0; i + 1 < nUpper; ++i) os << " (upper " << i << ")";
    os << " ); }\n";
    return os.str();
}


int run(int argc, char* argv[])
{
    nmm::argList args("nmmRoughFracture",
        "Write two blocks split by a rough fracture from system/nmmRoughFractureDict");
    args.addKeywordHelp("system/nmmRoughFractureDict", keywords());
    args.addKeywordHelp("system/nmmRoughFractureDict, 'box'", nmm::boxExtent::keywords());
    args.addKeywordHelp("system/nmmRoughFractureDict, 'lower' and 'upper'", profileKeywords());
    args.addKeywordHelp("system/nmmRoughFractureDict, 'columns'", columnKeywords());
    if (args.parse(argc, argv) == nmm::argList::parseResult::done) return 0;
    args.printBanner(std::cout);

    const fs::path casePath = args.casePath();
    const nmm::dictionary dict = nmm::readUtilityDict(casePath, "nmmRoughFractureDict");
    keywords().validate(dict);
    const nmm::boxExtent b = nmm::boxExtent::read(dict.subDict("box"));
    const double meanHeight = keywords().get<double>(dict, "meanHeight");

    profile lower = readProfile(dict.subDict("lower"), b.x0, b.x1, nullptr);
    profile upper = readProfile(dict.subDict("upper"), b.x0, b.x1, &lower);
    for (auto& q : lower) q.y() += meanHeight;
    for (auto& q : upper) q.y() += meanHeight;
    lift(upper, lower, keywords().get<double>(dict, "aperture"));
    checkInside(lower, b, dict, "lower");
    checkInside(upper, b, dict, "upper");

    nmm::blockList blocks =
        makeBlocks(lower, upper, b, keywords().get<std::string>(dict, "material"));
    if (dict.found("columns"))
    {
        addColumns(blocks, dict.subDict("columns"), lower, upper, b);
    }

    const apertureSummary s = summarise(lower, upper);
    std::cout << "Faces: " << lower.size() << " and " << upper.size() << " points\n"
        << "Aperture: smallest " << keywords().get<double>(dict, "aperture")
        << " m at x = " << s.xFirstContact << " m, mean " << s.mean
        << " m, largest " << s.max << " m\n";

    const fs::path output = keywords().getFileName(dict, "output");
    const fs::path file = nmm::writeGeometry(casePath, output, blocks,
        "Written by nmmRoughFracture from system/nmmRoughFractureDict: edit that, not this").file;
    std::ofstream patches(file.string() + "Patches");
    patches << "// Written by nmmRoughFracture: the faces of the fracture\n"
        << facePatches(lower.size(), upper.size());
    if (!patches.flush())
    {
        throw std::runtime_error("cannot write " + file.string() + "Patches");
    }
    std::cout << "Wrote " << blocks.size() << " blocks to " << file.string()
        << ", the faces' patches to " << file.string() << "Patches"
        << " and the preview " << file.string() << ".png\n\nEnd\n";
    return 0;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    return nmm::catchFatalErrors([&] { return run(argc, argv); });
}
