#include "nmmSolid/coupling/poreFlow/poreMesh/poreMesh.H"

#include "nmmSolid/coupling/poreFlow/wallSearch/wallSearch.H"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Constrained_voronoi_diagram_2.h>
#include <CGAL/Mesh_2/Lloyd_move_2.h>
#include <CGAL/Mesh_2/Mesh_sizing_field.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_2/Face_badness.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>

namespace nmm
{

namespace
{

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using point = K::Point_2;

// The triangulation that is refined into the mesh
using meshFace = CGAL::Delaunay_mesh_face_base_2<K>;
using meshTds = CGAL::Triangulation_data_structure_2<CGAL::Delaunay_mesh_vertex_base_2<K>, meshFace>;
using meshCdt = CGAL::Constrained_Delaunay_triangulation_2<K, meshTds, CGAL::Exact_predicates_tag>;

// The triangulation of the boundary alone, each face with its width
struct widthInfo
{
    bool inDomain = false;
    double width = std::numeric_limits<double>::infinity();
    //- The narrowest of the face's gaps that has a sample block on one
    //  side (a throat), and its ends
    double throat = std::numeric_limits<double>::infinity();
    Eigen::Vector2d from = Eigen::Vector2d::Zero(), to = Eigen::Vector2d::Zero();
};
using sizeFace = CGAL::Triangulation_face_base_with_info_2<widthInfo, K,
    CGAL::Constrained_triangulation_face_base_2<K>>;
using sizeTds = CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<K>, sizeFace>;
using sizeCdt = CGAL::Constrained_Delaunay_triangulation_2<K, sizeTds, CGAL::Exact_predicates_tag>;

Eigen::Vector2d vec(const point& p) { return {p.x(), p.y()}; }


//- The kept triangles, numbered in the triangulation's own order: the
//  addresses of its handles vary from run to run, and the cells' order
//  (and which of two coincident points is kept) must not follow them
class keptFaces
{
    std::set<meshCdt::Face_handle> kept_;

public:
    std::vector<meshCdt::Face_handle> faces;

    void add(meshCdt::Face_handle f)
    {
        kept_.insert(f);
        faces.push_back(f);
    }
    bool count(meshCdt::Face_handle f) const { return kept_.count(f) > 0; }
    std::size_t size() const { return faces.size(); }
};


//- Refinement criteria of Delaunay_mesher_2 (the MeshingCriteria_2
//  concept) with a cell size that varies in space: the shape bound of
//  Delaunay_mesh_criteria_2 and a longest edge of at most size(centroid)
class sizeFieldCriteria
{
public:
    using Face_handle = meshCdt::Face_handle;
    using sizeFunction = std::function<double(const Eigen::Vector2d&)>;

    //- (squared sine of the smallest angle, squared longest edge over the
    //  squared size): as Delaunay_mesh_size_criteria_2's
    struct Quality : std::pair<double, double>
    {
        Quality() = default;
        Quality(double sine, double size) : std::pair<double, double>(sine, size) {}
        double sine() const { return first; }
        double size() const { return second; }
        // Too large first (the largest first), then the worst shaped
        bool operator<(const Quality& q) const
        {
            if (size() > 1) return q.size() > 1 ? size() > q.size() : true;
            if (q.size() > 1) return false;
            return sine() < q.sine();
        }
    };

    class Is_bad
    {
        double bound_;
        const sizeFunction* size_;

    public:
        Is_bad(double bound, const sizeFunction* size) : bound_(bound), size_(size) {}

        CGAL::Mesh_2::Face_badness operator()(const Quality& q) const
        {
            if (q.size() > 1) return CGAL::Mesh_2::IMPERATIVELY_BAD;
            return q.sine() < bound_ ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
        }

