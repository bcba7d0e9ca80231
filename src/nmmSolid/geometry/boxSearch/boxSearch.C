#include "nmmSolid/geometry/boxSearch/boxSearch.H"

#include <CGAL/Bbox_2.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>

namespace nmm
{
namespace boxSearch
{

namespace
{

using cgalBox = CGAL::Box_intersection_d::Box_with_info_d
<
    double, 2, std::size_t, CGAL::Box_intersection_d::ID_EXPLICIT
>;

std::vector<cgalBox> cgalBoxes(const std::vector<box>& boxes)
{
    std::vector<cgalBox> result;
    result.reserve(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i)
    {
        const box& b = boxes[i];
        result.emplace_back
        (
            CGAL::Bbox_2(b.min().x(), b.min().y(), b.max().x(), b.max().y()),
            i
        );
    }
    return result;
}

} // End anonymous namespace


box segmentBox(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
    return box(a.cwiseMin(b), a.cwiseMax(b));
}


std::vector<indexPair> selfPairs(const std::vector<box>& boxes)
{
    std::vector<cgalBox> cb = cgalBoxes(boxes);
    std::vector<indexPair> result;
    CGAL::box_self_intersection_d
    (
        cb.begin(), cb.end(),
        [&result](const cgalBox& a, const cgalBox& b)
        {
            result.emplace_back
            (
                std::min(a.info(), b.info()),
                std::max(a.info(), b.info())
            );
        }
    );
    std::sort(result.begin(), result.end());
    return result;
}


std::vector<indexPair> pairs(const std::vector<box>& a, const std::vector<box>& b)
{
    std::vector<cgalBox> ca = cgalBoxes(a);
    std::vector<cgalBox> cb = cgalBoxes(b);
    std::vector<indexPair> result;
    CGAL::box_intersection_d
    (
        ca.begin(), ca.end(), cb.begin(), cb.end(),
        [&result](const cgalBox& x, const cgalBox& y)
        {
            result.emplace_back(x.info(), y.info());
        }
    );
    std::sort(result.begin(), result.end());
    return result;
}

} // End namespace boxSearch
} // End namespace nmm
