#include "nmmSolid/cover/mathematicalCover/delaunayCover/delaunayCover.H"

#include "nmmSolid/cover/physicalCover/physicalCover.H"
#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace nmm
{

addToRunTimeSelectionTable(mathematicalCover, delaunayCover, "delaunay");


namespace
{

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;
constexpr double pi = 3.14159265358979323846;

//- Raster of cells within a distance of a block boundary edge: answers
//  "is this point near a boundary?" in O(1) during refinement
class boundaryBand
{
    Eigen::Vector2d origin_;
    double h_ = 1;
    long nx_ = 0, ny_ = 0;
    std::vector<bool> marked_;

    static double segmentDistance
    (
        const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b
    )
    {
        const Eigen::Vector2d ab = b - a;
        const double l2 = ab.squaredNorm();
        const double s = l2 > 0 ? std::clamp((p - a).dot(ab)/l2, 0.0, 1.0) : 0.0;
        return (p - (a + s*ab)).norm();
    }

public:
    boundaryBand
    (
        const blockGeometry& geometry,
        const Eigen::AlignedBox2d& box,
        double fineSize,
        double distance,
        bool nearBlocks,
        bool nearJoints
    )
    :
        origin_(box.min()), h_(0.5*fineSize),
        nx_(long(std::ceil(box.sizes().x()/h_)) + 1),
        ny_(long(std::ceil(box.sizes().y()/h_)) + 1),
        marked_(std::size_t(nx_*ny_), false)
    {
        for (const auto& b : geometry.blocks())
        {
            for (const auto& [l, i] : b.edgeList())
            {
                const auto [p, q] = b.edge(l, i);
                if (nearBlocks) mark(p, q, distance);
            }
        }
        // Cracks too: their tips are where the stresses are singular
        for (const auto& jt : geometry.joints())
        {
            if (!nearJoints) break;
            for (std::size_t i = 0; i < jt.nSegments(); ++i)
            {
                const auto [p, q] = jt.segment(i);
                mark(p, q, distance);
            }
        }
    }

    //- Mark the cells any of which may be within distance of p-q
    void mark(const Eigen::Vector2d& p, const Eigen::Vector2d& q, double distance)
    {
        const double reach = distance + 0.7072*h_;
        const Eigen::Vector2d lo = p.cwiseMin(q).array() - reach;
        const Eigen::Vector2d hi = p.cwiseMax(q).array() + reach;
        for (long j = index(lo.y() - origin_.y(), ny_); j <= index(hi.y() - origin_.y(), ny_); ++j)
        {
            for (long k = index(lo.x() - origin_.x(), nx_); k <= index(hi.x() - origin_.x(), nx_); ++k)
            {
                const Eigen::Vector2d c = origin_ + h_*Eigen::Vector2d(k + 0.5, j + 0.5);
                if (segmentDistance(c, p, q) <= reach) marked_[j*nx_ + k] = true;
            }
        }
    }

    long index(double x, long n) const
    {
        return long(std::clamp(std::floor(x/h_), 0.0, double(n - 1)));
    }

    bool near(double x, double y) const
    {
        return marked_[index(y - origin_.y(), ny_)*nx_ + index(x - origin_.x(), nx_)];
    }

    bool near(const CDT::Face_handle& fh) const
    {
        double cx = 0, cy = 0;
        for (int v = 0; v < 3; ++v)
        {
            const auto& p = fh->vertex(v)->point();
            if (near(p.x(), p.y())) return true;
            cx += p.x()/3;
            cy += p.y()/3;
        }
        return near(cx, cy);
    }
};


//- CGAL's size-and-angle criterion with a smaller size bound for the
//  triangles near block boundaries
class localSizeCriteria : public CGAL::Delaunay_mesh_size_criteria_2<CDT>
{
    using Base = CGAL::Delaunay_mesh_size_criteria_2<CDT>;
    double fineSize_;
    const boundaryBand* band_;

public:
    localSizeCriteria(double B, double size, double fineSize, const boundaryBand* band)
    :
        CGAL::Delaunay_mesh_criteria_2<CDT>(B),     // virtual base
        Base(B, size),
        fineSize_(fineSize),
        band_(band)
    {}

    class Is_bad : public Base::Is_bad
    {
        typename Base::Is_bad fine_;
        const boundaryBand* band_;

    public:
        Is_bad(double B, double size, double fineSize, const boundaryBand* band,
               const K& traits)
        :
            Base::Is_bad(B, size, traits),
            fine_(B, fineSize, traits),
            band_(band)
        {}

        using Base::Is_bad::operator();

        CGAL::Mesh_2::Face_badness operator()
        (
            const CDT::Face_handle& fh,
            Quality& q
        ) const
        {
            if (band_ && band_->near(fh)) return fine_(fh, q);
            return Base::Is_bad::operator()(fh, q);
        }
    };

    Is_bad is_bad_object() const
    {
        return Is_bad(this->bound(), size_bound(), fineSize_, band_, this->traits);
    }
};

} // End anonymous namespace


const keywordTable& delaunayCover::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("delaunay", "CGAL Delaunay refinement of the blocks' "
            "bounding box: bounded edge length and minimum angle");
        t.word("type", "cover type").required();
        t.include(physicalCover::keywords());
        t.scalar("cellSize", "largest triangle edge length", "m")
            .required().above(0);
        t.scalar("margin", "cover extends this far beyond the blocks; "
            "default one cellSize", "m").atLeast(0);
        t.scalar("minAngle", "smallest triangle angle; at most 20.7 for "
            "refinement to end", "deg").range(1, 20.7).defaultValue(20.7);
        t.subDict("refineNearBoundaries", "smaller triangles near block "
            "boundaries: { cellSize <m>; distance <m>; }");
        return t;
    }();
    return table;
}