        CGAL::Mesh_2::Face_badness operator()(const Face_handle& f, Quality& q) const
        {
            const Eigen::Vector2d a = vec(f->vertex(0)->point());
            const Eigen::Vector2d b = vec(f->vertex(1)->point());
            const Eigen::Vector2d c = vec(f->vertex(2)->point());
            const double la = (b - c).squaredNorm(), lb = (c - a).squaredNorm(), lc = (a - b).squaredNorm();
            const double longest = std::max({la, lb, lc});
            const double cross = std::abs((b - a).x()*(c - a).y() - (b - a).y()*(c - a).x());
            // sin^2 of the smallest angle, opposite the shortest edge
            const double shortest = std::min({la, lb, lc});
            const double others = la*lb*lc/shortest;
            const double sine = others > 0 ? cross*cross/others : 0;
            const double h = (*size_)((a + b + c)/3);
            q = Quality(sine, longest/(h*h));
            return operator()(q);
        }
    };

    sizeFieldCriteria(double bound, sizeFunction size) : bound_(bound), size_(std::move(size)) {}

    Is_bad is_bad_object() const { return Is_bad(bound_, &size_); }

private:
    double bound_;
    sizeFunction size_;
};


//- The loop without the vertices that lie within tol of the line through
//  their neighbours (the points where a block's edge crosses a cover line,
//  rounded off it) and without edges shorter than tol: the refinement
//  would otherwise resolve those kinks with cells of their size
poreDomain::loop simplified(poreDomain::loop l, double tol)
{
    bool removed = true;
    while (removed && l.points.size() > 3)
    {
        removed = false;
        for (std::size_t i = 0; i < l.points.size() && l.points.size() > 3; ++i)
        {
            const std::size_t n = l.points.size(), prev = (i + n - 1)%n, next = (i + 1)%n;
            const Eigen::Vector2d& a = l.points[prev];
            const Eigen::Vector2d& x = l.points[i];
            const Eigen::Vector2d& b = l.points[next];
            const Eigen::Vector2d ab = b - a;
            const double lab = ab.norm();
            const double off = lab > 0 ? std::abs(ab.x()*(x - a).y() - ab.y()*(x - a).x())/lab : (x - a).norm();
            const bool between = (x - a).dot(ab) > 0 && (b - x).dot(ab) > 0;
            if (!((off < tol && between) || (x - a).norm() < tol)) continue;
            // The merged edge keeps the label of the longer of the two
            const int label = (x - a).norm() > (b - x).norm() ? l.labels[prev] : l.labels[i];
            l.labels[prev] = label;
            l.points.erase(l.points.begin() + long(i));
            l.labels.erase(l.labels.begin() + long(i));
            removed = true;
        }
    }
    return l;
}


template<class Cdt>
void insertLoops(Cdt& cdt, const poreDomain& domain)
{
    for (const auto& l : domain.loops)
    {
        std::vector<typename Cdt::Vertex_handle> v;
        for (const auto& x : l.points) v.push_back(cdt.insert(point(x.x(), x.y())));
        for (std::size_t i = 0; i < v.size(); ++i)
        {
            const auto& w = v[(i + 1)%v.size()];
            if (v[i] != w) cdt.insert_constraint(v[i], w);
        }
    }
}


//- In the domain: an odd number of constraints crossed from outside;
//  mark(face, inDomain)
template<class Cdt, class Mark>
void markDomain(const Cdt& cdt, Mark mark)
{
    std::set<typename Cdt::Face_handle> seen;
    std::deque<std::pair<typename Cdt::Face_handle, bool>> front{{cdt.infinite_face(), false}};
    while (!front.empty())
    {
        auto [f, in] = front.front();
        front.pop_front();
        if (!seen.insert(f).second) continue;
        mark(f, in);
        for (int i = 0; i < 3; ++i)
        {
            const auto n = f->neighbor(i);
            if (seen.count(n)) continue;
            // Crossing a constraint: one level further in, after this level
            if (cdt.is_constrained({f, i})) front.emplace_back(n, !in);
            else front.emplace_front(n, in);
        }
    }
}


Eigen::Vector2d closestOnSegment(const Eigen::Vector2d& x, const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((x - a).dot(ab)/ab.squaredNorm(), 0.0, 1.0);
    return a + t*ab;
}


//- A wall, not the inlet or outlet (symmetry sides count: they halve a
//  throat)
bool isWall(int label)
{
    return label != poreDomain::inlet && label != poreDomain::outlet;
}


//- The wall labels of the constrained edges at each vertex
template<class Cdt>
std::map<typename Cdt::Vertex_handle, std::set<int>> vertexLabels(const Cdt& cdt, const wallSearch& edges)
{
    std::map<typename Cdt::Vertex_handle, std::set<int>> labels;
    for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    {
        if (!cdt.is_constrained(*e)) continue;
        const auto u = e->first->vertex(cdt.ccw(e->second));
        const auto v = e->first->vertex(cdt.cw(e->second));
        const int l = edges.closest(0.5*(vec(u->point()) + vec(v->point()))).label;
        if (!isWall(l)) continue;
        labels[u].insert(l);
        labels[v].insert(l);
    }
    return labels;
}


bool disjoint(const std::set<int>& a, const std::set<int>& b)
{
    for (int x : a) if (b.count(x)) return false;
    return true;
}


//- Each domain face's width (see the Description)
void setWidths(sizeCdt& cdt, const wallSearch& edges, const std::vector<bool>& holders)
{
    auto sample = [&](int l)
    {
        return l >= 0 && !(std::size_t(l) < holders.size() && holders[std::size_t(l)]);
    };
    auto anySample = [&](const std::set<int>& a, int l)
    {
        if (sample(l)) return true;
        for (int x : a) if (sample(x)) return true;
        return false;
    };
    const auto labels = vertexLabels(cdt, edges);
    auto labelsOf = [&](sizeCdt::Vertex_handle v) -> const std::set<int>&
    {
        static const std::set<int> none;
        const auto it = labels.find(v);
        return it == labels.end() ? none : it->second;
    };
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    {
        if (!f->info().inDomain) continue;
        auto& w = f->info();
        auto consider = [&](const Eigen::Vector2d& p, const Eigen::Vector2d& q, bool throat)
        {
            const double d = (q - p).norm();
            w.width = std::min(w.width, d);
            if (throat && d < w.throat) { w.throat = d; w.from = p; w.to = q; }
        };
        for (int j = 0; j < 3; ++j)
        {
            const auto u = f->vertex(cdt.ccw(j)), v = f->vertex(cdt.cw(j));
            if (labelsOf(u).empty() || labelsOf(v).empty() || !disjoint(labelsOf(u), labelsOf(v))) continue;
            const int lv = *labelsOf(v).begin();
            consider(vec(u->point()), vec(v->point()),
                anySample(labelsOf(u), lv) || anySample(labelsOf(v), lv));
        }
        for (int j = 0; j < 3; ++j)
        {
            if (!cdt.is_constrained({f, j})) continue;
            const Eigen::Vector2d a = vec(f->vertex(cdt.ccw(j))->point());
            const Eigen::Vector2d b = vec(f->vertex(cdt.cw(j))->point());
            const int l = edges.closest(0.5*(a + b)).label;
            if (!isWall(l) || labelsOf(f->vertex(j)).empty() || labelsOf(f->vertex(j)).count(l)) continue;
            const Eigen::Vector2d x = vec(f->vertex(j)->point());
            consider(x, closestOnSegment(x, a, b), anySample(labelsOf(f->vertex(j)), l));
        }
    }
}


wallSearch domainEdges(const poreDomain& domain)
{
    std::vector<wallSearch::segment> segments;
    for (const auto& l : domain.loops)
    {
        for (std::size_t i = 0; i < l.points.size(); ++i)
        {
            segments.push_back({l.points[i], l.points[(i + 1)%l.points.size()], l.labels[i]});
        }
    }
    return wallSearch(std::move(segments));
}


//- Per domain face, its region (joined through unconstrained edges); and
//  per region whether it touches the inlet and the outlet
struct regions
{
    std::map<meshCdt::Face_handle, int> of;
    std::vector<bool> inlet, outlet;
    std::vector<double> area;
};


regions findRegions(const meshCdt& cdt, const wallSearch& edges)
{
    regions r;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    {
        if (!f->is_in_domain() || r.of.count(f)) continue;
        const int id = int(r.inlet.size());
        r.inlet.push_back(false);
        r.outlet.push_back(false);
        r.area.push_back(0);
        std::vector<meshCdt::Face_handle> stack{f};
        r.of[f] = id;
        while (!stack.empty())
        {
            const auto g = stack.back();
            stack.pop_back();
            r.area[id] += cdt.triangle(g).area();
            for (int i = 0; i < 3; ++i)
            {
                if (cdt.is_constrained({g, i}))
                {
                    const auto a = vec(g->vertex(cdt.ccw(i))->point());
                    const auto b = vec(g->vertex(cdt.cw(i))->point());
                    const int l = edges.closest(0.5*(a + b)).label;
                    if (l == poreDomain::inlet) r.inlet[id] = true;
                    if (l == poreDomain::outlet) r.outlet[id] = true;
                    continue;
                }
                const auto n = g->neighbor(i);
                if (!cdt.is_infinite(n) && n->is_in_domain() && !r.of.count(n))
                {
                    r.of[n] = id;
                    stack.push_back(n);
                }
            }
        }
    }
    return r;
}


//- The cells the segment from p to q passes through: sampled, each sample
//  in its triangle or (dual cells: the Voronoi cell of the nearest vertex)
//  in the cell of that triangle's nearest corner
int cellsCrossed(const meshCdt& cdt, const Eigen::Vector2d& p, const Eigen::Vector2d& q, bool dual)
{
    constexpr int samples = 2000;
    int n = 0;
    const void* last = nullptr;
    meshCdt::Face_handle hint;
    for (int i = 0; i < samples; ++i)
    {
        const Eigen::Vector2d x = p + (i + 0.5)/samples*(q - p);
        hint = cdt.locate(point(x.x(), x.y()), hint);
        const void* cell = &*hint;
        if (dual)
        {
            int k = 0;
            for (int j = 1; j < 3; ++j)
            {
                if ((vec(hint->vertex(j)->point()) - x).squaredNorm()
                  < (vec(hint->vertex(k)->point()) - x).squaredNorm()) k = j;
            }
            cell = &*hint->vertex(k);
        }
        if (cell != last) { ++n; last = cell; }
    }
    return n;
}

//- The kept triangles as the cells
void triangleCells(const meshCdt& cdt, const keptFaces& cellOf,
    const wallSearch& edges, poreMesh& m)
{
    std::map<meshCdt::Vertex_handle, int> pointOf;
    auto index = [&](meshCdt::Vertex_handle v)
    {
        const auto [it, added] = pointOf.emplace(v, int(m.points.size()));
        if (added) m.points.push_back(vec(v->point()));
        return it->second;
    };
    for (const auto& f : cellOf.faces)
    {
        m.cells.push_back({index(f->vertex(0)), index(f->vertex(1)), index(f->vertex(2))});
    }
    for (std::size_t ci = 0; ci < cellOf.size(); ++ci)
    {
        const auto f = cellOf.faces[ci];
        const int c = int(ci);
        for (int i = 0; i < 3; ++i)
        {
            if (cellOf.count(f->neighbor(i))) continue;
            const int a = pointOf.at(f->vertex(cdt.ccw(i))), b = pointOf.at(f->vertex(cdt.cw(i)));
            const int l = edges.closest(0.5*(m.points[std::size_t(a)] + m.points[std::size_t(b)])).label;
            m.boundary.push_back({a, b, c, l});
        }
    }
}


double signedArea(const poreMesh& m, const std::vector<int>& cell)
{
    double a = 0;
    for (std::size_t i = 0; i < cell.size(); ++i)
    {
        const auto& p = m.points[std::size_t(cell[i])];
        const auto& q = m.points[std::size_t(cell[(i + 1)%cell.size()])];
        a += p.x()*q.y() - q.x()*p.y();
    }
    return a/2;
}


//- The circumcentre of a kept triangle, or its centroid where the
//  circumcentre lies beyond one of its boundary edges (a wall would then
//  cut the dual cell)
Eigen::Vector2d dualPoint(const meshCdt& cdt, meshCdt::Face_handle f,
    const keptFaces& cellOf)
{
    const auto t = cdt.triangle(f);
    const Eigen::Vector2d cc = vec(CGAL::circumcenter(t));
    for (int i = 0; i < 3; ++i)
    {
        if (cellOf.count(f->neighbor(i))) continue;
        const Eigen::Vector2d a = vec(f->vertex(cdt.ccw(i))->point());
        const Eigen::Vector2d b = vec(f->vertex(cdt.cw(i))->point());
        const Eigen::Vector2d ab = b - a, ac = cc - a;
        if (ab.x()*ac.y() - ab.y()*ac.x() <= 1e-12*ab.squaredNorm())
        {
            return vec(CGAL::centroid(t));
        }
    }
    return cc;
}


//- Where the circumcentres of neighbouring triangles coincide (four
//  points on a circle), or a circumcentre lies on its boundary edge (a
//  right angle), the dual would have faces of no area: such points become
//  one
void mergeCoincident
(
    const meshCdt& cdt,
    const keptFaces& cellOf,
    const std::map<meshCdt::Face_handle, int>& centre,
    const std::map<std::pair<meshCdt::Vertex_handle, meshCdt::Vertex_handle>, int>& midpoint,
    poreMesh& d
)
{
    std::vector<int> parent(d.points.size());
    for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = int(i);
    std::function<int(int)> root = [&](int i)
    {
        return parent[std::size_t(i)] == i ? i : parent[std::size_t(i)] = root(parent[std::size_t(i)]);
    };
    for (const auto& f : cellOf.faces)
    {
        const int c = centre.at(f);
        // Faces shorter than this carry nothing but rounding
        const double tol = 1e-3*std::sqrt(cdt.triangle(f).area());
        for (int i = 0; i < 3; ++i)
        {
            const auto n = f->neighbor(i);
            int other = -1;
            if (cellOf.count(n)) other = centre.at(n);
            else
            {
                auto u = f->vertex(cdt.ccw(i)), v = f->vertex(cdt.cw(i));
                if (v < u) std::swap(u, v);
                const auto it = midpoint.find({u, v});
                if (it != midpoint.end()) other = it->second;
            }
            if (other < 0) continue;
            if ((d.points[std::size_t(c)] - d.points[std::size_t(other)]).norm() < tol)
            {
                parent[std::size_t(root(c))] = root(other);
            }
        }
    }
    for (auto& cell : d.cells)
    {
        std::vector<int> merged;
        for (int p : cell)
        {
            const int r = root(p);
            if (merged.empty() || merged.back() != r) merged.push_back(r);
        }
        while (merged.size() > 1 && merged.front() == merged.back()) merged.pop_back();
        cell = std::move(merged);
    }
    // Points merged away are numbered out
    std::vector<int> newIndex(d.points.size(), -1);
    std::vector<Eigen::Vector2d> used;
    auto renumber = [&](int p)
    {
        int& i = newIndex[std::size_t(root(p))];
        if (i < 0) { i = int(used.size()); used.push_back(d.points[std::size_t(root(p))]); }
        return i;
    };
    for (auto& cell : d.cells) for (int& p : cell) p = renumber(p);
    for (auto& b : d.boundary) { b.a = renumber(b.a); b.b = renumber(b.b); }
    d.points = std::move(used);
}


//- The dual of the kept triangles (see makeDual)
class dualBuilder
{
    using vertex = meshCdt::Vertex_handle;
    using faceHandle = meshCdt::Face_handle;

