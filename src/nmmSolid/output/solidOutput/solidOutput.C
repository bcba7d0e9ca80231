#include "nmmSolid/output/solidOutput/solidOutput.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/hdf5File/hdf5File.H"
#include "nmmSolid/output/vtk/vtkFieldNames/vtkFieldNames.H"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace nmm
{

namespace
{

using label = physicalCover::label;

//- Elements below which a point's recovery patch takes one ring more
constexpr std::size_t minimumPatchElements = 6;

//- Weights below this do not tie a point to a patch
constexpr double weightTolerance = 1e-12;


//- Identity of a point: block, reference position in units of a small
//  fraction of the model size, and the patches the field is made of
using pointKey = std::tuple<label, long long, long long, std::vector<label>>;


struct frameBuilder
{
    const nmmSolidModel& model;
    Eigen::Matrix2Xd patchD, patchV;
    double quantum;
    std::map<pointKey, std::int64_t> pointIds;
    std::vector<Eigen::Vector2d> pointD, pointU;
    std::vector<vtkSymmTensor> pointSigma;
    //- A point lies in one block: its element's
    std::vector<std::int32_t> pointBlock;
    std::vector<int> pointCount;
    //- Reference position and the patches of each point
    std::vector<Eigen::Vector2d> pointX;
    std::vector<std::vector<label>> pointPatches;
    vtkPolygonMesh mesh;

    explicit frameBuilder(const nmmSolidModel& m)
    :
        model(m),
        patchD(m.patchDisplacements()),
        patchV(m.patchVelocities()),
        quantum(1e-10*std::max(m.geometry().modelSize(), 1e-300))
    {}

    std::int64_t point
    (
        const physicalCover::element& e,
        const manifoldElement::triangleNodes& T0,
        const manifoldElement::baryPoint& lambda,
        const vtkSymmTensor& sigma
    )
    {
        const Eigen::Vector2d X = manifoldElement::toCartesian(T0, lambda);
        Eigen::Vector2d d = Eigen::Vector2d::Zero(), u = Eigen::Vector2d::Zero();
        std::vector<label> patches;
        for (int k = 0; k < 3; ++k)
        {
            d += lambda[k]*patchD.col(e.patches[k]);
            u += lambda[k]*patchV.col(e.patches[k]);
            if (std::abs(lambda[k]) > weightTolerance) patches.push_back(e.patches[k]);
        }
        std::sort(patches.begin(), patches.end());
        const pointKey key
        {
            e.block, std::llround(X.x()/quantum), std::llround(X.y()/quantum), patches
        };
        auto [it, added] = pointIds.try_emplace(key, std::int64_t(pointD.size()));
        if (added)
        {
            mesh.addPoint(Eigen::Vector2d(X + d));
            pointD.push_back(d);
            pointU.push_back(u);
            pointBlock.push_back(std::int32_t(e.block));
            pointSigma.push_back(vtkSymmTensor::Zero());
            pointCount.push_back(0);
            pointX.push_back(X);
            pointPatches.push_back(patches);
        }
        pointSigma[it->second] += sigma;
        ++pointCount[it->second];
        return it->second;
    }
};


vtkSymmTensor paraviewOrder(const Eigen::Vector4d& s)
{
    vtkSymmTensor t;
    t << s[0], s[1], s[3], s[2], 0, 0;
    return t;
}


//- Back to the model's order (xx yy xy zz)
Eigen::Vector4d modelOrder(const vtkSymmTensor& t)
{
    return Eigen::Vector4d(t[0], t[1], t[3], t[2]);
}


double vonMises(const Eigen::Vector4d& s)
{
    const double xx = s[0], yy = s[1], xy = s[2], zz = s[3];
    return std::sqrt
    (
        0.5*((xx - yy)*(xx - yy) + (yy - zz)*(yy - zz) + (zz - xx)*(zz - xx))
      + 3*xy*xy
    );
}


//- Principal stresses, largest first
Eigen::Vector3d principal(const Eigen::Vector4d& s)
{
    Eigen::Matrix2d S;
    S << s[0], s[2], s[2], s[1];
    const Eigen::Vector2d inPlane = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(S).eigenvalues();
    Eigen::Vector3d p(inPlane[0], inPlane[1], s[3]);
    std::sort(p.data(), p.data() + 3, std::greater<double>());
    return p;
}


void addCellData(vtkPolygonMesh& mesh, const nmmSolidModel& model,
                 const Eigen::Matrix2Xd& patchD, const Eigen::Matrix2Xd& patchV)
{
    const auto& els = model.elements().elements();
    std::vector<Eigen::Vector2d> D, U;
    std::vector<vtkSymmTensor> sigma;
    std::vector<double> eq, sMax, sMid, sMin;
    std::vector<std::int32_t> blockId, materialId;
    for (std::size_t e = 0; e < els.size(); ++e)
    {
        const auto& el = els[e];
        Eigen::Vector2d d = Eigen::Vector2d::Zero(), u = Eigen::Vector2d::Zero();
        for (int k = 0; k < 3; ++k)
        {
            const double w = el.moments.area > 0 ? el.moments.w[k]/el.moments.area : 1.0/3;
            d += w*patchD.col(el.patches[k]);
            u += w*patchV.col(el.patches[k]);
        }
        D.push_back(d);
        U.push_back(u);
        const Eigen::Vector4d& s = model.state().sigma[e];
        sigma.push_back(paraviewOrder(s));
        eq.push_back(vonMises(s));
        const Eigen::Vector3d p = principal(s);
        sMax.push_back(p[0]);
        sMid.push_back(p[1]);
        sMin.push_back(p[2]);
        blockId.push_back(el.block);
        materialId.push_back(std::int32_t(model.materialOfBlock(el.block)));
    }
    namespace f = vtkFieldNames;
    mesh.addCellData(vtkDataArray::vector(f::displacement, D));
    mesh.addCellData(vtkDataArray::vector(f::velocity, U));
    mesh.addCellData(vtkDataArray::symmTensor(f::stress, sigma));
    mesh.addCellData(vtkDataArray::scalar(f::equivalentStress, eq));
    mesh.addCellData(vtkDataArray::scalar(f::principalStressMax, sMax));
    mesh.addCellData(vtkDataArray::scalar(f::principalStressMid, sMid));
    mesh.addCellData(vtkDataArray::scalar(f::principalStressMin, sMin));
    mesh.addCellData(vtkDataArray::int32(f::blockId, blockId));
    mesh.addCellData(vtkDataArray::int32(f::materialId, materialId));
}


//- sigmaEq and the principal stresses of the recovered point stresses
void addInvariants(vtkPolygonMesh& mesh, const std::vector<vtkSymmTensor>& sigma)
{
    std::vector<double> eq, sMax, sMid, sMin;
    for (const vtkSymmTensor& t : sigma)
    {
        const Eigen::Vector4d s = modelOrder(t);
        eq.push_back(vonMises(s));
        const Eigen::Vector3d p = principal(s);
        sMax.push_back(p[0]);
        sMid.push_back(p[1]);
        sMin.push_back(p[2]);
    }
    namespace f = vtkFieldNames;
    mesh.addPointData(vtkDataArray::scalar(f::equivalentStress, eq));
    mesh.addPointData(vtkDataArray::scalar(f::principalStressMax, sMax));
    mesh.addPointData(vtkDataArray::scalar(f::principalStressMid, sMid));
    mesh.addPointData(vtkDataArray::scalar(f::principalStressMin, sMin));
}


//- Element centroids in the reference configuration
std::vector<Eigen::Vector2d> referenceCentroids(const nmmSolidModel& model)
{
    const auto& els = model.elements().elements();
    std::vector<Eigen::Vector2d> c(els.size());
    for (std::size_t e = 0; e < els.size(); ++e)
    {
        const auto T0 = model.space().referenceTriangle(label(e));
        c[e] = manifoldElement::centroid(T0, els[e].moments);
    }
    return c;
}


//- Point stresses recovered from the constant element stresses around a
//  point (Zienkiewicz-Zhu's idea): a linear field fitted by least squares,
//  weighted by element area, to the stresses at the centroids of the
//  elements of the point's patches, and evaluated at the point. On a
//  boundary the fit extrapolates, where a plain average is only first
//  order. Points whose elements do not span a plane keep the average.
void recoverStresses(const nmmSolidModel& model, frameBuilder& b)
{
    const auto& els = model.elements().elements();
    std::vector<std::vector<label>> elementsOf(model.elements().nPatches());
    for (std::size_t e = 0; e < els.size(); ++e)
    {
        for (const label p : els[e].patches) elementsOf[p].push_back(label(e));
    }
    const auto centroid = referenceCentroids(model);

    std::vector<label> around;
    for (std::size_t p = 0; p < b.pointX.size(); ++p)
    {
        around.clear();
        for (const label q : b.pointPatches[p])
        {
            around.insert(around.end(), elementsOf[q].begin(), elementsOf[q].end());
        }
        std::sort(around.begin(), around.end());
        around.erase(std::unique(around.begin(), around.end()), around.end());
        // A corner of the material sees few elements: one ring more
        if (around.size() < minimumPatchElements)
        {
            const std::vector<label> first = around;
            for (const label e : first)
            {
                for (const label q : els[e].patches)
                {
                    around.insert(around.end(), elementsOf[q].begin(), elementsOf[q].end());
                }
            }
            std::sort(around.begin(), around.end());
            around.erase(std::unique(around.begin(), around.end()), around.end());
        }

        Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
        Eigen::Matrix<double, 3, 6> rhs = Eigen::Matrix<double, 3, 6>::Zero();
        double scale = 0;
        for (const label e : around)
        {
            const Eigen::Vector2d d = centroid[e] - b.pointX[p];
            scale = std::max(scale, d.norm());
        }
        if (around.size() < 3 || scale == 0) continue;
        for (const label e : around)
        {
            const double w = els[e].moments.area;
            const Eigen::Vector3d row(1, (centroid[e] - b.pointX[p]).x()/scale,
                                         (centroid[e] - b.pointX[p]).y()/scale);
            A += w*row*row.transpose();
            rhs += w*row*paraviewOrder(model.state().sigma[e]).transpose();
        }
        // A patch whose centroids (nearly) lie on a line cannot fix a plane
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(A);
        if (eig.eigenvalues()[0] < 1e-6*eig.eigenvalues()[2]) continue;
        b.pointSigma[p] = (A.ldlt().solve(rhs)).row(0).transpose();
    }
}

} // End anonymous namespace


vtkPolygonMesh solidOutput::frame(const nmmSolidModel& model)
{
    frameBuilder b(model);
    const auto& els = model.elements().elements();
    for (std::size_t e = 0; e < els.size(); ++e)
    {
        const auto T0 = model.space().referenceTriangle(label(e));
        const vtkSymmTensor s = paraviewOrder(model.state().sigma[e]);
        std::vector<std::int64_t> ids;
        for (const auto& lambda : els[e].loops[0])
        {
            ids.push_back(b.point(els[e], T0, lambda, s));
        }
        b.mesh.addCell(ids);
    }
    addCellData(b.mesh, model, b.patchD, b.patchV);

    for (std::size_t p = 0; p < b.pointSigma.size(); ++p)
    {
        b.pointSigma[p] /= b.pointCount[p];
    }
    recoverStresses(model, b);
    namespace f = vtkFieldNames;
    b.mesh.addPointData(vtkDataArray::vector(f::displacement, b.pointD));
    b.mesh.addPointData(vtkDataArray::vector(f::velocity, b.pointU));
    b.mesh.addPointData(vtkDataArray::symmTensor(f::stress, b.pointSigma));
    addInvariants(b.mesh, b.pointSigma);
    std::vector<std::int32_t> pointMaterial;
    pointMaterial.reserve(b.pointBlock.size());
    for (const std::int32_t block : b.pointBlock)
    {
        pointMaterial.push_back(std::int32_t(model.materialOfBlock(block)));
    }
    b.mesh.addPointData(vtkDataArray::int32(f::blockId, b.pointBlock));
    b.mesh.addPointData(vtkDataArray::int32(f::materialId, pointMaterial));
    return std::move(b.mesh);
}


const char* solidOutput::stateFileName()
{
    return "nmmState.h5";
}


namespace
{

constexpr std::size_t contactIdColumns = 6;
constexpr std::size_t contactValueColumns = 10;

//- The bond of a contact in its id row: 0 none, 1 intact, 2 broken
//  (states written before broken bonds were kept have 0 and 1 only)
std::int32_t bondNumber(const contactRecord& r)
{
    return r.bondIntact ? 1 : r.bondBroken ? 2 : 0;
}


void writeContacts(hdf5File& out, const std::vector<contactRecord>& contacts)
{
    out.writeAttribute("/", "nContacts", std::int64_t(contacts.size()));
    if (contacts.empty()) return;
    hdf5File::array2D<std::int32_t> ids{contacts.size(), contactIdColumns, {}};
    hdf5File::array2D<double> values{contacts.size(), contactValueColumns, {}};
    for (const auto& r : contacts)
    {
        ids.values.insert(ids.values.end(),
        {
            r.vertexLoop, r.vertex, r.edgeLoop, r.edge,
            contactStateNumber(r.state), bondNumber(r)
        });
        values.values.insert(values.values.end(),
        {
            r.shearForce, r.slip, r.normalForce, r.gap, r.t, r.length,
            r.point.x(), r.point.y(), r.normal.x(), r.normal.y()
        });
    }
    out.write("contacts/ids", ids);
    out.write("contacts/values", values);
    std::vector<double> hidden, multiplier;
    for (const auto& r : contacts)
    {
        hidden.push_back(r.hiddenOverlap);
        multiplier.push_back(r.multiplier);
    }
    out.write("contacts/hiddenOverlap", hidden);
    out.write("contacts/multiplier", multiplier);
}


//- A column of the contacts added after the first states were written:
//  zeros where it is absent
std::vector<double> optionalContactColumn
(
    const hdf5File& in,
    const std::filesystem::path& file,
    const std::string& name,
    std::size_t rows
)
{
    if (!in.exists(name)) return std::vector<double>(rows, 0.0);
    std::vector<double> column = in.read<double>(name);
    if (column.size() != rows)
    {
        throw fatalError(file.string() + ": " + name + " has "
            + std::to_string(column.size()) + " rows for "
            + std::to_string(rows) + " contacts");
    }
    return column;
}


std::vector<contactRecord> readContacts
(
    const hdf5File& in,
    const std::filesystem::path& file,
    const nmmSolidModel& model
)
{
    std::vector<contactRecord> result;
    if (!in.exists("contacts/ids")) return result;
    const auto ids = in.read2D<std::int32_t>("contacts/ids", contactIdColumns);
    const auto values = in.read2D<double>("contacts/values", contactValueColumns);
    const std::size_t nLoops =
        model.contacts() ? model.contacts()->boundaries().loops().size() : 0;
    const auto hidden = optionalContactColumn(in, file, "contacts/hiddenOverlap", ids.rows);
    const auto multiplier = optionalContactColumn(in, file, "contacts/multiplier", ids.rows);
    for (std::size_t i = 0; i < ids.rows; ++i)
    {
        contactRecord r;
        r.vertexLoop = ids(i, 0);
        r.vertex = ids(i, 1);
        r.edgeLoop = ids(i, 2);
        r.edge = ids(i, 3);
        if (ids.rows != values.rows || std::size_t(std::max(r.vertexLoop, r.edgeLoop)) >= nLoops
         || ids(i, 4) < 0 || ids(i, 4) > 2 || ids(i, 5) < 0 || ids(i, 5) > 2)
        {
            throw fatalError(file.string() + ": contact " + std::to_string(i)
                + " does not belong to this model's contact boundaries");
        }
        r.state = static_cast<contactState>(ids(i, 4));
        r.bondIntact = ids(i, 5) == 1;
        r.bondBroken = ids(i, 5) == 2;
        r.shearForce = values(i, 0);
        r.slip = values(i, 1);
        r.normalForce = values(i, 2);
        r.gap = values(i, 3);
        r.t = values(i, 4);
        r.length = values(i, 5);
        r.point = {values(i, 6), values(i, 7)};
        r.normal = {values(i, 8), values(i, 9)};
        r.hiddenOverlap = hidden[i];
        r.multiplier = multiplier[i];
        result.push_back(r);
    }
    return result;
}


//- A dataset that holds one number
double readOne
(
    const hdf5File& in,
    const std::filesystem::path& file,
    const std::string& name
)
{
    const auto v = in.read<double>(name);
    if (v.size() != 1)
    {
        throw fatalError(file.string() + ": " + name + " has "
            + std::to_string(v.size()) + " values, not one");
    }
    return v[0];
}


//- The contact solver's carried values (states written before they were
//  kept have none: the solver starts from its defaults)
std::map<std::string, double> readContactSolver
(
    const hdf5File& in,
    const std::filesystem::path& file
)
{
    std::map<std::string, double> values;
    if (!in.exists("contactSolver")) return values;
    for (const std::string& name : in.members("contactSolver"))
    {
        values[name] = readOne(in, file, "contactSolver/" + name);
    }
    return values;
}

} // End anonymous namespace


void solidOutput::writeState
(
    const std::filesystem::path& timeDir,
    const nmmSolidModel& model,
    const stepHistory* steps
)
{
    const solidState& s = model.state();
    hdf5File out = hdf5File::create(timeDir/stateFileName());
    out.writeAttribute("/", "formatVersion", std::int64_t(1));
    out.writeAttribute("/", "time", s.time);
    out.writeAttribute("/", "timeIndex", std::int64_t(s.timeIndex));
    out.write("D", std::vector<double>(s.D.data(), s.D.data() + s.D.size()));
    out.write("V", std::vector<double>(s.V.data(), s.V.data() + s.V.size()));
    out.write("A", std::vector<double>(s.A.data(), s.A.data() + s.A.size()));
    hdf5File::array2D<double> sigma{s.sigma.size(), 4, {}};
    for (const auto& v : s.sigma) sigma.values.insert(sigma.values.end(), v.data(), v.data() + 4);
    out.write("sigma", sigma);
    writeContacts(out, s.contacts);
    for (const auto& [name, value] : s.contactSolver)
    {
        out.write("contactSolver/" + name, std::vector<double>{value});
    }
    // Set by a coupled thermal solver only
    if (!s.temperature.empty()) out.write("temperature", s.temperature);
    if (steps)
    {
        out.write("stepControl/lastDeltaT", std::vector<double>{steps->last});
        out.write("stepControl/lastMotionUse", std::vector<double>{steps->motionUse});
        out.write("stepControl/lastCut", std::vector<double>{double(steps->cut)});
        out.write("stepControl/ceiling", std::vector<double>{steps->ceiling});
    }
    out.commit();
}


std::optional<stepHistory> solidOutput::readStepHistory(const std::filesystem::path& timeDir)
{
    const auto file = timeDir/stateFileName();
    const hdf5File in = hdf5File::openRead(file);
    if (!in.exists("stepControl")) return std::nullopt;
    const auto one = [&](const char* name)
    {
        return readOne(in, file, std::string("stepControl/") + name);
    };
    // States written before the ceiling was kept have none; those written
    // before the motion's use was kept have the displacement ratio, which
    // the history no longer holds: the next step is then held only by
    // growth (and cut if it moves too far)
    const double ceiling = in.exists("stepControl/ceiling") ? one("ceiling") : 0.0;
    const double motionUse =
        in.exists("stepControl/lastMotionUse") ? one("lastMotionUse") : 0.0;
    return stepHistory{one("lastDeltaT"), motionUse, one("lastCut") != 0, ceiling};
}


solidState solidOutput::readState
(
    const std::filesystem::path& timeDir,
    const nmmSolidModel& model
)
{
    const auto file = timeDir/stateFileName();
    if (!std::filesystem::exists(file))
    {
        throw fatalError("cannot restart: no state file " + file.string());
    }
    const hdf5File in = hdf5File::openRead(file);
    solidState s;
    s.time = in.readDoubleAttribute("/", "time");
    s.timeIndex = in.readIntAttribute("/", "timeIndex");
    const auto vec = [&](const char* name)
    {
        const auto v = in.read<double>(name);
        if (v.size() != model.elements().nUnknowns())
        {
            throw fatalError(file.string() + ": '" + name + "' has "
                + std::to_string(v.size()) + " values but the mesh has "
                + std::to_string(model.elements().nUnknowns())
                + " unknowns; was nmmMeshDict changed after this time was written?");
        }
        return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(v.data(), Eigen::Index(v.size())));
    };
    s.D = vec("D");
    s.V = vec("V");
    s.A = vec("A");
    const auto sigma = in.read2D<double>("sigma", 4);
    if (sigma.rows != model.elements().nElements())
    {
        throw fatalError(file.string() + ": stresses of " + std::to_string(sigma.rows)
            + " elements but the mesh has " + std::to_string(model.elements().nElements()));
    }
    for (std::size_t e = 0; e < sigma.rows; ++e)
    {
        s.sigma.emplace_back(sigma(e, 0), sigma(e, 1), sigma(e, 2), sigma(e, 3));
    }
    s.contacts = readContacts(in, file, model);
    s.contactSolver = readContactSolver(in, file);
    if (in.exists("temperature"))
    {
        s.temperature = in.read<double>("temperature");
        if (s.temperature.size() != model.geometry().blocks().size())
        {
            throw fatalError(file.string() + ": temperatures of "
                + std::to_string(s.temperature.size()) + " blocks but the mesh has "
                + std::to_string(model.geometry().blocks().size()));
        }
    }
    return s;
}


