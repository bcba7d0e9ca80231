// Checks of one loop (block polygon or hole) or one joint polyline on its
// own: everything that does not need a second loop.

#include "nmmSolid/geometry/geometryCheck/geometryCheck.H"

#include "nmmSolid/geometry/boxSearch/boxSearch.H"
#include "nmmSolid/geometry/exactPredicates/exactPredicates.H"
#include "nmmSolid/io/dictionary/token.H"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <utility>

namespace nmm
{
namespace geometryCheck
{

namespace
{

//- The two segments of a polyline or loop that meet although they are not
//  neighbours; the lowest pair, so the message does not depend on CGAL's
//  reporting order
std::optional<boxSearch::indexPair> firstSelfIntersection
(
    const std::vector<Eigen::Vector2d>& pts,
    bool closed
)
{
    const std::size_t n = pts.size();
    const std::size_t nSeg = closed ? n : n - 1;
    auto end = [&](std::size_t i) -> const Eigen::Vector2d&
    {
        return pts[(i + 1) % n];
    };

    std::vector<boxSearch::box> boxes;
    boxes.reserve(nSeg);
    for (std::size_t i = 0; i < nSeg; ++i)
    {
        boxes.push_back(boxSearch::segmentBox(pts[i], end(i)));
    }
    for (const auto& [i, j] : boxSearch::selfPairs(boxes))
    {
        // Neighbours share a vertex; beyond it only a spike, checked first
        const bool neighbours = j == i + 1 || (closed && i == 0 && j == nSeg - 1);
        if (!neighbours && exact::segmentsIntersect(pts[i], end(i), pts[j], end(j)))
        {
            return boxSearch::indexPair{i, j};
        }
    }
    return std::nullopt;
}


//- How a message names a path and its parts
struct pathWords
{
    std::string path;           // "polygon", "hole 1", "polyline"
    std::string vertex;         // "vertex" or "point"
    std::string segment;        // "edge" or "segment"