    const meshCdt& cdt_;
    const keptFaces& cellOf_;
    const wallSearch& edges_;
    std::map<faceHandle, int> centre_;
    std::map<std::pair<vertex, vertex>, int> midpoint_;
    std::map<vertex, int> corner_;

    int add(const Eigen::Vector2d& x)
    {
        d.points.push_back(x);
        return int(d.points.size()) - 1;
    }

    int mid(vertex u, vertex v)
    {
        const auto key = u < v ? std::make_pair(u, v) : std::make_pair(v, u);
        const auto it = midpoint_.find(key);
        if (it != midpoint_.end()) return it->second;
        return midpoint_[key] = add(0.5*(vec(u->point()) + vec(v->point())));
    }

    int label(vertex u, vertex v) const
    {
        return edges_.closest(0.5*(vec(u->point()) + vec(v->point()))).label;
    }

    bool kept(faceHandle f) const { return cellOf_.count(f) > 0; }

    //- The cell of the fan of kept triangles around v from around[i0] on:
    //  v, the midpoint of the boundary edge before the fan, the fan's
    //  circumcentres, the midpoint of the boundary edge after it
    void fanCell(vertex v, const std::vector<faceHandle>& around, std::size_t i0)
    {
        const std::size_t n = around.size();
        const auto f0 = around[i0];
        const auto w0 = f0->vertex(cdt_.ccw(f0->index(v)));
        const int vi = corner_.count(v) ? corner_[v] : (corner_[v] = add(vec(v->point())));
        std::vector<int> cell{vi, mid(v, w0)};
        std::size_t i = i0;
        for (; kept(around[i%n]); ++i) cell.push_back(centre_.at(around[i%n]));
        const auto fk = around[(i + n - 1)%n];
        const auto wk = fk->vertex(cdt_.cw(fk->index(v)));
        cell.push_back(mid(v, wk));
        const int c = int(d.cells.size());
        d.boundary.push_back({vi, cell[1], c, label(v, w0)});
        d.boundary.push_back({cell.back(), vi, c, label(wk, v)});
        d.cells.push_back(std::move(cell));
    }

