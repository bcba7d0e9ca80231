#include "nmmSolid/contact/contactModel/contactModel.H"

#include "nmmSolid/cover/physicalCover/physicalCover.H"
#include "nmmSolid/space/manifoldSpace/manifoldSpace.H"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <unordered_map>

namespace nmm
{

namespace
{

using vec = Eigen::Vector2d;

//- A sliding contact has settled when its friction load changes by less
//  than this fraction between two solves (friction lags the normal force
//  by one solve)
constexpr double frictionTolerance = 1e-2;

//- Fewer contacts than this get their terms and history on one thread:
//  a small model's threads would cost more than they save
constexpr long minThreadedContacts = 512;

//- State changes of one contact within a step that make it chatter
constexpr int maxChangesPerStep = 3;

//- The slope along a solve's increment at its end, relative to that at
//  its start, below which the end is the minimum (rounding). A solve's
//  residual is rounding times the condition of K, a million in granular
//  models, so the end's slope is rounding to about 1e-7 of the start's
constexpr double endSlope = 1e-6;

//- A damped iteration takes the whole increment when the potential falls
//  by at least this fraction of what its slope at the start promises
constexpr double sufficientDecrease = 1e-4;

//- Smallest spring weight: a contact at a sliver's vertex (a tiny
//  tributary length) still resists penetration
constexpr double minWeight = 0.05;


//- The rounding of a gap: a few units of the last place of the largest
//  coordinate of the loops' vertices
double gapRounding(const std::vector<contactLoop>& loops)
{
    double largest = 0;
    for (const contactLoop& loop : loops)
    {
        for (const contactVertex& v : loop.vertices)
        {
            largest = std::max(largest, v.x.cwiseAbs().maxCoeff());
        }
    }
    return 64*std::numeric_limits<double>::epsilon()*std::max(largest, 1.0);
}


//- Median tributary length of the loops' vertices, 1 without vertices
double medianTributaryLength(const std::vector<contactLoop>& loops)
{
    std::vector<double> l;
    for (const contactLoop& loop : loops)
    {
        for (int i = 0; i < int(loop.vertices.size()); ++i)
        {
            l.push_back(loop.tributaryLength(i));
        }
    }
    if (l.empty()) return 1;
    const auto mid = l.begin() + l.size()/2;
    std::nth_element(l.begin(), mid, l.end());
    return *mid > 0 ? *mid : 1;
}

vec tangentOf(const contactLoop& l, int e)
{
    return (l.edgeEnd(e).x - l.edgeStart(e).x).normalized();
}


double distanceToEdge(const vec& x, const contactLoop& l, int e)
{
    const vec& a = l.edgeStart(e).x;
    const vec ab = l.edgeEnd(e).x - a;
    const double t = ab.squaredNorm() > 0
        ? std::clamp((x - a).dot(ab)/ab.squaredNorm(), 0.0, 1.0) : 0.0;
    return (a + t*ab - x).norm();
}


//- Sum of coefficient x dd over the terms
double along(const std::vector<std::pair<int, double>>& t, const Eigen::VectorXd& dd)
{
    double s = 0;
    for (const auto& [dof, c] : t) s += c*dd[dof];
    return s;
}


//- Where each stored entry of A's lower triangle (its index among A's
//  values) is among the values of B, whose pattern holds that triangle:
//  both columns are sorted, so one walk each
std::vector<std::array<int, 2>> lowerSlotsIn
(
    const Eigen::SparseMatrix<double>& A,
    const Eigen::SparseMatrix<double>& B
)
{
    std::vector<std::array<int, 2>> slots;
    slots.reserve(std::size_t(B.nonZeros()));
    const int* bInner = B.innerIndexPtr();
    for (int j = 0; j < A.outerSize(); ++j)
    {
        int b = B.outerIndexPtr()[j];
        for (int a = A.outerIndexPtr()[j]; a < A.outerIndexPtr()[j + 1]; ++a)
        {
            const int i = A.innerIndexPtr()[a];
            if (i < j) continue;
            while (bInner[b] != i) ++b;
            slots.push_back({a, b});
        }
    }
    return slots;
}


// A clique looked up by its dofs (withPattern)
struct dofsHash
{
    std::size_t operator()(const std::vector<int>& dofs) const noexcept
    {
        std::size_t h = dofs.size();
        for (const int d : dofs) h = h*1000003u ^ std::size_t(d);
        return h;
    }
};

} // End anonymous namespace


contactModel::contactModel
(
    const manifoldSpace& space,
    const blockGeometry& geometry,
    contactProperties properties,
    std::vector<std::size_t> materialOfBlock,
    const settings& s,
    double thickness
)
:
    space_(space),
    properties_(std::move(properties)),
    materialOfBlock_(std::move(materialOfBlock)),
    settings_(s),
    thickness_(thickness),
    boundaries_(space.cover(), space.elements(), geometry),
    referenceLength_(medianTributaryLength(boundaries_.loops())),
    gapRounding_(gapRounding(boundaries_.loops())),
    search_(s.searchDistance)
{}


double contactModel::weight(double l) const
{
    return std::max(l/referenceLength_, minWeight);
}


void contactModel::relativeTerms
(
    const contactCandidate& c,
    const Eigen::Vector2d& n,
    const Eigen::Vector2d& s,
    terms& g,
    terms& h
) const
{
    const auto& loops = boundaries_.loops();
    const contactVertex& v = loops[c.vertexLoop].vertices[c.vertex];
    const contactVertex& a = loops[c.edgeLoop].edgeStart(c.edge);
    const manifoldElement::baryPoint edgePoint = (1 - c.t)*a.lambda + c.t*a.edgeEndLambda;

    // u(vertex) - u(edge point), each through its element's weights, along
    // n and s at once (one list, one sort); the terms of a dof both share
    // are summed after sorting
    struct term { int dof; double alongN, alongS; };
    // One list per thread, kept from contact to contact: a pile's step
    // makes these terms for thousands of contacts
    thread_local std::vector<term> all;
    all.clear();
    all.reserve(space_.dofTerms(v.element).size() + space_.dofTerms(a.element).size());
    const auto add = [&](std::int32_t e, const manifoldElement::baryPoint& w, double sign)
    {
        for (const auto& t : space_.dofTerms(e))
        {
            all.push_back
            ({
                t.dof,
                sign*w[t.local/2]*n[t.local%2]*t.coefficient,
                sign*w[t.local/2]*s[t.local%2]*t.coefficient
            });
        }
    };
    add(v.element, v.lambda, 1);
    add(a.element, edgePoint, -1);
    // Stable, so a dof's terms are summed in the list's order; by
    // insertion, as the list is a few dozen terms (stable_sort would
    // allocate a buffer for each contact)
    for (std::size_t k = 1; k < all.size(); ++k)
    {
        const term t = all[k];
        std::size_t j = k;
        for (; j > 0 && all[j - 1].dof > t.dof; --j) all[j] = all[j - 1];
        all[j] = t;
    }
    g.clear();
    h.clear();
    for (const term& t : all)
    {
        if (!g.empty() && g.back().first == t.dof)
        {
            g.back().second += t.alongN;
            h.back().second += t.alongS;
        }
        else
        {
            g.emplace_back(t.dof, t.alongN);
            h.emplace_back(t.dof, t.alongS);
        }
    }
}


const contactLaw& contactModel::lawOf(const contactCandidate& c) const
{
    const auto& loops = boundaries_.loops();
    return properties_.law
    (
        materialOfBlock_[loops[c.vertexLoop].block],
        materialOfBlock_[loops[c.edgeLoop].block]
    );
}


void contactModel::beginStep
(
    const Eigen::Matrix2Xd& patchD,
    const std::vector<contactRecord>& history,
    bool start
)
{
    boundaries_.move(space_.cover(), space_.elements(), patchD, threaded_);
    const auto& loops = boundaries_.loops();
    const std::vector<contactCandidate> found = search_.find(loops, threaded_);
    // The contacts' term lists are kept from step to step, written over:
    // made anew for thousands of contacts, they took a tenth of a pile's
    // contact detection
    active_.resize(found.size());
    statesSteady_ = false;
    // Each contact's terms and springs on its own: on OpenMP's threads
    const long nFound = long(found.size());
    #pragma omp parallel for schedule(dynamic, 64) if (threaded_ && nFound >= minThreadedContacts)
    for (long k = 0; k < nFound; ++k)
    {
        const contactCandidate& c = found[std::size_t(k)];
        active& a = active_[std::size_t(k)];
        terms g = std::move(a.g), h = std::move(a.h);
        a = active{};
        a.g = std::move(g);
        a.h = std::move(h);
        a.record.vertexLoop = c.vertexLoop;
        a.record.vertex = c.vertex;
        a.record.edgeLoop = c.edgeLoop;
        a.record.edge = c.edge;
        a.record.t = c.t;
        a.record.length = c.length;
        a.record.gap = c.gap;
        a.gap0 = c.gap;
        a.kN = settings_.normalPenalty*thickness_*weight(c.length);
        a.kS = settings_.shearPenalty*thickness_*weight(c.length);
        a.law = &lawOf(c);
        const contactLoop& el = loops[c.edgeLoop];
        const vec s = tangentOf(el, c.edge);
        a.n = vec(s.y(), -s.x());
        a.record.normal = a.n;
        a.record.point = loops[c.vertexLoop].vertices[c.vertex].x;
        relativeTerms(c, a.n, s, a.g, a.h);
        const auto p = pressure_.find(a.record.key());
        if (p != pressure_.end()) a.pressureForce = p->second*c.length*thickness_;
    }
    carryHistory(history, start);
}


void contactModel::carryHistory(const std::vector<contactRecord>& history, bool start)
{
    // By (vertex loop, vertex, edge loop): the edges a vertex touched, in
    // the history's order among equals. A sorted list, not a multimap: a
    // node per record was most of the history's time in a pile
    using key = std::tuple<int, int, int>;
    std::vector<std::pair<key, const contactRecord*>> byVertex;
    byVertex.reserve(history.size());
    for (const auto& r : history) byVertex.emplace_back(key{r.vertexLoop, r.vertex, r.edgeLoop}, &r);
    const auto byKey = [](const auto& a, const auto& b) { return a.first < b.first; };
    std::stable_sort(byVertex.begin(), byVertex.end(), byKey);
    const auto& loops = boundaries_.loops();

    // Each contact's history on its own: on OpenMP's threads
    const long nActive = long(active_.size());
    #pragma omp parallel for schedule(dynamic, 64) if (threaded_ && nActive >= minThreadedContacts)
    for (long k = 0; k < nActive; ++k)
    {
        active& a = active_[std::size_t(k)];
        contactRecord& r = a.record;
        const contactRecord* old = nullptr;
        const auto range = std::equal_range(byVertex.begin(), byVertex.end(),
            std::pair<key, const contactRecord*>{{r.vertexLoop, r.vertex, r.edgeLoop}, nullptr}, byKey);
        // The same edge, or else the nearest one along the loop that is
        // still within the search distance of the vertex: a loop cut by
        // the cover has edges shorter than a step's slide
        const contactLoop& el = loops[r.edgeLoop];
        const vec& x = loops[r.vertexLoop].vertices[r.vertex].x;
        const int n = int(el.nEdges());
        int nearest = n;
        for (auto it = range.first; it != range.second; ++it)
        {
            const int e = it->second->edge;
            const int apart = std::min((e - r.edge + n)%n, (r.edge - e + n)%n);
            const bool near =
                distanceToEdge(x, el, e) <= settings_.searchDistance;
            if (apart < nearest && (apart == 0 || near))
            {
                nearest = apart;
                old = it->second;
            }
        }

        if (old)
        {
            r.state = old->state;
            r.bondIntact = old->bondIntact;
            r.bondBroken = old->bondBroken;
            r.shearForce = old->shearForce;
            r.slip = old->slip;
            r.normalForce = old->normalForce;
            r.multiplier = multipliers_ && isClosed(old->state) ? old->multiplier : 0.0;
        }
        else
        {
            const bool touching = std::abs(a.gap0) <= settings_.touchTolerance;
            const bool cemented = start && touching
                && a.law->initialState() == contactState::bonded;
            r.state = touching || a.gap0 < 0 ? contactState::bonded : contactState::open;
            r.bondIntact = cemented && a.law->hasBondStrength();
        }
        hideOverlap(a, old);
        a.shearForce0 = isClosed(r.state) ? r.shearForce : 0;
        a.friction = r.state == contactState::sliding ? r.shearForce : 0;
        capStuckShearForce(a);
    }
}


void contactModel::hideOverlap(active& a, const contactRecord* old) const
{
    // The spring sees the measured gap plus the overlap hidden from it,
    // which is never more than the overlap there is: it vanishes as the
    // bodies move apart
    const double measured = a.gap0;
    double hidden = old ? std::min(old->hiddenOverlap, std::max(-measured, 0.0)) : 0.0;
    // A closed contact starts where it ended: measured against another
    // edge's line (near a corner) its gap can jump deeper, and a spring
    // starting there would push the bodies apart with energy no load put
    // in. An overlap the search found without the contact having been
    // closed enters by at most overlapRelief: resolved at once, its
    // momentum would throw the bodies apart
    const double deepest = old && isClosed(old->state)
        ? std::min(old->gap, 0.0) : -settings_.overlapRelief;
    const double excess = deepest - (measured + hidden);
    if (excess > 0) hidden += excess;
    a.relieved = excess > settings_.touchTolerance;
    a.gap0 = measured + hidden;
    a.record.hiddenOverlap = hidden;
}


void contactModel::capStuckShearForce(active& a) const
{
    // A stuck contact's spring force can start a step outside the friction
    // cone: its normal force changed with the search (another edge, another
    // tributary length, a relieved overlap) while its shear force was
    // carried. Left there, the spring and the friction that would replace
    // it point against the slip in turn, and the open-close iteration
    // swaps the two states for ever. The force is returned to the cone
    // (an intact bond's strength is left to the law, which breaks it)
    const contactRecord& r = a.record;
    if (r.state != contactState::bonded || r.bondIntact) return;
    contactQuery q;
    q.state = r.state;
    q.gap = a.gap0;
    q.Fn = r.multiplier - a.kN*a.gap0;
    q.Fs = a.shearForce0;
    q.length = r.length*thickness_;
    const contactDecision d = a.law->decide(q);
    if (d.state == contactState::sliding) a.shearForce0 = d.frictionForce;
}


contactModel::sparseMatrix contactModel::withPattern(const sparseMatrix& K)
{
    if (!K.isCompressed())
    {
        sparseMatrix compressed = K;
        compressed.makeCompressed();
        return withPattern(compressed);
    }
    // A contact's terms couple all its unknowns (their dofs, sorted and
    // unique): a clique, shared by its normal and shear terms and by
    // the contacts between the same elements. Found by hash, the dofs
    // copied only for a new clique: an ordered map of vectors, one made
    // per term, was a tenth of the pattern's time in a marble's step
    std::unordered_map<std::vector<int>, int, dofsHash> index;
    index.reserve(2*active_.size());
    std::vector<std::vector<int>> cliques;
    std::vector<int> keys, dofs;
    std::vector<std::array<int, 2>> cliqueOf(active_.size());
    const auto cliqueOfTerms = [&](const terms& t)
    {
        dofs.resize(t.size());
        for (std::size_t i = 0; i < t.size(); ++i) dofs[i] = t[i].first;
        const auto found = index.find(dofs);
        if (found != index.end()) return found->second;
        const int c = int(cliques.size());
        index.emplace(dofs, c);
        keys.push_back(int(dofs.size()));
        keys.insert(keys.end(), dofs.begin(), dofs.end());
        cliques.push_back(dofs);
        return c;
    };
    for (std::size_t c = 0; c < active_.size(); ++c)
    {
        cliqueOf[c] = {cliqueOfTerms(active_[c].g), cliqueOfTerms(active_[c].h)};
    }

    const bool same = keys == cliqueKeys_ && K.rows() == stepMatrix_.rows()
        && std::equal(K.outerIndexPtr(), K.outerIndexPtr() + K.outerSize() + 1,
                      kOuter_.begin(), kOuter_.end())
        && std::equal(K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros(),
                      kInner_.begin(), kInner_.end());
    if (same)
    {
        // K + 0 is K, bit for bit
        double* values = stepMatrix_.valuePtr();
        std::fill(values, values + stepMatrix_.nonZeros(), 0.0);
        for (const auto& [k, at] : kSlots_) values[at] = K.valuePtr()[k];
    }
    else
    {
        makeStepPattern(K, cliques);
        cliqueKeys_ = std::move(keys);
    }

    for (std::size_t c = 0; c < active_.size(); ++c)
    {
        active_[c].gClique = cliqueOf[c][0];
        active_[c].hClique = cliqueOf[c][1];
    }
    return stepMatrix_;
}


void contactModel::makeStepPattern
(
    const sparseMatrix& K,
    const std::vector<std::vector<int>>& cliques
)
{
    // Column by column: K's rows and those of every clique holding the
    // column, each once (a marker per row), then sorted. A matrix of
    // zeros summed with K by Eigen went through every clique's m^2
    // entries three times, a quarter of a wall's step. The lower triangle
    // only (the diagonal and below): the linear solvers and the products
    // with it read no more (selfadjointView<Lower>), and with both
    // triangles the copies, the springs and CHOLMOD's permuting
    // transpose went through twice the entries
    const int columns = int(K.cols());
    std::vector<int> start(std::size_t(columns) + 1, 0);
    for (const auto& dofs : cliques)
    {
        for (const int j : dofs) ++start[std::size_t(j) + 1];
    }
    for (int j = 0; j < columns; ++j) start[std::size_t(j) + 1] += start[std::size_t(j)];
    std::vector<const std::vector<int>*> holding(std::size_t(start.back()));
    std::vector<int> next(start.begin(), start.end() - 1);
    for (const auto& dofs : cliques)
    {
        for (const int j : dofs) holding[std::size_t(next[std::size_t(j)]++)] = &dofs;
    }
    std::vector<int> outer(std::size_t(columns) + 1, 0), inner, mark(std::size_t(columns), -1);
    inner.reserve(std::size_t(K.nonZeros()));
    for (int j = 0; j < columns; ++j)
    {
        const std::size_t first = inner.size();
        const auto add = [&](int i)
        {
            if (i < j || mark[std::size_t(i)] == j) return;
            mark[std::size_t(i)] = j;
            inner.push_back(i);
        };
        for (int k = K.outerIndexPtr()[j]; k < K.outerIndexPtr()[j + 1]; ++k) add(K.innerIndexPtr()[k]);
        for (int h = start[std::size_t(j)]; h < start[std::size_t(j) + 1]; ++h)
        {
            for (const int i : *holding[std::size_t(h)]) add(i);
        }
        std::sort(inner.begin() + long(first), inner.end());
        outer[std::size_t(j) + 1] = int(inner.size());
    }
    stepMatrix_ = sparseMatrix(K.rows(), K.cols());
    stepMatrix_.resizeNonZeros(long(inner.size()));
    std::copy(outer.begin(), outer.end(), stepMatrix_.outerIndexPtr());
    std::copy(inner.begin(), inner.end(), stepMatrix_.innerIndexPtr());
    std::fill(stepMatrix_.valuePtr(), stepMatrix_.valuePtr() + inner.size(), 0.0);
    kSlots_ = lowerSlotsIn(K, stepMatrix_);
    for (const auto& [k, at] : kSlots_) stepMatrix_.valuePtr()[at] = K.valuePtr()[k];
    kOuter_.assign(K.outerIndexPtr(), K.outerIndexPtr() + K.outerSize() + 1);
    kInner_.assign(K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros());

    // Each clique's column b, rows a >= b (its dofs are sorted), one
    // after the other: the rows are sorted, so one walk down each column
    cliqueSlots_.assign(cliques.size(), {});
    const int* rows = stepMatrix_.innerIndexPtr();
    for (std::size_t c = 0; c < cliques.size(); ++c)
    {
        const std::vector<int>& dofs = cliques[c];
        std::vector<int>& slots = cliqueSlots_[c];
        slots.resize(dofs.size()*(dofs.size() + 1)/2);
        std::size_t n = 0;
        for (std::size_t b = 0; b < dofs.size(); ++b)
        {
            int at = stepMatrix_.outerIndexPtr()[dofs[b]];
            for (std::size_t a = b; a < dofs.size(); ++a)
            {
                while (rows[at] != dofs[a]) ++at;
                slots[n++] = at;
            }
        }
    }
}


std::vector<double> contactModel::springStiffnesses() const
{
    std::vector<double> k;
    k.reserve(2*active_.size());
    for (const active& a : active_)
    {
        const contactState s = a.record.state;
        k.push_back(isClosed(s) ? a.kN : 0.0);
        k.push_back(s == contactState::bonded ? a.kS : 0.0);
    }
    return k;
}


void contactModel::addSprings(sparseMatrix& K) const
{
    double* values = K.valuePtr();
    // Down each column b of the clique from its diagonal (its slots'
    // order), the entry of row a gets k c_a c_b
    const auto add = [this, values](const terms& t, int clique, double k)
    {
        if (k == 0) return;
        const std::vector<int>& at = cliqueSlots_[std::size_t(clique)];
        std::size_t n = 0;
        for (std::size_t b = 0; b < t.size(); ++b)
        {
            const double cb = t[b].second;
            for (std::size_t a = b; a < t.size(); ++a) values[at[n++]] += k*t[a].second*cb;
        }
    };
    const std::vector<double> k = springStiffnesses();
    for (std::size_t i = 0; i < active_.size(); ++i)
    {
        add(active_[i].g, active_[i].gClique, k[2*i]);
        add(active_[i].h, active_[i].hClique, k[2*i + 1]);
    }
}


Eigen::VectorXd contactModel::forces(long nUnknowns) const
{
    Eigen::VectorXd f = Eigen::VectorXd::Zero(nUnknowns);
    for (const active& a : active_)
    {
        const contactState s = a.record.state;
        double normal = 0, shear = 0;
        if (isClosed(s)) normal = a.record.multiplier - a.kN*a.gap0;
        if (s == contactState::bonded) shear = a.shearForce0;
        if (s == contactState::sliding) shear = a.friction;
        for (const auto& [dof, c] : a.g) f[dof] += normal*c;
        for (const auto& [dof, c] : a.h) f[dof] += shear*c;
    }
    return f;
}


Eigen::VectorXd contactModel::frictionRelease(long nUnknowns) const
{
    // The law's decision on the forces of the last solve, as the first
    // step's capStuckShearForce will make it
    Eigen::VectorXd f = Eigen::VectorXd::Zero(nUnknowns);
    for (const active& a : active_)
    {
        const contactRecord& r = a.record;
        if (r.state != contactState::bonded || r.bondIntact) continue;
        contactQuery q;
        q.state = r.state;
        q.gap = r.gap;
        q.Fn = r.normalForce;
        q.Fs = r.shearForce;
        q.length = r.length*thickness_;
        const contactDecision d = a.law->decide(q);
        if (d.state != contactState::sliding) continue;
        for (const auto& [dof, c] : a.h) f[dof] += (d.frictionForce - r.shearForce)*c;
    }
    return f;
}


Eigen::VectorXd contactModel::pressureLoads(long nUnknowns) const
{
    Eigen::VectorXd f = Eigen::VectorXd::Zero(nUnknowns);
    if (pressure_.empty()) return f;     // no coupled fluid
    for (const active& a : active_)
    {
        // Work of the pair of forces on the opening: F dgap, dgap = g dd
        for (const auto& [dof, c] : a.g) f[dof] += a.pressureForce*c;
    }
    return f;
}


double contactModel::stepLength
(
    const Eigen::VectorXd& dd,
    const Eigen::VectorXd& delta,
    double curvature,
    double slope
) const
{
    // The derivative of the potential along the line is piecewise linear
    // and non-decreasing: a spring without a bond pulls nothing, so its
    // term has a kink where its gap passes zero. Shear terms are those of
    // the assumed states (friction has no potential)
    // A spring's force is lambda - kN gap (lambda the augmented
    // Lagrangian's multiplier, 0 with plain penalties), its potential
    // kN/2 gap^2 - lambda gap; without a bond it pulls nothing, beyond
    // gap = lambda/kN
    struct line
    {
        double gap, rate, kN, lambda;
        bool oneSided;
        double kink() const { return lambda/kN; }
        double potential(double g) const
        {
            if (oneSided) g = std::min(g, kink());
            return 0.5*kN*g*g - lambda*g;
        }
    };
    std::vector<line> springs;
    springs.reserve(active_.size());
    double a = curvature, b = slope;
    bool frictionLoads = false;
    for (const active& c : active_)
    {
        const contactState s = c.record.state;
        const double dh = along(c.h, delta);
        if (s == contactState::bonded)
        {
            a += c.kS*dh*dh;
            b += (c.kS*along(c.h, dd) - c.shearForce0)*dh;
        }
        else if (s == contactState::sliding)
        {
            b -= c.friction*dh;
            frictionLoads = frictionLoads || c.friction != 0;
        }
        const bool bond = c.record.bondIntact && isClosed(s);
        const double lambda = isClosed(s) ? c.record.multiplier : 0.0;
        springs.push_back({c.gap0 + along(c.g, dd), along(c.g, delta), c.kN, lambda, !bond});
    }
    const auto derivative = [&](double alpha)
    {
        double d = a*alpha + b;
        for (const line& l : springs)
        {
            const double gap = l.gap + alpha*l.rate;
            if (!l.oneSided || gap < l.kink()) d += (l.kN*gap - l.lambda)*l.rate;
        }
        return d;
    };
    // The potential's change over the whole increment
    const auto fall = [&]
    {
        double f = 0.5*a + b;
        for (const line& l : springs) f += l.potential(l.gap + l.rate) - l.potential(l.gap);
        return f;
    };

    // A solve that changed no state ends at the minimum, where the slope
    // is zero up to rounding: that end is the minimum, not a step short
    const double d0 = derivative(0);
    const double d1 = derivative(1);
    if (!(d0 < 0) || d1 <= endSlope*(-d0)) return 1;

    // Without friction the potential is the same in every iteration, and
    // the full step is taken when it lowers it enough (Armijo): the solve
    // knows the contacts the step reaches, the line's minimum stops at the
    // first that resists. Friction loads change from solve to solve, so
    // with them only the minimum keeps the states from cycling
    if (!frictionLoads && fall() <= sufficientDecrease*d0) return 1;

    // Between two neighbouring kinks the derivative is linear
    std::vector<double> kinks{0.0, 1.0};
    for (const line& l : springs)
    {
        const double at = l.rate != 0 ? (l.kink() - l.gap)/l.rate : -1;
        if (l.oneSided && at > 0 && at < 1) kinks.push_back(at);
    }
    std::sort(kinks.begin(), kinks.end());

    std::size_t lo = 0, hi = kinks.size() - 1;
    double dLo = d0, dHi = d1;
    while (hi - lo > 1)
    {
        const std::size_t mid = (lo + hi)/2;
        const double dMid = derivative(kinks[mid]);
        if (dMid < 0) { lo = mid; dLo = dMid; }
        else { hi = mid; dHi = dMid; }
    }
    return kinks[lo] - dLo*(kinks[hi] - kinks[lo])/(dHi - dLo);
}


contactModel::iterationCounts contactModel::update(const Eigen::VectorXd& dd)
{
    // Each contact on its own, on OpenMP's threads; the counts summed
    // after, in the contacts' order, so that their sums are one thread's
    const long n = long(active_.size());
    std::vector<contactTally> tally(active_.size());
    #pragma omp parallel for schedule(dynamic, 64) if (threaded_ && n >= minThreadedContacts)
    for (long k = 0; k < n; ++k) tally[std::size_t(k)] = updateOne(active_[std::size_t(k)], dd);
    iterationCounts counts;
    for (const contactTally& c : tally)
    {
        counts.changes += c.changed;
        counts.chattering += c.chattering;
        counts.bondsBroken += c.bondBroken;
        counts.frictionUpdates += c.frictionUpdated;
        // + 0 leaves a sum of magnitudes as it was, bit for bit
        counts.frictionChange += c.frictionChange;
        counts.frictionLoad += c.frictionLoad;
        ++counts.states[contactStateNumber(c.state)];
    }
    statesSteady_ = counts.changes == 0;
    return counts;
}


contactDecision contactModel::decideState
(
    active& a,
    const contactQuery& q,
    bool slips
) const
{
    contactDecision d = a.law->decide(q);
    const contactState state = a.record.state;
    if (holdFriction_ && d.state == contactState::sliding)
    {
        d.state = contactState::bonded;
        d.frictionForce = 0;
    }
    if
    (
        state == contactState::sliding && d.state == contactState::sliding
     && slips && a.friction*a.ds > 0
    )
    {
        // The friction load drove the vertex backwards: it overshoots
        // the stop within the step, so the contact sticks (Shi's rule
        // for a reversed slip). It stops where the slip reversed, at
        // the step's start, with the friction force in its spring: the
        // spring force the step started with may lie outside the cone
        // the step ends with, and would make it slide again
        d.state = contactState::bonded;
        a.shearForce0 = a.friction;
        a.locked = true;
    }
    else if
    (
        a.locked && state == contactState::bonded
     && d.state == contactState::sliding
     && std::abs(q.Fs) <= (1 + frictionTolerance)*std::abs(d.frictionForce)
    )
    {
        // Locked at the friction force, it stays within the friction
        // tolerance of the cone rather than slide and reverse again
        d.state = contactState::bonded;
        d.frictionForce = 0;
    }
    return d;
}


contactModel::contactTally contactModel::updateOne(active& a, const Eigen::VectorXd& dd) const
{
    contactTally tally;
    contactRecord& r = a.record;
    a.dn = along(a.g, dd);
    a.ds = along(a.h, dd);
    r.gap = a.gap0 + a.dn;

    contactQuery q;
    q.state = r.state;
    q.bondIntact = r.bondIntact;
    q.gap = r.gap;
    // An open contact gets the trial forces of closing over the whole
    // step, so that one that closes while slipping starts sliding
    q.Fn = r.multiplier - a.kN*r.gap;
    q.Fs = a.shearForce0 - a.kS*a.ds;
    q.length = r.length*thickness_;
    // A coupled fluid's pressure is a load on the faces (pressureLoads),
    // so the springs carry the rest, the effective normal force Fn - p L
    // of the paper's Eq. 8, which the law compares with its strengths
    // A slip within the touch tolerance is rounding: its sign must not
    // turn the friction of a contact at rest
    const bool slips = std::abs(a.ds) > settings_.touchTolerance;
    q.shearDisplacement = r.state != contactState::bonded && slips ? a.ds : 0;

    const contactDecision d = decideState(a, q, slips);
    if (d.state != r.state)
    {
        tally.changed = true;
        ++a.changes;
        tally.chattering = a.changes >= maxChangesPerStep;
    }
    if (d.bondBroken)
    {
        tally.bondBroken = true;
        r.bondBroken = true;
    }
    r.normalForce = isClosed(r.state) ? q.Fn : 0;
    r.shearForce = r.state == contactState::sliding ? a.friction
                 : r.state == contactState::bonded ? q.Fs : 0;
    // Friction needs the normal force of a closed solve: the trial
    // force of an open contact can be any multiple of the real one
    double friction = r.state == contactState::open ? 0.0 : d.frictionForce;
    if (d.state == contactState::sliding && d.state == r.state)
    {
        friction = a.frictionStep.next(a.friction, friction, statesSteady_);
        // A change of the size of a spring's force over the rounding
        // of a gap is rounding
        const double scale = std::max(std::abs(friction), a.kN*gapRounding_);
        const double moved = std::abs(a.frictionStep.lastChange());
        tally.frictionUpdated = moved > frictionTolerance*scale;
        if (moved > frictionTolerance*a.kN*gapRounding_) tally.frictionChange = moved;
        tally.frictionLoad = std::abs(friction);
    }
    r.state = d.state;
    r.bondIntact = d.bondIntact;
    // An open contact carries no force: its multiplier starts again
    // from 0 when it closes
    if (!isClosed(r.state)) r.multiplier = 0;
    a.friction = friction;
    tally.state = r.state;
    return tally;
}


bool contactModel::iterationCounts::frictionSettled() const
{
    return frictionChange <= frictionTolerance*frictionLoad;
}


void contactModel::augment()
{
    for (active& a : active_)
    {
        contactRecord& r = a.record;
        if (!isClosed(r.state)) continue;
        // Uzawa: the multiplier takes the whole force of the last solve,
        // which the spring then need not carry by penetrating
        r.multiplier -= a.kN*r.gap;
        if (!r.bondIntact) r.multiplier = std::max(r.multiplier, 0.0);
    }
}


Eigen::Vector2d contactModel::startForces(std::size_t i) const
{
    const contactRecord& r = active_[i].record;
    if (!isClosed(r.state)) return Eigen::Vector2d::Zero();
    return {r.normalForce, r.shearForce};
}


Eigen::Vector2d contactModel::relax
(
    std::size_t i,
    const Eigen::Vector2d& rho,
    const Eigen::Matrix2d& W,
    bool& changed
)
{
    active& a = active_[i];
    contactRecord& r = a.record;
    const contactState before = r.state;
    const double gapFree = a.gap0 + rho[0];
    a.overloaded = false;

    Eigen::Vector2d lambda = Eigen::Vector2d::Zero();
    contactDecision d;
    d.state = contactState::open;
    d.bondIntact = r.bondIntact;
    // Apart without its force and nothing to hold it: open, without
    // asking the law (an open contact's trial forces would be tension)
    if (r.state != contactState::open || gapFree < 0 || r.bondIntact)
    {
        // The stick solution: both springs on, with the forces they
        // carry from the last step (multiplier and shear force)
        const double lambda0 = isClosed(r.state) ? r.multiplier : 0.0;
        Eigen::Matrix2d A = Eigen::Matrix2d::Identity();
        A.row(0) += a.kN*W.row(0);
        A.row(1) += a.kS*W.row(1);
        const Eigen::Vector2d b(lambda0 - a.kN*gapFree, a.shearForce0 - a.kS*rho[1]);
        lambda = A.inverse()*b;

        contactQuery q;
        q.state = r.state;
        q.bondIntact = r.bondIntact;
        q.gap = gapFree + W.row(0).dot(lambda);
        q.Fn = lambda[0];
        q.Fs = lambda[1];
        q.length = r.length*thickness_;
        d = a.law->decide(q);
        if (holdFriction_ && d.state == contactState::sliding) d.state = contactState::bonded;
        if (d.bondBroken)
        {
            // Broken only once the others have settled too: the forces of
            // an unsettled iterate can be far off
            a.overloaded = true;
            d.state = contactState::bonded;
            d.bondIntact = true;
            d.bondBroken = false;
        }
        if (d.state != contactState::bonded) lambda = slipSolution(a, q, gapFree, W, d);
    }
    r.state = d.state;
    r.bondIntact = d.bondIntact;
    if (!isClosed(r.state)) r.multiplier = 0;
    r.normalForce = lambda[0];
    r.shearForce = lambda[1];
    a.friction = r.state == contactState::sliding ? lambda[1] : 0.0;
    changed = r.state != before;
    return lambda;
}


contactModel::stateEquations contactModel::equations(std::size_t i) const
{
    const active& a = active_[i];
    const contactRecord& r = a.record;
    stateEquations e;
    e.state = r.state;
    if (!isClosed(r.state)) return e;
    e.compliance = {1/a.kN, 1/a.kS};
    e.rhs = {r.multiplier/a.kN - a.gap0, a.shearForce0/a.kS};
    if (r.state == contactState::sliding && r.normalForce > 0)
    {
        e.friction = a.friction/r.normalForce;
    }
    return e;
}


void contactModel::setForces(std::size_t i, const Eigen::Vector2d& lambda)
{
    active& a = active_[i];
    a.record.normalForce = lambda[0];
    a.record.shearForce = lambda[1];
    if (a.record.state == contactState::sliding) a.friction = lambda[1];
}


void contactModel::setForces
(
    std::size_t i,
    const Eigen::Vector2d& lambda,
    contactState s
)
{
    active_[i].record.state = s;
    setForces(i, lambda);
}


Eigen::Vector2d contactModel::slipSolution
(
    const active& a,
    const contactQuery& trial,
    double gapFree,
    const Eigen::Matrix2d& W,
    contactDecision& d
) const
{
    // The friction acts along the stick solution's shear force (a return
    // mapping onto the friction cone) and moves the gap by W_nt, so the
    // normal force is solved with it. The stick solution's normal force
    // is not the one to judge opening by: its shear force, which the
    // friction replaces, can be far larger and pull the gap open through
    // W_nt. The friction per unit normal force is the law's at unit
    // compression
    contactQuery s = trial;
    s.Fn = 1;
    const double perUnit = a.law->slidingFriction(s);
    const double lambda0 = a.record.multiplier;
    const double soft = 1 + a.kN*(W(0, 0) + W(0, 1)*perUnit);
    if (!(soft > 0))
    {
        // The friction would pull the contact open faster than its spring
        // closes it (Painleve's paradox): no slip solution. It jams,
        // stuck, where the stick solution presses it; else it opens
        d.state = trial.Fn > 0 ? contactState::bonded : contactState::open;
        return d.state == contactState::bonded
            ? Eigen::Vector2d(trial.Fn, trial.Fs) : Eigen::Vector2d::Zero();
    }
    const double Fn = (lambda0 - a.kN*gapFree)/soft;
    if (!(Fn > 0))
    {
        d.state = contactState::open;
        return Eigen::Vector2d::Zero();
    }
    d.state = contactState::sliding;
    s.Fn = Fn;
    return {Fn, a.law->slidingFriction(s)};
}


long contactModel::breakOverloadedBonds()
{
    long broken = 0;
    for (active& a : active_)
    {
        if (!a.overloaded) continue;
        a.overloaded = false;
        a.record.bondIntact = false;
        a.record.bondBroken = true;
        ++broken;
    }
    return broken;
}


contactModel::iterationCounts contactModel::settleForces(const Eigen::VectorXd& dd)
{
    const long n = long(active_.size());
    #pragma omp parallel for schedule(static) if (threaded_ && n >= minThreadedContacts)
    for (long k = 0; k < n; ++k)
    {
        active& a = active_[std::size_t(k)];
        a.dn = along(a.g, dd);
        a.ds = along(a.h, dd);
        a.record.gap = a.gap0 + a.dn;
    }
    iterationCounts counts;
    for (const active& a : active_) ++counts.states[contactStateNumber(a.record.state)];
    return counts;
}


std::vector<double> contactModel::blockClearances(double reach) const
{
    const auto& loops = boundaries_.loops();
    const std::vector<double> ofLoop = search_.clearances(loops, reach);
    std::vector<double> ofBlock(materialOfBlock_.size(), reach);
    for (std::size_t l = 0; l < loops.size(); ++l)
    {
        double& c = ofBlock[std::size_t(loops[l].block)];
        c = std::min(c, ofLoop[l]);
    }
    return ofBlock;
}


double contactModel::maxPenetration() const
{
    double p = 0;
    for (const active& a : active_)
    {
        if (isClosed(a.record.state)) p = std::max(p, -a.record.gap);
    }
    return p;
}


double contactModel::maxPenetrationGrowth() const
{
    double p = 0;
    for (const active& a : active_)
    {
        // A contact that creeps deeper step by step is not the step's
        // doing: cutting it would not help
        if (isClosed(a.record.state) && a.dn < -settings_.overlapRelief)
        {
            p = std::max(p, -a.record.gap);
        }
    }
    return p;
}


long contactModel::overlapsAtStart() const
{
    return std::count_if(active_.begin(), active_.end(), [](const active& a)
    {
        return a.relieved;
    });
}


std::vector<contactRecord> contactModel::records() const
{
    // After a settled iteration every state is the one its solve used, so
    // the forces update() recorded belong to it. Each contact's on its
    // own: on OpenMP's threads
    const long n = long(active_.size());
    std::vector<contactRecord> result(active_.size());
    #pragma omp parallel for schedule(static) if (threaded_ && n >= minThreadedContacts)
    for (long k = 0; k < n; ++k)
    {
        const active& a = active_[std::size_t(k)];
        contactRecord& r = result[std::size_t(k)];
        r = a.record;
        if (r.state == contactState::sliding) r.slip += a.ds;
        if (!isClosed(r.state))
        {
            r.normalForce = 0;
            r.shearForce = 0;
        }
    }
    return result;
}


double contactModel::energy(const std::vector<contactRecord>& records) const
{
    double e = 0;
    for (const auto& r : records)
    {
        if (!isClosed(r.state)) continue;
        const double w = thickness_*weight(r.length);
        e += 0.5*r.normalForce*r.normalForce/(settings_.normalPenalty*w);
        if (r.state == contactState::bonded)
        {
            e += 0.5*r.shearForce*r.shearForce/(settings_.shearPenalty*w);
        }
    }
    return e;
}

} // End namespace nmm