vtkPointSet solidOutput::contactFrame(const nmmSolidModel& model)
{
    vtkPointSet set;
    const contactModel* cm = model.contacts();
    if (!cm) return set;
    const auto patchD = model.patchDisplacements();
    const auto& loops = cm->boundaries().loops();
    std::vector<std::int32_t> state, bond, broken, blockA, blockB;
    std::vector<double> fn, fs, penetration, slip, length;
    std::vector<Eigen::Vector2d> normal, traction;
    for (const contactRecord& r : model.state().contacts)
    {
        set.addPoint(contactBoundaries::position
        (
            model.cover(), model.elements(), loops[r.vertexLoop].vertices[r.vertex], patchD
        ));
        state.push_back(contactStateNumber(r.state));
        bond.push_back(r.bondIntact);
        broken.push_back(r.bondBroken);
        blockA.push_back(loops[r.vertexLoop].block);
        blockB.push_back(loops[r.edgeLoop].block);
        fn.push_back(r.normalForce);
        fs.push_back(r.shearForce);
        penetration.push_back(-r.gap);
        slip.push_back(r.slip);
        length.push_back(r.length);
        normal.push_back(r.normal);
        const Eigen::Vector2d s(-r.normal.y(), r.normal.x());
        traction.push_back(r.normalForce*r.normal + r.shearForce*s);
    }
    namespace f = vtkFieldNames;
    set.addPointData(vtkDataArray::int32(f::contactState, std::move(state)));
    set.addPointData(vtkDataArray::int32(f::bondIntact, std::move(bond)));
    set.addPointData(vtkDataArray::int32(f::bondBroken, std::move(broken)));
    set.addPointData(vtkDataArray::scalar(f::normalForce, std::move(fn)));
    set.addPointData(vtkDataArray::scalar(f::shearForce, std::move(fs)));
    set.addPointData(vtkDataArray::scalar(f::penetration, std::move(penetration)));
    set.addPointData(vtkDataArray::scalar(f::slip, std::move(slip)));
    set.addPointData(vtkDataArray::scalar(f::contactLength, std::move(length)));
    set.addPointData(vtkDataArray::vector(f::contactNormal, normal));
    set.addPointData(vtkDataArray::vector(f::contactForce, traction));
    set.addPointData(vtkDataArray::int32(f::blockA, std::move(blockA)));
    set.addPointData(vtkDataArray::int32(f::blockB, std::move(blockB)));
    return set;
}

} // End namespace nmm