    std::string vertexText(std::size_t i, const Eigen::Vector2d& p) const
    {
        return vertex + " " + std::to_string(i) + " " + pointText(p);
    }
};


//- Consecutive points i and i+1 are the same
void checkRepeated
(
    const std::vector<Eigen::Vector2d>& pts,
    bool closed,
    const pathWords& w,
    const subject& who
)
{
    const std::size_t n = pts.size();
    const std::size_t nSeg = closed ? n : n - 1;
    for (std::size_t i = 0; i < nSeg; ++i)
    {
        const std::size_t next = (i + 1) % n;
        if (pts[i] == pts[next])
        {
            throw who.error(w.path + " " + w.vertexText(i, pts[i])
                + " is repeated as " + w.vertex + " " + std::to_string(next)
                + ": " + w.segment + " " + std::to_string(i) + " has zero length");
        }
    }
}


//- A vertex where the path turns back along itself
void checkSpikes
(
    const std::vector<Eigen::Vector2d>& pts,
    bool closed,
    const pathWords& w,
    const subject& who
)
{
    const std::size_t n = pts.size();
    const std::size_t first = closed ? 0 : 1;
    const std::size_t last = closed ? n : n - 1;
    for (std::size_t i = first; i < last; ++i)
    {
        const std::size_t before = (i + n - 1) % n;
        const Eigen::Vector2d& prev = pts[before];
        const Eigen::Vector2d& next = pts[(i + 1) % n];
        if
        (
            exact::orientation(prev, pts[i], next) == 0
         && !exact::strictlyBetween(prev, pts[i], next)
        )
        {
            throw who.error(w.path + " folds back on itself at "
                + w.vertexText(i, pts[i]) + ": " + w.segment + "s "
                + std::to_string(before) + " and " + std::to_string(i)
                + " run along the same line in opposite directions (a spike)");
        }
    }
}


void checkFinite
(
    const std::vector<Eigen::Vector2d>& pts,
    const pathWords& w,
    const subject& who
)
{
    for (std::size_t i = 0; i < pts.size(); ++i)
    {
        if (!std::isfinite(pts[i].x()) || !std::isfinite(pts[i].y()))
        {
            throw who.error(w.path + " " + w.vertexText(i, pts[i])
                + " has a coordinate that is not a finite number");
        }
    }
}


void checkSelfIntersection
(
    const std::vector<Eigen::Vector2d>& pts,
    bool closed,
    const pathWords& w,
    const subject& who
)
{
    const auto hit = firstSelfIntersection(pts, closed);
    if (!hit) return;
    const auto [i, j] = *hit;
    const std::size_t n = pts.size();
    const Eigen::Vector2d& a0 = pts[i];
    const Eigen::Vector2d& a1 = pts[(i + 1) % n];
    const Eigen::Vector2d& b0 = pts[j];
    const Eigen::Vector2d& b1 = pts[(j + 1) % n];
    const bool cross = exact::segmentsCross(a0, a1, b0, b1);
    throw who.error(w.path + " intersects itself: " + w.segment + " "
        + std::to_string(i) + " " + pointText(a0) + "-" + pointText(a1)
        + " and " + w.segment + " " + std::to_string(j) + " " + pointText(b0)
        + "-" + pointText(b1) + (cross ? " cross" : " touch") + " at "
        + pointText(exact::intersectionPoint(a0, a1, b0, b1)));
}

} // End anonymous namespace


IOerror subject::error(const std::string& message) const
{
    return IOerror(kind + " '" + name + "': " + message, where, name);
}


std::string pointText(const Eigen::Vector2d& p)
{
    return "(" + formatScalar(p.x()) + " " + formatScalar(p.y()) + ")";
}


std::string edgeText(const block& b, std::size_t l, std::size_t i)
{
    auto [p, q] = b.edge(l, i);
    if (b.reversed(l)) std::swap(p, q);
    return block::loopName(l) + " edge " + std::to_string(b.inputEdge(l, i))
        + " " + pointText(p) + "-" + pointText(q);
}


std::string measureText(double v)
{
    std::ostringstream os;
    os << std::setprecision(4) << v;
    return os.str();
}


std::string vertexText(const block& b, std::size_t l, std::size_t i)
{
    const std::size_t k = b.inputVertex(l, i);
    if (k == block::npos)
    {
        // A point snapping added: named by the edge it split
        return block::loopName(l) + " edge " + std::to_string(b.inputEdge(l, i))
            + " point " + pointText(b.vertex(l, i));
    }
    return block::loopName(l) + " vertex " + std::to_string(k)
        + " " + pointText(b.vertex(l, i));
}


void checkLoop(pointLoop& loop, const std::string& loopName, const subject& who)
{
    if (loop.size() > 1 && loop.front() == loop.back())
    {
        loop.pop_back();
    }
    checkLoopShape(loop, loopName, who);
}


void recheckSnapped(const block& b, const std::string& note)
{
    const subject who{"Block", b.name(), b.where()};
    try
    {
        for (std::size_t l = 0; l < b.loops().size(); ++l)
        {
            // As read, so that the vertex numbers are the user's (but for
            // points added to the loop's edges)
            pointLoop asRead = b.loop(l);
            if (b.reversed(l)) std::reverse(asRead.begin() + 1, asRead.end());
            checkLoopShape(asRead, block::loopName(l), who);
            if (exact::loopOrientation(b.loop(l)) != (l == 0 ? 1 : -1))
            {
                throw who.error(block::loopName(l) + " has turned inside out");
            }
        }
        checkHoles(b);
    }
    catch (const IOerror& err)
    {
        throw IOerror(err.message() + note, err.where(), err.keyword());
    }
}


void checkLoopShape(const pointLoop& loop, const std::string& loopName, const subject& who)
{
    const pathWords w{loopName, "vertex", "edge"};
    checkFinite(loop, w, who);
    if (loop.size() < 3)
    {
        throw who.error(loopName + " has " + std::to_string(loop.size())
            + (loop.size() == 1 ? " vertex" : " vertices")
            + "; it needs at least 3");
    }
    checkRepeated(loop, true, w, who);
    if (exact::allCollinear(loop))
    {
        throw who.error(loopName + " has zero area: all its "
            + std::to_string(loop.size()) + " vertices, from "
            + w.vertexText(0, loop[0]) + ", lie on one line");
    }
    checkSpikes(loop, true, w, who);
    checkSelfIntersection(loop, true, w, who);
}


void checkPolyline(const joint& j)
{
    const subject who{"Joint", j.name(), j.where()};
    const pathWords w{"polyline", "point", "segment"};
    const auto& pts = j.points();
    checkFinite(pts, w, who);
    if (pts.size() < 2)
    {
        throw who.error("polyline has " + std::to_string(pts.size())
            + (pts.size() == 1 ? " point" : " points")
            + "; a joint needs at least 2");
    }
    checkRepeated(pts, false, w, who);
    checkSpikes(pts, false, w, who);
    checkSelfIntersection(pts, false, w, who);
}

} // End namespace geometryCheck
} // End namespace nmm
