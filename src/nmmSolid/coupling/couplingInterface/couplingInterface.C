#include "nmmSolid/coupling/couplingInterface/couplingInterface.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/dictionary/IOerror.H"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nmm
{

namespace
{

//- Position of a segment of the boundary on the faces of a patch
template<class Key>
long indexIn(const std::vector<Key>& sorted, const Key& k)
{
    const auto it = std::lower_bound(sorted.begin(), sorted.end(), k);
    return it != sorted.end() && *it == k ? long(it - sorted.begin()) : -1;
}


//- The segment's end points, displaced by patchD (zero: reference)
std::pair<Eigen::Vector2d, Eigen::Vector2d> segmentEnds
(
    const nmmSolidModel& m,
    const physicalCover::boundarySegment& s,
    const Eigen::Matrix2Xd& patchD
)
{
    const auto T = m.space().displacedTriangle(s.element, patchD);
    return {manifoldElement::toCartesian(T, s.p), manifoldElement::toCartesian(T, s.q)};
}

} // End anonymous namespace


couplingInterface::couplingInterface(nmmSolidModel& model)
:
    model_(model)
{
    findUpcoming();
    const auto& segments = model_.elements().segments();
    for (const geometryPatch& p : model_.geometry().patches())
    {
        auto& faces = segments_[p.name];
        faces.resize(p.edges.size() + p.jointFaces.size());
        for (std::size_t i = 0; i < segments.size(); ++i)
        {
            const auto& s = segments[i];
            const long f = s.kind == physicalCover::segmentKind::blockEdge
                ? indexIn(p.edges, s.edge)
                : (indexIn(p.jointFaces, s.face) < 0 ? -1
                   : long(p.edges.size()) + indexIn(p.jointFaces, s.face));
            if (f >= 0) faces[std::size_t(f)].push_back(i);
        }
    }
    if (segments_.count(edgesRegion))
    {
        throw couplingError(std::string("a patch is named '") + edgesRegion
            + "', the name of the region of every block edge: rename the patch");
    }
    auto& edges = segments_[edgesRegion];
    for (std::size_t i = 0; i < segments.size(); ++i)
    {
        if (segments[i].kind == physicalCover::segmentKind::blockEdge) edges.push_back({i});
    }
}


const std::vector<std::vector<std::size_t>>& couplingInterface::facesOf
(
    const std::string& region
) const
{
    const auto it = segments_.find(region);
    if (it != segments_.end()) return it->second;
    std::string msg = "unknown coupling region '" + region + "'";
    const std::string hint = didYouMean(region, regions());
    if (!hint.empty()) msg += "; " + hint;
    std::string valid;
    for (const auto& r : regions()) valid += " " + r;
    throw couplingError(msg + " (regions:" + valid + ")");
}


std::vector<std::string> couplingInterface::regions() const
{
    std::vector<std::string> names;
    for (const geometryPatch& p : model_.geometry().patches()) names.push_back(p.name);
    names.push_back(edgesRegion);
    if (model_.contacts()) names.push_back(fractures);
    return names;
}


bool couplingInterface::isFractures(const std::string& region) const
{
    return region == fractures && model_.contacts();
}


std::vector<couplingInterface::face> couplingInterface::faces(const std::string& region) const
{
    if (isFractures(region))
    {
        const auto& loops = model_.contacts()->boundaries().loops();
        std::vector<face> result;
        for (const contactRecord& r : contacts())
        {
            face f;
            f.midpoint = r.point;
            f.normal = r.normal;
            f.length = r.length;
            f.block = std::size_t(loops[std::size_t(r.edgeLoop)].block);
            f.otherBlock = std::size_t(loops[std::size_t(r.vertexLoop)].block);
            result.push_back(f);
        }
        return result;
    }
    const auto& segments = model_.elements().segments();
    const Eigen::Matrix2Xd patchD = model_.space().patchDisplacements(model_.latestState().D);
    std::vector<face> result;
    for (const auto& pieces : facesOf(region))
    {
        face f;
        Eigen::Vector2d normal = Eigen::Vector2d::Zero();
        for (const std::size_t i : pieces)
        {
            const auto& s = segments[i];
            const auto [a, b] = segmentEnds(model_, s, patchD);
            const double l = (b - a).norm();
            f.midpoint += 0.5*l*(a + b);
            // Material on the left from p to q: the outward normal is on the right
            normal += Eigen::Vector2d(b.y() - a.y(), a.x() - b.x());
            f.length += l;
            f.block = model_.elements().elements()[s.element].block;
        }
        f.otherBlock = f.block;
        if (f.length > 0) f.midpoint /= f.length;
        if (normal.norm() > 0) f.normal = normal.normalized();
        result.push_back(f);
    }
    return result;
}


void couplingInterface::checkValues(const std::string& region, const std::vector<double>& v) const
{
    const std::size_t n = isFractures(region) ? contacts().size() : facesOf(region).size();
    if (v.size() != n)
    {
        throw couplingError("region '" + region + "' has " + std::to_string(n)
            + " faces; " + std::to_string(v.size()) + " values were given");
    }
    for (std::size_t i = 0; i < v.size(); ++i)
    {
        if (!std::isfinite(v[i]))
        {
            throw couplingError("region '" + region + "': the value of face "
                + std::to_string(i) + " is not finite");
        }
    }
}


void couplingInterface::setPressure(const std::string& region, const std::vector<double>& p)
{
    if (region == poresRegion)
    {
        setPorePressure(p);
        return;
    }
    checkValues(region, p);
    if (isFractures(region))
    {
        setContactPressure(located(contacts()), p);
        return;
    }
    pressure_[region] = p;
    applySegmentPressure();
}


void couplingInterface::setTraction(const std::string& region,
    const std::vector<Eigen::Vector2d>& t)
{
    if (isFractures(region) || region == poresRegion)
    {
        throw couplingError("region '" + region + "' takes a pressure, not a traction");
    }
    const std::size_t n = facesOf(region).size();
    if (t.size() != n)
    {
        throw couplingError("region '" + region + "' has " + std::to_string(n)
            + " faces; " + std::to_string(t.size()) + " tractions were given");
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        if (!t[i].allFinite())
        {
            throw couplingError("region '" + region + "': the traction of face "
                + std::to_string(i) + " is not finite");
        }
    }
    traction_[region] = t;
    applySegmentPressure();
}


void couplingInterface::applySegmentPressure()
{
    const std::size_t n = model_.elements().segments().size();
    std::vector<double> perSegment(n, 0.0);
    const auto add = [&](const std::vector<std::vector<std::size_t>>& faces,
        const std::vector<double>& values)
    {
        for (std::size_t f = 0; f < faces.size(); ++f)
        {
            for (const std::size_t i : faces[f]) perSegment[i] += values[f];
        }
    };
    for (const auto& [name, values] : pressure_) add(segments_.at(name), values);
    add(poreWalls_, porePressure_);
    model_.setCouplingPressure(std::move(perSegment));
    if (traction_.empty()) return;
    std::vector<Eigen::Vector2d> tractions(n, Eigen::Vector2d::Zero());
    for (const auto& [name, values] : traction_)
    {
        const auto& faces = segments_.at(name);
        for (std::size_t f = 0; f < faces.size(); ++f)
        {
            for (const std::size_t i : faces[f]) tractions[i] += values[f];
        }
    }
    model_.setCouplingTraction(std::move(tractions));
}


void couplingInterface::setPorePressure(const std::vector<double>& p)
{
    // The walls where the step starts, where the pressure acts from
    const poreSpace space = poresAt(model_.state());
    if (p.size() != space.pores.size())
    {
        throw couplingError("region 'pores' has " + std::to_string(space.pores.size())
            + " pores; " + std::to_string(p.size()) + " values were given");
    }
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (!std::isfinite(p[i]))
        {
            throw couplingError("region 'pores': the value of pore " + std::to_string(i)
                + " is not finite");
        }
    }
    poreWalls_.assign(p.size(), {});
    const auto& segments = model_.elements().segments();
    const Eigen::Matrix2Xd patchD = model_.space().patchDisplacements(model_.state().D);
    for (std::size_t i = 0; i < segments.size(); ++i)
    {
        if (segments[i].kind != physicalCover::segmentKind::blockEdge) continue;
        const auto [a, b] = segmentEnds(model_, segments[i], patchD);
        // Material on the left from a to b: just to the right is what the
        // wall faces (a pore, another block, or the outside)
        const Eigen::Vector2d outward(b.y() - a.y(), a.x() - b.x());
        const Eigen::Vector2d probe = 0.5*(a + b) + 1e-6*outward;
        for (std::size_t k = 0; k < space.pores.size(); ++k)
        {
            if (space.pores[k].contains(probe)) poreWalls_[k].push_back(i);
        }
    }
    porePressure_ = p;
    applySegmentPressure();
}


