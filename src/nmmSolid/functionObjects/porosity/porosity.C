#include "nmmSolid/functionObjects/porosity/porosity.H"

#include "nmmSolid/functionObjects/functionObject/patchSegments.H"
#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <limits>

namespace nmm
{

addToRunTimeSelectionTable(functionObject, porosity, "porosity");


namespace
{

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using cgalPolygon = CGAL::Polygon_2<K>;
using cgalPolygonWithHoles = CGAL::Polygon_with_holes_2<K>;

//- Current (deformed) triangle of an element
manifoldElement::triangleNodes currentTriangle
(
    const nmmSolidModel& model,
    const Eigen::Matrix2Xd& D,
    const physicalCover::element& e
)
{
    manifoldElement::triangleNodes T = physicalCover::triangleOf(model.cover(), e);
    for (int k = 0; k < 3; ++k) T.col(k) += D.col(e.patches[k]);
    return T;
}


double twiceArea(const manifoldElement::triangleNodes& T)
{
    const Eigen::Vector2d a = T.col(1) - T.col(0), b = T.col(2) - T.col(0);
    return a.x()*b.y() - a.y()*b.x();
}


//- A barycentric loop in the plane of its (lambda1, lambda2), where the
//  element is the unit right triangle
cgalPolygon baryPolygon(const manifoldElement::baryLoop& loop)
{
    cgalPolygon p;
    for (const auto& lambda : loop) p.push_back(K::Point_2(lambda[1], lambda[2]));
    return p;
}


//- Area of the element's current shape inside the box, exactly. The
//  clipping is done where the element's loops are stored, in its
//  barycentric coordinates: the loops mapped to the current triangle in
//  floating point could cross themselves where a sliver's vertices are
//  nearly collinear (CGAL's Boolean operations need simple polygons),
//  while the box maps to a parallelogram, which cannot
double clippedArea
(
    const manifoldElement::triangleNodes& T,
    const physicalCover::element& e,
    const Eigen::AlignedBox2d& region
)
{
    const double twice = twiceArea(T);
    if (!(std::abs(twice) > 0)) return 0;
    cgalPolygon outer = baryPolygon(e.loops.front());
    if (!outer.is_simple()) return 0;
    if (outer.is_clockwise_oriented()) outer.reverse_orientation();
    cgalPolygonWithHoles shape(outer);
    for (std::size_t l = 1; l < e.loops.size(); ++l)
    {
        cgalPolygon hole = baryPolygon(e.loops[l]);
        if (!hole.is_simple()) return 0;
        if (hole.is_counterclockwise_oriented()) hole.reverse_orientation();
        shape.add_hole(hole);
    }
    cgalPolygon box;
    for (const Eigen::Vector2d& corner :
    {
        region.corner(Eigen::AlignedBox2d::BottomLeft),
        region.corner(Eigen::AlignedBox2d::BottomRight),
        region.corner(Eigen::AlignedBox2d::TopRight),
        region.corner(Eigen::AlignedBox2d::TopLeft)
    })
    {
        const manifoldElement::baryPoint lambda = manifoldElement::toBarycentric(T, corner);
        box.push_back(K::Point_2(lambda[1], lambda[2]));
    }
    if (!box.is_simple()) return 0;
    if (box.is_clockwise_oriented()) box.reverse_orientation();

    std::vector<cgalPolygonWithHoles> pieces;
    CGAL::intersection(shape, box, std::back_inserter(pieces));
    K::FT area = 0;
    for (const auto& piece : pieces)
    {
        area += piece.outer_boundary().area();
        for (auto h = piece.holes_begin(); h != piece.holes_end(); ++h)
        {
            area += h->area();      // clockwise: negative
        }
    }
    // The unit right triangle maps to T: areas scale by twice T's area
    return std::abs(twice)*CGAL::to_double(area);
}

} // End anonymous namespace


const keywordTable& porosity::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("porosity", "porosity of a region: 1 - solid area / region area");
        t.include(functionObject::commonKeywords());
        t.list("materials", "materials of the solid (the grains), e.g. (quartz)")
            .required();
        t.vector("min", "lower left corner of the region (x y)", "m").required();
        t.vector("max", "upper right corner of the region (x y)", "m").required();
        t.word("top", "top of the region: the box's, the highest point of"
            " the solid, or the lowest point of topPatch")
            .choices({"box", "grains", "patch"}).defaultValue("box");
        t.word("topPatch", "with top patch: the patch (e.g. a platen's underside)");
        return t;
    }();
    return table;
}


