#include "nmmSolid/cover/mathematicalCover/mathematicalCover/mathematicalCover.H"

#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"
#include "nmmSolid/geometry/geometryCheck/geometryCheck.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace nmm
{

namespace
{

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
    return a.x()*b.y() - a.y()*b.x();
}

} // End anonymous namespace


std::unique_ptr<mathematicalCover> mathematicalCover::New
(
    const dictionary& coverDict,
    const blockGeometry& geometry
)
{
    if (!coverDict.found("type"))
    {
        std::string valid;
        for (const auto& n : types()) valid += " " + n;
        throw IOerror("cover: no 'type' (one of:" + valid + ")",
            coverDict.where(), "type");
    }
    const std::string type = coverDict.get<std::string>("type");
    if (const auto* r = selector::find(type); r && r->keywords)
    {
        r->keywords->validate(coverDict);
    }
    return selector::New(type, coverDict, coverDict, geometry);
}


std::vector<std::string> mathematicalCover::types()
{
    return selector::names();
}


void mathematicalCover::printHelp(std::ostream& os)
{
    for (const auto& [name, record] : selector::table())
    {
        os << "cover type ";
        if (record.keywords) record.keywords->printHelp(os);
        else os << name << "\n";
    }
}


Eigen::AlignedBox2d mathematicalCover::coverBox
(
    const blockGeometry& geometry,
    double margin
)
{
    const Eigen::Vector2d m(margin, margin);
    return Eigen::AlignedBox2d(geometry.bounds().min() - m, geometry.bounds().max() + m);
}


void mathematicalCover::checkSize
(
    double nTriangles,
    const dictionary& coverDict,
    const std::string& key
)
{
    if (nTriangles > maxTriangles)
    {
        const entry* e = coverDict.findEntry(key);
        throw IOerror("cover: about " + std::to_string(std::llround(nTriangles))
            + " triangles, more than the limit of "
            + std::to_string(std::llround(maxTriangles))
            + "; use a larger " + key,
            e ? e->where() : coverDict.where(), key);
    }
}


double mathematicalCover::area(label t) const
{
    const auto& [a, b, c] = triangles_[t];
    return 0.5*cross(nodes_[b] - nodes_[a], nodes_[c] - nodes_[a]);
}


void mathematicalCover::set
(
    std::vector<Eigen::Vector2d> nodes,
    std::vector<triangle> triangles,
    const blockGeometry& geometry,
    const dictionary& coverDict
)
{
    nodes_ = std::move(nodes);
    triangles_ = std::move(triangles);
    box_.setEmpty();
    for (const auto& p : nodes_) box_.extend(p);
    orientCounterClockwise();
    buildStars();
    buildBuckets();

    // The cover is convex, so holding every block vertex means holding
    // every block
    for (const auto& b : geometry.blocks())
    {
        for (const auto& loop : b.loops())
        {
            for (const auto& v : loop)
            {
                if (!locate(v).found)
                {
                    throw IOerror("Block '" + b.name() + "': vertex "
                        + geometryCheck::pointText(v) + " lies outside the "
                        "mathematical cover "
                        + geometryCheck::pointText(box_.min()) + "-"
                        + geometryCheck::pointText(box_.max()),
                        coverDict.where());
                }
            }
        }
    }
}


void mathematicalCover::orientCounterClockwise()
{
    for (label t = 0; t < label(triangles_.size()); ++t)
    {
        if (area(t) < 0) std::swap(triangles_[t][1], triangles_[t][2]);
    }
}


void mathematicalCover::buildStars()
{
    // Counting sort by node: two passes and no per-node vectors, which
    // matters for tens of millions of triangles
    starOffsets_.assign(nodes_.size() + 1, 0);
    for (const auto& tri : triangles_)
    {
        for (label n : tri) ++starOffsets_[n + 1];
    }
    for (std::size_t n = 0; n < nodes_.size(); ++n)
    {
        starOffsets_[n + 1] += starOffsets_[n];
    }
    starTriangles_.resize(starOffsets_.back());
    std::vector<label> fill(starOffsets_.begin(), starOffsets_.end() - 1);
    for (label t = 0; t < label(triangles_.size()); ++t)
    {
        for (label n : triangles_[t]) starTriangles_[fill[n]++] = t;
    }
}


