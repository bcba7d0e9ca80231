#include "nmmSolid/coupling/poreFlow/wallSearch/wallSearch.H"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <stdexcept>

namespace nmm
{

namespace
{
// CGAL 5.5's AABB tree is three-dimensional: the segments lie in z = 0
using K3 = CGAL::Simple_cartesian<double>;
using segment3 = K3::Segment_3;
using iterator = std::vector<segment3>::const_iterator;
using primitive = CGAL::AABB_segment_primitive<K3, iterator>;
using aabbTree = CGAL::AABB_tree<CGAL::AABB_traits<K3, primitive>>;
}


struct wallSearch::tree
{
    std::vector<segment3> segments;
    aabbTree aabb;
};


wallSearch::wallSearch(std::vector<segment> segments)
:
    segments_(std::move(segments)),
    tree_(std::make_unique<tree>())
{
    if (segments_.empty()) throw std::invalid_argument("wallSearch: no segments");
    tree_->segments.reserve(segments_.size());
    for (const auto& s : segments_)
    {
        tree_->segments.emplace_back(K3::Point_3(s.a.x(), s.a.y(), 0), K3::Point_3(s.b.x(), s.b.y(), 0));
    }
    tree_->aabb.insert(tree_->segments.cbegin(), tree_->segments.cend());
    tree_->aabb.build();
    tree_->aabb.accelerate_distance_queries();
}


wallSearch::~wallSearch() = default;
wallSearch::wallSearch(wallSearch&&) noexcept = default;


wallSearch::nearest wallSearch::closest(const Eigen::Vector2d& x) const
{
    const K3::Point_3 q(x.x(), x.y(), 0);
    const auto hit = tree_->aabb.closest_point_and_primitive(q);
    const std::size_t i = std::size_t(hit.second - tree_->segments.cbegin());
    const Eigen::Vector2d p(hit.first.x(), hit.first.y());
    return {(p - x).norm(), segments_[i].label, p};
}

} // End namespace nmm