std::vector<std::string> couplingInterface::blocks() const
{
    std::vector<std::string> names;
    for (const auto& b : model_.geometry().blocks()) names.push_back(b.name());
    return names;
}


void couplingInterface::setTemperature(const std::vector<double>& perBlock)
{
    const std::size_t n = model_.geometry().blocks().size();
    if (perBlock.size() != n)
    {
        throw couplingError("temperature: the model has " + std::to_string(n)
            + " blocks; " + std::to_string(perBlock.size()) + " values were given");
    }
    for (std::size_t b = 0; b < n; ++b)
    {
        if (!(std::isfinite(perBlock[b]) && perBlock[b] > 0))
        {
            throw couplingError("temperature of block '" + blocks()[b]
                + "' must be finite and positive [K], got " + std::to_string(perBlock[b]));
        }
    }
    try
    {
        model_.setTemperature(perBlock);
    }
    catch (const fatalError& e)
    {
        throw couplingError(e.what());
    }
}


std::vector<double> couplingInterface::referenceTemperatures() const
{
    try
    {
        return model_.referenceTemperatures();
    }
    catch (const fatalError& e)
    {
        throw couplingError(e.what());
    }
}


std::vector<Eigen::Vector2d> couplingInterface::displacement(const std::string& region) const
{
    if (isFractures(region))
    {
        throw couplingError("region 'fractures' has no displacement: its fields are"
            " normalJump, aperture, slip and contactTraction");
    }
    const auto& segments = model_.elements().segments();
    const Eigen::Matrix2Xd patchD = model_.space().patchDisplacements(model_.latestState().D);
    const Eigen::Matrix2Xd none = Eigen::Matrix2Xd::Zero(2, patchD.cols());
    std::vector<Eigen::Vector2d> result;
    for (const auto& pieces : facesOf(region))
    {
        Eigen::Vector2d integral = Eigen::Vector2d::Zero();
        double length = 0;
        for (const std::size_t i : pieces)
        {
            const auto [a0, b0] = segmentEnds(model_, segments[i], none);
            const auto [a, b] = segmentEnds(model_, segments[i], patchD);
            // Linear along the piece: the mean is the value at its middle
            const double l0 = (b0 - a0).norm();
            integral += 0.5*l0*((a - a0) + (b - b0));
            length += l0;
        }
        result.push_back(length > 0 ? Eigen::Vector2d(integral/length) : integral);
    }
    return result;
}