namespace
{

const keywordTable& refineKeywords()
{
    static const keywordTable table = []
    {
        keywordTable t("refineNearBoundaries", "smaller triangles within a "
            "distance of the block boundaries");
        t.scalar("cellSize", "largest edge length near boundaries", "m")
            .required().above(0);
        t.scalar("distance", "width of the refined band", "m")
            .required().atLeast(0);
        t.word("near", "which boundaries: block edges and joints, or only "
            "one of them").choices({"all", "blocks", "joints"}).defaultValue("all");
        return t;
    }();
    return table;
}

} // End anonymous namespace


delaunayCover::delaunayCover
(
    const dictionary& coverDict,
    const blockGeometry& geometry
)
:
    mathematicalCover(keywords().get<double>(coverDict, "cellSize")),
    minAngle_(keywords().get<double>(coverDict, "minAngle"))
{
    const double h = cellSize();
    const double margin = coverDict.found("margin")
        ? keywords().get<double>(coverDict, "margin") : h;
    const Eigen::AlignedBox2d box = coverBox(geometry, margin);

    // Estimated from the area of an equilateral triangle of side h, before
    // any memory is used: CGAL's triangles are a little smaller on average
    const double equilateral = std::sqrt(3.0)/4.0;
    double nEstimate = 2*box.volume()/(equilateral*h*h);

    std::unique_ptr<boundaryBand> band;
    if (const dictionary* refine = coverDict.findDict("refineNearBoundaries"))
    {
        refineKeywords().validate(*refine);
        fineCellSize_ = refineKeywords().get<double>(*refine, "cellSize");
        refineDistance_ = refineKeywords().get<double>(*refine, "distance");
        const double band2 = 2*refineDistance_ + fineCellSize_;
        double perimeter = 0;
        for (const auto& b : geometry.blocks())
        {
            for (const auto& [l, i] : b.edgeList())
            {
                const auto [p, q] = b.edge(l, i);
                perimeter += (q - p).norm();
            }
        }
        nEstimate += 2*std::min(box.volume(), perimeter*band2)
            /(equilateral*fineCellSize_*fineCellSize_);
        checkSize(nEstimate, *refine, "cellSize");
        const std::string near = refineKeywords().get<std::string>(*refine, "near");
        band = std::make_unique<boundaryBand>
        (
            geometry, box, fineCellSize_, refineDistance_,
            near != "joints", near != "blocks"
        );
    }
    checkSize(nEstimate, coverDict, "cellSize");

    CDT cdt;
    const auto corner = [&](double x, double y) { return cdt.insert(K::Point_2(x, y)); };
    const auto v0 = corner(box.min().x(), box.min().y());
    const auto v1 = corner(box.max().x(), box.min().y());
    const auto v2 = corner(box.max().x(), box.max().y());
    const auto v3 = corner(box.min().x(), box.max().y());
    cdt.insert_constraint(v0, v1);
    cdt.insert_constraint(v1, v2);
    cdt.insert_constraint(v2, v3);
    cdt.insert_constraint(v3, v0);

    const double s = std::sin(minAngle_*pi/180.0);
    localSizeCriteria criteria
    (
        s*s, h, fineCellSize_ > 0 ? std::min(fineCellSize_, h) : h, band.get()
    );
    CGAL::Delaunay_mesher_2<CDT, localSizeCriteria> mesher(cdt, criteria);
    mesher.refine_mesh();

    std::vector<Eigen::Vector2d> nodes;
    nodes.reserve(cdt.number_of_vertices());
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    {
        v->info() = int(nodes.size());
        nodes.emplace_back(v->point().x(), v->point().y());
    }
    std::vector<triangle> triangles;
    triangles.reserve(cdt.number_of_faces());
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    {
        triangles.push_back
        ({
            f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()
        });
    }
    set(std::move(nodes), std::move(triangles), geometry, coverDict);
}

} // End namespace nmm