    //- The cell or cells of vertex v: inside, the circumcentres around it;
    //  on the boundary, one cell per fan of kept triangles
    void cellsOf(vertex v)
    {
        std::vector<faceHandle> around;
        auto c = cdt_.incident_faces(v), end = c;
        do { around.push_back(c); } while (++c != end);
        const std::size_t n = around.size();
        bool inside = true;
        for (std::size_t i = 0; i < n; ++i)
        {
            if (kept(around[i]) && !kept(around[(i + n - 1)%n]))
            {
                fanCell(v, around, i);
                inside = false;
            }
        }
        if (!inside) return;
        std::vector<int> cell;
        for (const auto& f : around) cell.push_back(centre_.at(f));
        d.cells.push_back(std::move(cell));
    }

public:
    poreMesh d;

    dualBuilder(const meshCdt& cdt, const keptFaces& cellOf, const wallSearch& edges)
    :
        cdt_(cdt), cellOf_(cellOf), edges_(edges)
    {
        for (const auto& f : cellOf_.faces) centre_[f] = add(dualPoint(cdt_, f, cellOf_));
        std::set<vertex> done;
        for (const auto& f : cellOf_.faces)
        {
            for (int k = 0; k < 3; ++k)
            {
                if (done.insert(f->vertex(k)).second) cellsOf(f->vertex(k));
            }
        }
        mergeCoincident(cdt_, cellOf_, centre_, midpoint_, d);
    }
};


//- The cells as the dual of the triangles (see the Description); false,
//  leaving m as it was, if a dual cell would not be a valid polygon
bool makeDual(const meshCdt& cdt, const keptFaces& cellOf,
    const wallSearch& edges, poreMesh& m)
{
    dualBuilder b(cdt, cellOf, edges);
    poreMesh& d = b.d;
    for (const auto& cell : d.cells)
    {
        if (cell.size() < 3 || !(signedArea(d, cell) > 0)) return false;
    }
    d.area = m.area;
    d.throat = m.throat;
    d.droppedArea = m.droppedArea;
    d.droppedRegions = m.droppedRegions;
    m = std::move(d);
    return true;
}


double smallestSqCircumradius(const meshCdt& cdt, meshCdt::Vertex_handle v)
{
    double r = std::numeric_limits<double>::infinity();
    auto f = cdt.incident_faces(v), end = f;
    do
    {
        if (cdt.is_infinite(f)) continue;
        r = std::min(r, CGAL::squared_radius(f->vertex(0)->point(), f->vertex(1)->point(),
            f->vertex(2)->point()));
    } while (++f != end);
    return r;
}


//- The mean square root of the largest hundredth of the moves (squared,
//  over the local size squared) of the n vertices free to move
double largestMoves(std::vector<double> ratios, std::size_t n)
{
    const std::size_t k = std::max<std::size_t>(1, n/100);
    ratios.resize(std::max(ratios.size(), k), 0.0);
    std::partial_sort(ratios.begin(), ratios.begin() + std::ptrdiff_t(k), ratios.end(), std::greater<>());
    double sum = 0;
    for (std::size_t i = 0; i < k; ++i) sum += std::sqrt(ratios[i]);
    return sum/double(k);
}


//- Lloyd steps as CGAL's lloyd_optimize_mesh_2 takes them (its move to
//  the centroid of the constrained Voronoi cell, weighted by its sizing
//  field; its freeze and convergence bounds), but over the vertices in the
//  triangulation's own order. CGAL 5.5 takes them in the order of their
//  addresses, so one domain gave meshes that differ from run to run
//  (CGAL issue 8719, fixed in 6.1)
void lloydSteps(meshCdt& cdt, int iterations)
{
    // CGAL's defaults: a vertex moves if its move is at least sqrt(freeze)
    // of its smallest circumradius; the steps end when the largest moves
    // average below convergence of it
    constexpr double freeze = 1e-3, convergence = 1e-3;
    using sizingField = CGAL::Mesh_2::Mesh_sizing_field<meshCdt>;
    const sizingField sizing(cdt);
    const CGAL::Mesh_2::Lloyd_move_2<meshCdt, sizingField> lloyd;
    for (int i = 0; i < iterations; ++i)
    {
        CGAL::Constrained_voronoi_diagram_2<meshCdt>(cdt).tag_faces_blind();
        std::vector<std::pair<meshCdt::Vertex_handle, point>> moves;
        std::vector<double> ratios;
        std::size_t free = 0;
        for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
        {
            if (cdt.are_there_incident_constraints(v)) continue;
            ++free;
            const auto move = lloyd(v, cdt, sizing);
            const double ratio = move.squared_length()/smallestSqCircumradius(cdt, v);
            if (!(ratio >= freeze) || !std::isfinite(ratio)) continue;
            moves.emplace_back(v, v->point() + move);
            ratios.push_back(ratio);
        }
        if (moves.empty() || largestMoves(std::move(ratios), free) < convergence) return;
        for (const auto& [v, p] : moves)
        {
            const double size = v->sizing_info();
            cdt.remove(v);
            cdt.insert(p)->set_sizing_info(size);
        }
    }
}


//- The domain's triangulation refined to the size field, then (Lloyd
//  steps) smoothed and refined again
void refine(meshCdt& cdt, const poreDomain& domain, const poreMesh::settings& s,
    const sizeFieldCriteria::sizeFunction& size)
{
    insertLoops(cdt, domain);
    auto mark = [](meshCdt::Face_handle f, bool in) { f->set_in_domain(in); };
    markDomain(cdt, mark);
    CGAL::Delaunay_mesher_2<meshCdt, sizeFieldCriteria> mesher(cdt, sizeFieldCriteria(0.125, size));
    mesher.init(true);
    mesher.refine_mesh();
    if (s.lloydIterations == 0) return;
    lloydSteps(cdt, s.lloydIterations);
    // The moved vertices may encroach on boundary edges: refined again,
    // every boundary triangle has its circumcentre inside
    markDomain(cdt, mark);
    CGAL::Delaunay_mesher_2<meshCdt, sizeFieldCriteria> again(cdt, sizeFieldCriteria(0.125, size));
    again.init(true);
    again.refine_mesh();
}


//- Per kept triangle (of a region that joins the inlet to the outlet) its
//  index; the regions dropped are counted in m
keptFaces keptTriangles(const meshCdt& cdt, const wallSearch& edges,
    poreMesh& m)
{
    const regions r = findRegions(cdt, edges);
    std::vector<bool> keep(r.inlet.size());
    for (std::size_t i = 0; i < keep.size(); ++i)
    {
        keep[i] = r.inlet[i] && r.outlet[i];
        if (!keep[i]) { m.droppedArea += r.area[i]; ++m.droppedRegions; }
    }
    if (std::find(keep.begin(), keep.end(), true) == keep.end())
    {
        throw std::runtime_error("no path through the pore space joins the inlet to the outlet "
            "(blocks in contact close it; in 2D a packing of touching grains has no "
            "open path: shrink opens the contacts)");
    }
    keptFaces cellOf;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    {
        const auto id = r.of.find(f);
        if (id == r.of.end() || !keep[std::size_t(id->second)]) continue;
        cellOf.add(f);
        m.area += cdt.triangle(f).area();
    }
    return cellOf;
}


//- The narrowest throat whose middle lies in the kept pore space
poreMesh::throatInfo narrowestThroat(const sizeCdt& sizing, const meshCdt& cdt,
    const keptFaces& cellOf, bool dual)
{
    std::vector<const widthInfo*> widths;
    for (auto f = sizing.finite_faces_begin(); f != sizing.finite_faces_end(); ++f)
    {
        if (f->info().inDomain && std::isfinite(f->info().throat)) widths.push_back(&f->info());
    }
    std::sort(widths.begin(), widths.end(),
        [](const widthInfo* a, const widthInfo* b) { return a->throat < b->throat; });
    for (const widthInfo* w : widths)
    {
        const Eigen::Vector2d mid = 0.5*(w->from + w->to);
        const auto f = cdt.locate(point(mid.x(), mid.y()));
        if (cdt.is_infinite(f) || !cellOf.count(f)) continue;
        return {true, w->throat, w->from, w->to, cellsCrossed(cdt, w->from, w->to, dual)};
    }
    return {};
}

} // End anonymous namespace


poreMesh poreMesh::of(const poreDomain& original, const settings& s)
{
    if (original.loops.empty()) throw std::runtime_error("no pore space in the box: the blocks cover it");
    poreDomain domain = original;
    for (auto& l : domain.loops) l = simplified(std::move(l), 1e-3*s.minCellSize);
    const wallSearch edges = domainEdges(domain);

    sizeCdt sizing;
    insertLoops(sizing, domain);
    markDomain(sizing, [](sizeCdt::Face_handle f, bool in) { f->info().inDomain = in; });
    setWidths(sizing, edges, domain.holders);
    sizeCdt::Face_handle hint;
    const sizeFieldCriteria::sizeFunction size = [&](const Eigen::Vector2d& x)
    {
        hint = sizing.locate(point(x.x(), x.y()), hint);
        const double w = sizing.is_infinite(hint) ? s.maxCellSize : hint->info().width;
        return std::clamp(w/s.cellsAcross, s.minCellSize, s.maxCellSize);
    };

    meshCdt cdt;
    refine(cdt, domain, s, size);
    poreMesh m;
    const auto cellOf = keptTriangles(cdt, edges, m);
    const bool dual = s.cells == cellShape::dual && makeDual(cdt, cellOf, edges, m);
    if (!dual) triangleCells(cdt, cellOf, edges, m);
    m.throat = narrowestThroat(sizing, cdt, cellOf, dual);
    return m;
}

} // End namespace nmm