std::vector<Eigen::Vector4d> couplingInterface::blockStress() const
{
    const std::size_t n = model_.geometry().blocks().size();
    std::vector<Eigen::Vector4d> integral(n, Eigen::Vector4d::Zero());
    std::vector<double> area(n, 0.0);
    const auto& sigma = model_.latestState().sigma;
    const auto& elements = model_.elements().elements();
    for (std::size_t e = 0; e < elements.size(); ++e)
    {
        // The stress is constant over an element (linear displacement)
        const auto b = std::size_t(elements[e].block);
        integral[b] += elements[e].moments.area*sigma[e];
        area[b] += elements[e].moments.area;
    }
    for (std::size_t b = 0; b < n; ++b)
    {
        if (area[b] > 0) integral[b] /= area[b];
    }
    return integral;
}


poreSpace couplingInterface::pores() const
{
    return poresAt(model_.latestState());
}


poreSpace couplingInterface::poresAt(const solidState& s) const
{
    // Reading a region's fields asks again for the same state's pores
    if (poreCacheD_.size() == s.D.size() && poreCacheD_ == s.D) return poreCache_;
    poreCache_ = outlinePores(s);
    poreCacheD_ = s.D;
    return poreCache_;
}


poreSpace couplingInterface::outlinePores(const solidState& s) const
{
    if (!outlines_) outlines_ = std::make_unique<blockOutlines>(model_);
    const auto blocks = outlines_->at(s.D);
    try
    {
        return poreSpace::of(blocks);
    }
    catch (const std::invalid_argument& e)
    {
        throw couplingError(std::string("pores: ") + e.what());
    }
}


void couplingInterface::findUpcoming()
{
    const solidState& s = model_.state();
    if (s.timeIndex == upcomingIndex_ && s.D.size() == upcomingD_.size() && s.D == upcomingD_)
    {
        return;
    }
    upcoming_ = model_.upcomingContacts();
    upcomingIndex_ = s.timeIndex;
    upcomingD_ = s.D;
}


