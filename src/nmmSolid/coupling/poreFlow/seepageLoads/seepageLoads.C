#include "nmmSolid/coupling/poreFlow/seepageLoads/seepageLoads.H"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace nmm
{

namespace
{

//- Distance from x to the face (a straight piece through its midpoint,
//  across its normal)
double distance(const couplingInterface::face& f, const Eigen::Vector2d& x)
{
    const Eigen::Vector2d along(-f.normal.y(), f.normal.x());
    const double s = std::clamp((x - f.midpoint).dot(along), -0.5*f.length, 0.5*f.length);
    return (f.midpoint + s*along - x).norm();
}

} // End anonymous namespace


seepageLoads::seepageLoads(std::vector<couplingInterface::face> edges)
:
    edges_(std::move(edges))
{
    for (std::size_t i = 0; i < edges_.size(); ++i)
    {
        const std::size_t b = edges_[i].block;
        if (b >= byBlock_.size()) byBlock_.resize(b + 1);
        byBlock_[b].push_back(i);
    }
}


std::vector<Eigen::Vector2d> seepageLoads::tractions
(
    const std::vector<poreFlowCase::wallForces::face>& fluid,
    const std::vector<Eigen::Vector2d>& centroids,
    const std::vector<double>& shrink
) const
{
    std::vector<Eigen::Vector2d> force(edges_.size(), Eigen::Vector2d::Zero());
    for (const auto& f : fluid)
    {
        const auto b = std::size_t(f.block);
        if (b >= byBlock_.size() || byBlock_[b].empty())
        {
            throw std::invalid_argument("seepageLoads: a wall face of block "
                + std::to_string(f.block) + ", which has no edges");
        }
        Eigen::Vector2d x = f.midpoint;
        if (b < shrink.size() && shrink[b] > 0)
        {
            x = centroids[b] + (x - centroids[b])/(1 - shrink[b]);
        }
        std::size_t nearest = byBlock_[b].front();
        double best = std::numeric_limits<double>::infinity();
        for (const std::size_t i : byBlock_[b])
        {
            const double d = distance(edges_[i], x);
            if (d < best) { best = d; nearest = i; }
        }
        force[nearest] += f.force;
    }
    for (std::size_t i = 0; i < edges_.size(); ++i)
    {
        if (edges_[i].length > 0) force[i] /= edges_[i].length;
    }
    return force;
}


std::vector<double> seepageLoads::hydrostatic
(
    const std::vector<bool>& immersed,
    double density,
    const Eigen::Vector2d& gravity,
    const Eigen::Vector2d& reference
) const
{
    std::vector<double> p(edges_.size(), 0.0);
    for (std::size_t i = 0; i < edges_.size(); ++i)
    {
        const std::size_t b = edges_[i].block;
        if (b < immersed.size() && immersed[b])
        {
            p[i] = density*gravity.dot(edges_[i].midpoint - reference);
        }
    }
    return p;
}

} // End namespace nmm