mathematicalCover::label mathematicalCover::clampedIndex(double x, label n) const
{
    const double i = std::floor(x/bucketSize_);
    return label(std::clamp(i, 0.0, double(n - 1)));
}


void mathematicalCover::buildBuckets()
{
    // About two triangles per bucket: locate() tests a handful of triangles
    const Eigen::Vector2d size = box_.sizes();
    const double nBuckets = std::max(1.0, 0.5*double(triangles_.size()));
    bucketSize_ = std::sqrt(std::max(size.x()*size.y(), 1e-300)/nBuckets);
    bucketSize_ = std::max({bucketSize_, size.x()/1e5, size.y()/1e5});
    gridOrigin_ = box_.min();
    nx_ = std::max<label>(1, label(std::ceil(size.x()/bucketSize_)));
    ny_ = std::max<label>(1, label(std::ceil(size.y()/bucketSize_)));

    auto forBuckets = [&](label t, auto&& action)
    {
        Eigen::AlignedBox2d tb;
        for (label n : triangles_[t]) tb.extend(nodes_[n]);
        const Eigen::Vector2d lo = tb.min() - gridOrigin_;
        const Eigen::Vector2d hi = tb.max() - gridOrigin_;
        for (label j = clampedIndex(lo.y(), ny_); j <= clampedIndex(hi.y(), ny_); ++j)
        {
            for (label i = clampedIndex(lo.x(), nx_); i <= clampedIndex(hi.x(), nx_); ++i)
            {
                action(bucketOf(i, j));
            }
        }
    };

    bucketOffsets_.assign(std::size_t(nx_)*ny_ + 1, 0);
    for (label t = 0; t < label(triangles_.size()); ++t)
    {
        forBuckets(t, [&](std::int64_t b) { ++bucketOffsets_[b + 1]; });
    }
    for (std::size_t b = 0; b + 1 < bucketOffsets_.size(); ++b)
    {
        bucketOffsets_[b + 1] += bucketOffsets_[b];
    }
    bucketTriangles_.resize(bucketOffsets_.back());
    std::vector<label> fill(bucketOffsets_.begin(), bucketOffsets_.end() - 1);
    for (label t = 0; t < label(triangles_.size()); ++t)
    {
        forBuckets(t, [&](std::int64_t b) { bucketTriangles_[fill[b]++] = t; });
    }
}


mathematicalCover::location mathematicalCover::locate(const Eigen::Vector2d& p) const
{
    location result;
    // Points a rounding error outside the box still belong to it
    const double tol = 1e-12;
    const Eigen::Vector2d slack = Eigen::Vector2d::Constant(tol*box_.diagonal().norm());
    if (triangles_.empty()
     || !Eigen::AlignedBox2d(box_.min() - slack, box_.max() + slack).contains(p))
    {
        return result;
    }
    const Eigen::Vector2d r = p - gridOrigin_;
    const std::int64_t b = bucketOf(clampedIndex(r.x(), nx_), clampedIndex(r.y(), ny_));

    // The triangle where p is deepest inside: on an edge or at a node, the
    // choice among the triangles sharing it is arbitrary but valid
    double best = -std::numeric_limits<double>::infinity();
    for (label k = bucketOffsets_[b]; k < bucketOffsets_[b + 1]; ++k)
    {
        const label t = bucketTriangles_[k];
        const auto& [ia, ib, ic] = triangles_[t];
        const Eigen::Vector2d& a = nodes_[ia];
        const Eigen::Vector2d& bb = nodes_[ib];
        const Eigen::Vector2d& c = nodes_[ic];
        const double twiceArea = cross(bb - a, c - a);
        Eigen::Vector3d w;
        w[0] = cross(bb - p, c - p)/twiceArea;
        w[1] = cross(c - p, a - p)/twiceArea;
        w[2] = 1.0 - w[0] - w[1];
        if (w.minCoeff() > best)
        {
            best = w.minCoeff();
            result.triangle = t;
            result.weights = w;
        }
    }
    if (best < -tol) return location{};

    // Round-off below zero on an edge: clip, keeping the sum one
    result.found = true;
    result.weights = result.weights.cwiseMax(0.0);
    result.weights /= result.weights.sum();
    return result;
}

} // End namespace nmm