void couplingInterface::acceptStep()
{
    model_.acceptStep();
    const std::vector<contactRecord> before = upcoming_;
    findUpcoming();
    bool changed = model_.lastStep().bondsBroken > 0 || before.size() != upcoming_.size();
    for (std::size_t i = 0; i < before.size() && !changed; ++i)
    {
        changed = before[i].key() != upcoming_[i].key();
    }
    if (!changed) return;
    ++revision_;
    if (!pressured_.empty())
    {
        const std::vector<locatedContact> now = located(upcoming_);
        setContactPressure(now, carriedPressure(pressured_, contactPressure_, now));
    }
}


std::vector<locatedContact> couplingInterface::located(const std::vector<contactRecord>& records) const
{
    const auto& loops = model_.contacts()->boundaries().loops();
    std::vector<locatedContact> result;
    for (const contactRecord& r : records)
    {
        locatedContact c;
        c.key = r.key();
        c.point = r.point;
        c.bodies = {loops[std::size_t(r.edgeLoop)].block, loops[std::size_t(r.vertexLoop)].block};
        result.push_back(c);
    }
    return result;
}


void couplingInterface::setContactPressure
(
    const std::vector<locatedContact>& contacts,
    const std::vector<double>& p
)
{
    std::map<std::tuple<int, int, int, int>, double> byContact;
    for (std::size_t i = 0; i < p.size(); ++i) byContact[contacts[i].key] = p[i];
    model_.setContactPressure(std::move(byContact));
    pressured_ = contacts;
    contactPressure_ = p;
}


void couplingInterface::restoreState(const solidState& s)
{
    model_.restoreState(s);
    findUpcoming();
}


std::vector<const contactRecord*> couplingInterface::latestContacts() const
{
    std::vector<const contactRecord*> result;
    // Before a solve, the search's records
    if (&model_.latestState() == &model_.state())
    {
        for (const auto& r : contacts()) result.push_back(&r);
        return result;
    }
    const auto& latest = model_.latestState().contacts;
    std::map<std::tuple<int, int, int, int>, const contactRecord*> byKey;
    for (const auto& r : latest) byKey[r.key()] = &r;
    for (const auto& r : contacts())
    {
        const auto it = byKey.find(r.key());
        result.push_back(it != byKey.end() ? it->second : &r);
    }
    return result;
}


std::vector<double> couplingInterface::normalJump() const
{
    std::vector<double> v;
    for (const auto* r : latestContacts()) v.push_back(r->gap);
    return v;
}


std::vector<double> couplingInterface::aperture(double residual) const
{
    if (!(residual >= 0) || !std::isfinite(residual))
    {
        throw couplingError("aperture: the residual aperture must be finite and not"
            " negative, got " + std::to_string(residual));
    }
    std::vector<double> v;
    for (const auto* r : latestContacts()) v.push_back(std::max(r->gap, residual));
    return v;
}


std::vector<double> couplingInterface::slip() const
{
    std::vector<double> v;
    for (const auto* r : latestContacts()) v.push_back(r->slip);
    return v;
}


std::vector<Eigen::Vector2d> couplingInterface::contactTraction() const
{
    const double thickness = model_.properties().thickness();
    std::vector<Eigen::Vector2d> v;
    for (const auto* r : latestContacts())
    {
        const double area = r->length*thickness;
        v.push_back(area > 0 ? Eigen::Vector2d(r->normalForce/area, r->shearForce/area)
                             : Eigen::Vector2d::Zero());
    }
    return v;
}


double couplingInterface::maxDeltaT() const
{
    if (!model_.scheme().dynamic() || !model_.controls())
    {
        return std::numeric_limits<double>::infinity();
    }
    return model_.controls()->stepControl().maxDeltaT;
}


stepDriver::outcome couplingInterface::advanceTo(double tEnd, std::ostream* log)
{
    stepDriver driver
    (
        *this,
        model_.stepControl(),
        tEnd - time(),
        model_.dynamic()
    );
    if (log) driver.setLog(*log, true);
    return driver.advanceTo(tEnd);
}


void couplingInterface::setDeltaT(double dt)
{
    if (!(dt > 0) || !std::isfinite(dt))
    {
        throw couplingError("setDeltaT: the step must be positive and finite, got "
            + std::to_string(dt));
    }
    deltaT_ = dt;
}

} // End namespace nmm