porosity::porosity
(
    const std::string& name,
    const Time& runTime,
    const nmmSolidModel& model,
    const dictionary& dict
)
:
    functionObject(name, runTime, model, dict, "porosity", keywords())
{
    const auto lo = keywords().get<std::array<double, 2>>(dict, "min");
    const auto hi = keywords().get<std::array<double, 2>>(dict, "max");
    box_ = Eigen::AlignedBox2d(Eigen::Vector2d(lo[0], lo[1]), Eigen::Vector2d(hi[0], hi[1]));
    if (!(hi[0] > lo[0] && hi[1] > lo[1]))
    {
        throw dict.lookupEntry("max").error("function object '" + name
            + "': max must lie above and right of min");
    }

    const auto materials = dict.get<std::vector<std::string>>("materials");
    const auto& blocks = model.geometry().blocks();
    for (const auto& b : blocks)
    {
        solidBlock_.push_back(std::find(materials.begin(), materials.end(),
            b.material()) != materials.end());
    }
    for (const auto& m : materials)
    {
        const bool used = std::any_of(blocks.begin(), blocks.end(),
            [&](const block& b) { return b.material() == m; });
        if (!used)
        {
            throw dict.lookupEntry("materials").error("function object '" + name
                + "': no block is of material '" + m + "'");
        }
    }

    const std::string top = keywords().get<std::string>(dict, "top");
    top_ = top == "grains" ? topKind::grains : top == "patch" ? topKind::patch : topKind::box;
    if (top_ == topKind::patch)
    {
        if (!dict.found("topPatch"))
        {
            throw dict.lookupEntry("top").error("function object '" + name
                + "': 'top patch' needs 'topPatch'");
        }
        topSegments_ = patchSegments(name, model, dict, "topPatch");
    }
    writeHeader({"time", "solidArea", "regionArea", "top", "porosity"});
}


double porosity::regionTop() const
{
    if (top_ == topKind::box) return box_.max().y();

    const auto& pc = model_.elements();
    const Eigen::Matrix2Xd D = model_.patchDisplacements();
    if (top_ == topKind::patch)
    {
        double lowest = std::numeric_limits<double>::max();
        for (const std::size_t i : topSegments_)
        {
            const auto& s = pc.segments()[i];
            const auto T = currentTriangle(model_, D, pc.elements()[s.element]);
            lowest = std::min({lowest, manifoldElement::toCartesian(T, s.p).y(),
                manifoldElement::toCartesian(T, s.q).y()});
        }
        return lowest;
    }
    double highest = -std::numeric_limits<double>::max();
    for (const auto& e : pc.elements())
    {
        if (!solidBlock_[std::size_t(e.block)]) continue;
        const auto T = currentTriangle(model_, D, e);
        for (const auto& lambda : e.loops.front())
        {
            highest = std::max(highest, manifoldElement::toCartesian(T, lambda).y());
        }
    }
    return highest;
}


double porosity::solidAreaIn(const Eigen::AlignedBox2d& region) const
{
    const auto& pc = model_.elements();
    const Eigen::Matrix2Xd D = model_.patchDisplacements();
    double area = 0;
    for (const auto& e : pc.elements())
    {
        if (!solidBlock_[std::size_t(e.block)]) continue;
        const auto T = currentTriangle(model_, D, e);
        Eigen::AlignedBox2d bounds;
        for (const auto& lambda : e.loops.front())
        {
            bounds.extend(manifoldElement::toCartesian(T, lambda));
        }
        if (region.contains(bounds))
        {
            const auto T0 = physicalCover::triangleOf(model_.cover(), e);
            const double detF = twiceArea(T)/twiceArea(T0);
            area += detF*e.moments.area;
        }
        else if (region.intersects(bounds))
        {
            area += clippedArea(T, e, region);
        }
    }
    return area;
}


void porosity::execute()
{
    Eigen::AlignedBox2d region = box_;
    region.max().y() = regionTop();
    const double regionArea = std::max(region.volume(), 0.0);
    const double solid = regionArea > 0 ? solidAreaIn(region) : 0;
    writeRow({model_.time(), solid, regionArea, region.max().y(),
        regionArea > 0 ? 1 - solid/regionArea : 0});
}

} // End namespace nmm
