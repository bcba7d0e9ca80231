#include "nmmSolid/solver/assembler/nmmAssembler.H"

#include "nmmSolid/solver/threadRanges/threadRanges.H"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace nmm
{

namespace
{

using manifoldElement::baryPoint;
using manifoldElement::matrix36;
using manifoldElement::matrix66;
using manifoldElement::triangleNodes;
using manifoldElement::vector6;
using matrix26 = Eigen::Matrix<double, 2, 6>;
using matrix23 = Eigen::Matrix<double, 2, 3>;

//- Nitsche's parameter over the bound that keeps an element's energy
//  positive (see the class description)
constexpr double nitscheSafety = 2;
constexpr double nitscheBound = 8;
//- Elements smaller than this part of their triangle take it as their
//  area in Nitsche's parameter (see the class description)
constexpr double nitscheAreaFloor = 0.25;

//- 3-point Gauss rule on [0, 1]
const std::array<double, 3> gaussPoints{{0.5 - 0.5*std::sqrt(0.6), 0.5, 0.5 + 0.5*std::sqrt(0.6)}};
const std::array<double, 3> gaussWeights{{5.0/18, 8.0/18, 5.0/18}};


matrix26 weightMatrix(const baryPoint& lambda)
{
    matrix26 N = matrix26::Zero();
    for (int k = 0; k < 3; ++k)
    {
        N(0, 2*k) = lambda[k];
        N(1, 2*k + 1) = lambda[k];
    }
    return N;
}


//- Traction P_n sigma of a Voigt stress (xx, yy, xy) on normal n
matrix23 tractionMatrix(const Eigen::Vector2d& n)
{
    matrix23 P;
    P << n.x(), 0, n.y(),
         0, n.y(), n.x();
    return P;
}


//- A boundary segment of an element in the current configuration
struct segmentGeometry
{
    Eigen::Vector2d p, q, normal;
    double length;
};


segmentGeometry currentSegment
(
    const triangleNodes& T,
    const physicalCover::boundarySegment& s
)
{
    segmentGeometry g;
    g.p = manifoldElement::toCartesian(T, s.p);
    g.q = manifoldElement::toCartesian(T, s.q);
    const Eigen::Vector2d d = g.q - g.p;
    g.length = d.norm();
    // Material on the left: the outward normal is on the right
    g.normal = Eigen::Vector2d::Zero();
    if (g.length > 0) g.normal = Eigen::Vector2d(d.y(), -d.x())/g.length;
    return g;
}

} // End anonymous namespace


nmmAssembler::nmmAssembler
(
    const manifoldSpace& space,
    std::vector<elementMaterial> materials,
    double thickness,
    std::vector<const boundaryRule*> segmentRules,
    const Eigen::Vector2d& gravity
)
:
    space_(space),
    pc_(space.elements()),
    materials_(std::move(materials)),
    thickness_(thickness),
    rules_(std::move(segmentRules)),
    gravity_(gravity)
{
    setFluxElements();
    elementFirst_.assign(pc_.nElements() + 1, 0);
    for (label e = 0; e < label(pc_.nElements()); ++e)
    {
        elementFirst_[std::size_t(e) + 1] = elementFirst_[std::size_t(e)] + products(e);
    }
    setBodyForce();
}


void nmmAssembler::setFluxElements()
{
    const auto& els = pc_.elements();
    std::vector<std::vector<label>> elementsOf(pc_.nPatches());
    for (label e = 0; e < label(els.size()); ++e)
    {
        for (const label p : els[e].patches) elementsOf[p].push_back(e);
    }
    fluxElement_.resize(els.size());
    for (label e = 0; e < label(els.size()); ++e)
    {
        fluxElement_[e] = e;
        if (els[e].areaRatio >= nitscheAreaFloor) continue;
        for (const label p : els[e].patches)
        {
            for (const label f : elementsOf[p])
            {
                int shared = 0;
                for (const label q : els[f].patches)
                {
                    for (const label r : els[e].patches) shared += (q == r);
                }
                if (shared >= 2 && els[f].areaRatio > els[fluxElement_[e]].areaRatio)
                {
                    fluxElement_[e] = f;
                }
            }
        }
    }
}


std::size_t nmmAssembler::products(label e) const
{
    const auto terms = space_.dofTerms(e);
    std::size_t n = 0;
    for (const auto& a : terms)
    {
        for (const auto& b : terms) n += a.coefficient*b.coefficient != 0;
    }
    return n;
}


Eigen::Triplet<double>* nmmAssembler::scatter
(
    label e,
    const matrix66& Ke,
    Eigen::Triplet<double>* K
) const
{
    const auto terms = space_.dofTerms(e);
    for (const auto& a : terms)
    {
        for (const auto& b : terms)
        {
            // Exact zeros of Ke are kept: the pattern must not depend on
            // the state (a zero of an axis-aligned triangle becomes a
            // nonzero once it moves, and the analysis would be redone)
            const double w = a.coefficient*b.coefficient;
            if (w != 0) *K++ = {a.dof, b.dof, w*Ke(a.local, b.local)};
        }
    }
    return K;
}


void nmmAssembler::scatter(label e, const matrix66& Ke, triplets& K) const
{
    const std::size_t at = K.size();
    K.resize(at + products(e));
    scatter(e, Ke, K.data() + at);
}


void nmmAssembler::scatter(label r, label c, const matrix66& Ke, triplets& K) const
{
    const auto rows = space_.dofTerms(r);
    const auto cols = space_.dofTerms(c);
    for (const auto& a : rows)
    {
        for (const auto& b : cols)
        {
            // Exact zeros of Ke are kept: the pattern must not depend on
            // the state (a zero of an axis-aligned triangle becomes a
            // nonzero once it moves, and the analysis would be redone)
            const double w = a.coefficient*b.coefficient;
            if (w != 0) K.emplace_back(a.dof, b.dof, w*Ke(a.local, b.local));
        }
    }
}


void nmmAssembler::scatter(label e, const vector6& fe, Eigen::VectorXd& f) const
{
    for (const auto& a : space_.dofTerms(e)) f[a.dof] += a.coefficient*fe[a.local];
}


void nmmAssembler::scatter(const std::vector<vector6>& fe, Eigen::VectorXd& f) const
{
    if (vectorParts_.empty())
    {
        for (label e = 0; e < label(fe.size()); ++e) scatter(e, fe[std::size_t(e)], f);
        return;
    }
    const long nParts = long(vectorParts_.size());
    #pragma omp parallel for schedule(static, 1)
    for (long p = 0; p < nParts; ++p)
    {
        for (const auto& [e, k] : vectorParts_[std::size_t(p)])
        {
            const auto& a = space_.dofTerms(e).begin()[k];
            f[a.dof] += a.coefficient*fe[std::size_t(e)][a.local];
        }
    }
}


void nmmAssembler::makeVectorParts()
{
    vectorParts_.clear();
    if (!threadsElements()) return;
    const label nE = label(pc_.nElements());
    std::vector<std::size_t> writes(nUnknowns(), 0);
    for (label e = 0; e < nE; ++e)
    {
        for (const auto& a : space_.dofTerms(e)) ++writes[std::size_t(a.dof)];
    }
    const std::vector<std::size_t> start = threadRanges(writes);
    vectorParts_.assign(start.size() - 1, {});
    for (label e = 0; e < nE; ++e)
    {
        int k = 0;
        for (const auto& a : space_.dofTerms(e))
        {
            const auto p = std::upper_bound(start.begin(), start.end(), std::size_t(a.dof))
                - start.begin() - 1;
            vectorParts_[std::size_t(p)].emplace_back(e, k++);
        }
    }
}


void nmmAssembler::addElements
(
    const fieldState& s,
    const Eigen::Matrix2Xd& patchD,
    triplets& K,
    Eigen::VectorXd& f
) const
{
    // Each element writes its own range of the triplets, the same on any
    // number of threads: the pattern cache compares positions in that
    // order, and each entry is summed in the same order
    const label nE = label(pc_.nElements());
    std::vector<vector6> fe(static_cast<std::size_t>(nE));
    #pragma omp parallel for schedule(static) if (threadsElements())
    for (label e = 0; e < nE; ++e)
    {
        if (space_.fixedElement(e))
        {
            fe[std::size_t(e)].setZero();
            continue;
        }
        const auto T = space_.currentTriangle(e, patchD);
        const double area = space_.currentArea(e, T);
        const matrix36 B = manifoldElement::strainMatrix(T);
        scatter(e, manifoldElement::stiffness(B, area, materials_[e].D, thickness_),
                K.data() + elementFirst_[std::size_t(e)]);
        fe[std::size_t(e)] = -area*thickness_*B.transpose()*startStress(s, e);
    }
    scatter(fe, f);
}


Eigen::Vector3d nmmAssembler::startStress(const fieldState& s, label e) const
{
    // A thermal strain in the step is a stress the element starts from
    if (temperatureIncrement_.empty()) return s.sigma[e].head<3>();
    return s.sigma[e].head<3>()
        - materials_[e].D*thermalStrain(e, temperatureIncrement_[std::size_t(e)]);
}


void nmmAssembler::setBodyForce()
{
    if (gravity_.isZero()) return;
    const label nE = label(pc_.nElements());
    elementBodyForce_.assign(std::size_t(nE), manifoldElement::vector6::Zero());
    bodyForce_ = Eigen::VectorXd::Zero(Eigen::Index(nUnknowns()));
    for (label e = 0; e < nE; ++e)
    {
        if (space_.fixedElement(e)) continue;
        elementBodyForce_[std::size_t(e)] = manifoldElement::bodyForce
        (
            pc_.elements()[e].moments, materials_[e].rho*gravity_, thickness_
        );
        scatter(e, elementBodyForce_[std::size_t(e)], bodyForce_);
    }
}


void nmmAssembler::addBodyForce(Eigen::VectorXd& f) const
{
    // Element by element onto f, not bodyForce_ added: each entry summed
    // in the order it always was, so that a run repeats to the last digit
    if (!elementBodyForce_.empty()) scatter(elementBodyForce_, f);
}


std::vector<double> nmmAssembler::nitscheParameters(const Eigen::Matrix2Xd& patchD) const
{
    std::vector<double> length(pc_.nElements(), 0.0), gamma(pc_.nElements(), 0.0);
    for (std::size_t i = 0; i < rules_.size(); ++i)
    {
        const auto* rule = rules_[i];
        if (!rule || (rule->type != boundaryRule::kind::fixedValue
                   && rule->type != boundaryRule::kind::fixedNormal)) continue;
        const auto& seg = pc_.segments()[i];
        length[fluxElement_[seg.element]] +=
            currentSegment(space_.currentTriangle(seg.element, patchD), seg).length;
    }
    for (label e = 0; e < label(pc_.nElements()); ++e)
    {
        if (length[e] == 0) continue;
        const auto T = space_.currentTriangle(e, patchD);
        const double area = std::max
        (
            space_.currentArea(e, T),
            nitscheAreaFloor*std::abs(manifoldElement::signedArea(T))
        );
        gamma[e] = nitscheSafety*nitscheBound*materials_[e].lambdaMax*length[e]/area;
    }
    return gamma;
}


void nmmAssembler::addSegments
(
    const fieldState& s,
    const Eigen::Matrix2Xd& patchD,
    double t1,
    triplets& K,
    Eigen::VectorXd& f
) const
{
    const auto gamma = nitscheParameters(patchD);
    addCouplingLoads(patchD, f);
    for (std::size_t i = 0; i < rules_.size(); ++i)
    {
        const boundaryRule* rule = rules_[i];
        if (!rule || rule->type == boundaryRule::kind::tractionFree) continue;
        const auto& seg = pc_.segments()[i];
        const label e = seg.element;
        const auto g = currentSegment(space_.currentTriangle(e, patchD), seg);
        if (g.length == 0) continue;
        if (rule->type == boundaryRule::kind::traction)
        {
            addTraction(*rule, seg, g.length, g.normal, t1, f);
        }
        else
        {
            addNitsche(*rule, seg, g.length, g.normal, t1, gamma, s, patchD, K, f);
        }
    }
}


void nmmAssembler::addTraction
(
    const boundaryRule& rule,
    const physicalCover::boundarySegment& seg,
    double length,
    const Eigen::Vector2d& normal,
    double t1,
    Eigen::VectorXd& f
) const
{
    addLoad(seg, length, [&](const Eigen::Vector2d& X)
    {
        return Eigen::Vector2d(rule.vectorValue(X, t1) - rule.scalarValue(X, t1)*normal);
    }, f);
}


void nmmAssembler::addLoad
(
    const physicalCover::boundarySegment& seg,
    double length,
    const std::function<Eigen::Vector2d(const Eigen::Vector2d&)>& tr,
    Eigen::VectorXd& f
) const
{
    const auto T0 = space_.referenceTriangle(seg.element);
    vector6 fs = vector6::Zero();
    for (int qp = 0; qp < 3; ++qp)
    {
        const baryPoint lambda = (1 - gaussPoints[qp])*seg.p + gaussPoints[qp]*seg.q;
        const Eigen::Vector2d X = manifoldElement::toCartesian(T0, lambda);
        fs += gaussWeights[qp]*length*thickness_*weightMatrix(lambda).transpose()*tr(X);
    }
    scatter(seg.element, fs, f);
}


void nmmAssembler::addCouplingLoads(const Eigen::Matrix2Xd& patchD, Eigen::VectorXd& f) const
{
    const std::size_t n = std::max(couplingPressure_.size(), couplingTraction_.size());
    for (std::size_t i = 0; i < n; ++i)
    {
        const double p = i < couplingPressure_.size() ? couplingPressure_[i] : 0.0;
        const Eigen::Vector2d t = i < couplingTraction_.size()
            ? couplingTraction_[i] : Eigen::Vector2d::Zero();
        if (p == 0 && t.isZero()) continue;
        const auto& seg = pc_.segments()[i];
        const auto g = currentSegment(space_.currentTriangle(seg.element, patchD), seg);
        if (g.length == 0) continue;
        const Eigen::Vector2d tr = t - p*g.normal;
        addLoad(seg, g.length, [&](const Eigen::Vector2d&) { return tr; }, f);
    }
}


void nmmAssembler::setTemperatureIncrement(std::vector<double> dT)
{
    if (!dT.empty() && dT.size() != pc_.nElements())
    {
        throw std::invalid_argument("setTemperatureIncrement: " + std::to_string(dT.size())
            + " values for " + std::to_string(pc_.nElements()) + " elements");
    }
    temperatureIncrement_ = std::move(dT);
}


void nmmAssembler::setCouplingPressure(std::vector<double> p)
{
    if (!p.empty() && p.size() != pc_.segments().size())
    {
        throw std::invalid_argument("setCouplingPressure: " + std::to_string(p.size())
            + " values for " + std::to_string(pc_.segments().size()) + " boundary segments");
    }
    couplingPressure_ = std::move(p);
}


void nmmAssembler::setCouplingTraction(std::vector<Eigen::Vector2d> t)
{
    if (!t.empty() && t.size() != pc_.segments().size())
    {
        throw std::invalid_argument("setCouplingTraction: " + std::to_string(t.size())
            + " values for " + std::to_string(pc_.segments().size()) + " boundary segments");
    }
    couplingTraction_ = std::move(t);
}


void nmmAssembler::addNitsche
(
    const boundaryRule& rule,
    const physicalCover::boundarySegment& seg,
    double length,
    const Eigen::Vector2d& normal,
    double t1,
    const std::vector<double>& gamma,
    const fieldState& s,
    const Eigen::Matrix2Xd& patchD,
    triplets& K,
    Eigen::VectorXd& f
) const
{
    const label e = seg.element;
    const label fe = fluxElement_[e];
    const auto T0 = space_.referenceTriangle(e);
    const double gam = gamma[fe];

    // The flux: traction of the flux element's stress and of its dofs
    const matrix23 Pn = tractionMatrix(normal);
    const matrix26 tractionOfD
        = Pn*materials_[fe].D*manifoldElement::strainMatrix(space_.currentTriangle(fe, patchD));
    const Eigen::Vector2d sigmaN = Pn*startStress(s, fe);
    const Eigen::VectorXd de = space_.elementDisplacements(e, s.D);

    // Projection on what is prescribed: all of u, or its normal part
    const bool normalOnly = rule.type == boundaryRule::kind::fixedNormal;
    const Eigen::Matrix2d P = normalOnly ? Eigen::Matrix2d(normal*normal.transpose())
                                         : Eigen::Matrix2d::Identity();

    matrix66 Kee = matrix66::Zero(), Kef = matrix66::Zero();
    vector6 fE = vector6::Zero(), fF = vector6::Zero();
    for (int qp = 0; qp < 3; ++qp)
    {
        const baryPoint lambda = (1 - gaussPoints[qp])*seg.p + gaussPoints[qp]*seg.q;
        const double w = gaussWeights[qp]*length*thickness_;
        const matrix26 N = weightMatrix(lambda);
        const Eigen::Vector2d X = manifoldElement::toCartesian(T0, lambda);
        const Eigen::Vector2d target = normalOnly
            ? Eigen::Vector2d(rule.scalarValue(X, t1)*normal)
            : rule.vectorValue(X, t1);
        const Eigen::Vector2d r = P*(target - N*de);

        Kee += w*gam*N.transpose()*P*N;
        Kef -= w*N.transpose()*P*tractionOfD;
        fE += w*(N.transpose()*P*sigmaN + gam*N.transpose()*r);
        fF -= w*tractionOfD.transpose()*r;
    }
    scatter(e, Kee, K);
    scatter(e, fe, Kef, K);
    scatter(fe, e, matrix66(Kef.transpose()), K);
    scatter(e, fE, f);
    scatter(fe, fF, f);
}


Eigen::VectorXd nmmAssembler::externalForces(const fieldState& s, double t) const
{
    Eigen::VectorXd f = bodyForce_.size()
        ? bodyForce_ : Eigen::VectorXd::Zero(Eigen::Index(nUnknowns()));
    const auto patchD = space_.patchDisplacements(s.D);
    addCouplingLoads(patchD, f);
    for (std::size_t i = 0; i < rules_.size(); ++i)
    {
        const boundaryRule* rule = rules_[i];
        if (!rule || rule->type != boundaryRule::kind::traction) continue;
        const auto& seg = pc_.segments()[i];
        const auto g = currentSegment(space_.currentTriangle(seg.element, patchD), seg);
        if (g.length == 0) continue;
        addTraction(*rule, seg, g.length, g.normal, t, f);
    }
    return f;
}


void nmmAssembler::buildMass()
{
    triplets M;
    for (label e = 0; e < label(pc_.nElements()); ++e)
    {
        scatter
        (
            e,
            manifoldElement::mass(pc_.elements()[e].moments, materials_[e].rho, thickness_),
            M
        );
    }
    M_.resize(Eigen::Index(nUnknowns()), Eigen::Index(nUnknowns()));
    M_.setFromTriplets(M.begin(), M.end());
    massRows_.resize(0, 0);
}


Eigen::VectorXd nmmAssembler::massTimes(const Eigen::VectorXd& x) const
{
    if (massRows_.rows() != M_.rows()) massRows_ = M_;
    Eigen::VectorXd y(M_.rows());
    const long n = long(massRows_.rows());
    #pragma omp parallel for schedule(static) if (threadsElements())
    for (long i = 0; i < n; ++i)
    {
        double sum = 0;
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(massRows_, i); it; ++it)
        {
            sum += it.value()*x[it.index()];
        }
        y[i] = sum;
    }
    return y;
}


nmmAssembler::system nmmAssembler::assemble
(
    const fieldState& s,
    double dt,
    const timeScheme& scheme
) const
{
    const double t1 = s.time + dt;
    const Eigen::Index n = Eigen::Index(nUnknowns());
    // The elements' entries first, each at its place: the list is cut to
    // them, not cleared, as they are all written again (a cleared list
    // would be filled with zeros first, a tenth of the assembly's time)
    triplets& K = pattern_.triplets();
    K.resize(elementFirst_.back());
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    const auto patchD = space_.patchDisplacements(s.D);
    addElements(s, patchD, K, f);
    addBodyForce(f);
    addSegments(s, patchD, t1, K, f);
    if (!scheme.dynamic()) return {pattern_.assemble(n, n), std::move(f)};
    // After the elements' terms, so each entry is their sum plus the mass
    // term, as K + c M would give
    const sparseMatrix& Km = pattern_.assemble(n, n, &M_, scheme.massFactor(dt));
    f += massTimes(scheme.velocityFactor(dt)*s.V + scheme.accelerationFactor()*s.A);
    return {Km, std::move(f)};
}

} // End namespace nmm
