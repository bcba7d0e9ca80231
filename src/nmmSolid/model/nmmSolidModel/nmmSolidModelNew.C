#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

#include "nmmSolid/boundary/gravity/gravity.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"
#include "nmmSolid/cover/nmmMeshFile/nmmMeshFile.H"

#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <string>

namespace nmm
{

namespace
{

boundaryRule ruleOf(const patchCondition& c, const blockGeometry& geometry)
{
    boundaryRule r;
    r.name = geometry.patches()[c.patch].name;
    switch (c.type)
    {
        case bcType::fixedValue:
            r.type = boundaryRule::kind::fixedValue;
            r.vectorValue = [&c](const Eigen::Vector2d& x, double t)
            {
                return c.displacement(x, t);
            };
            break;
        case bcType::fixedNormal:
            r.type = boundaryRule::kind::fixedNormal;
            r.scalarValue = [&c](const Eigen::Vector2d& x, double t)
            {
                return c.normalDisplacement(x, t);
            };
            break;
        case bcType::tractionDisplacement:
            r.type = boundaryRule::kind::traction;
            r.vectorValue = [&c](const Eigen::Vector2d& x, double t)
            {
                return c.load(x, t, Eigen::Vector2d::Zero());
            };
            r.scalarValue = [&c](const Eigen::Vector2d& x, double t)
            {
                return c.pressure->value(x, t);
            };
            break;
    }
    return r;
}


//- Says so when a condition's patch lies on fixed blocks only: they do
//  not move (nmm::physicalCover), whatever the condition. A warning, not
//  an error, so that a container held by its outer faces can be made a
//  fixed block without editing 0/D
void warnFixedOnly
(
    const boundaryConditions& conditions,
    const blockGeometry& geometry,
    const physicalCover& elements,
    const std::vector<int>& segmentRule
)
{
    const auto& cs = conditions.conditions();
    std::vector<bool> onMoving(cs.size(), false);
    std::vector<std::set<std::string>> fixedBlocks(cs.size());
    for (std::size_t k = 0; k < segmentRule.size(); ++k)
    {
        const int r = segmentRule[k];
        if (r < 0) continue;
        const auto e = elements.segments()[k].element;
        const block& b = geometry.blocks()[std::size_t(elements.elements()[e].block)];
        if (b.fixed()) fixedBlocks[std::size_t(r)].insert("'" + b.name() + "'");
        else onMoving[std::size_t(r)] = true;
    }
    for (std::size_t r = 0; r < cs.size(); ++r)
    {
        if (onMoving[r] || fixedBlocks[r].empty()) continue;
        std::string names;
        for (const auto& n : fixedBlocks[r]) names += (names.empty() ? "" : ", ") + n;
        printWarning
        (
            std::cout,
            cs[r].where.str() + ": the " + bcTypeName(cs[r].type) + " condition of patch '"
            + geometry.patches()[cs[r].patch].name + "' has no effect: the patch lies on"
            " fixed blocks only (" + names + "), which do not move"
        );
    }
}


//- The contact laws when bodies can touch: two blocks or more, or a joint
//  (its faces close); a single block builds no contact machinery
std::unique_ptr<contactProperties> readContacts
(
    const caseFolder& runCase,
    const blockGeometry& geometry,
    const mechanicalProperties& props
)
{
    if (geometry.nBlocks() < 2 && geometry.nJoints() == 0) return nullptr;
    const auto file = runCase.constant()/"contactProperties";
    if (!std::filesystem::is_regular_file(file))
    {
        throw fatalError
        (
            "cannot find file \"" + file.string() + "\": the case has "
            + std::to_string(geometry.nBlocks()) + " blocks and "
            + std::to_string(geometry.nJoints()) + " joints, so bodies can "
            "touch and need a contact law (see nmmSolidFoam -help)"
        );
    }
    return std::make_unique<contactProperties>(contactProperties::read(file, props.names()));
}


//- Every block a cover's patches, elements and segments name is one of
//  nBlocks
bool withinBlocks(const physicalCover& pc, std::size_t nBlocks)
{
    const auto in = [&](auto b) { return b >= 0 && std::size_t(b) < nBlocks; };
    bool ok = true;
    for (const auto& p : pc.patches()) ok = ok && in(p.block);
    for (const auto& e : pc.elements()) ok = ok && in(e.block);
    for (const auto& s : pc.segments())
    {
        ok = ok && (s.kind != physicalCover::segmentKind::blockEdge || in(long(s.edge.block)));
    }
    return ok;
}


//- The physical cover nmmMesh stored in constant/nmmMesh, when it was
//  made from nmmMeshDict as it is now, on the same mathematical cover;
//  else cut here (a case never meshed, or edited since), origin saying
//  which and why. The cut is most of a large pack's start: 4 s of a
//  pack of 3,000 grains
std::unique_ptr<physicalCover> storedOrCut
(
    const caseFolder& runCase,
    const dictionary& meshDict,
    const mathematicalCover& cover,
    const blockGeometry& geometry,
    std::string& origin
)
{
    const auto file = nmmMeshFile::fileName(runCase.path());
    std::string why = nmmMeshFile::whyNotCurrent(file, meshDict);
    if (why.empty())
    {
        nmmMeshFile::contents stored = nmmMeshFile::read(file);
        const bool sameCover =
            stored.nodes == cover.nodes() && stored.triangles == cover.triangles();
        if (sameCover && withinBlocks(*stored.mesh, geometry.nBlocks()))
        {
            origin = "read from constant/nmmMesh/nmmMesh.h5";
            return std::move(stored.mesh);
        }
        why = file.string() + " was made on another mathematical cover or geometry";
    }
    origin = "cut from the blocks: " + why;
    return std::make_unique<physicalCover>(cover, geometry, meshDict.subDict("cover"));
}

} // End anonymous namespace


void nmmSolidModel::parts::setConditions(std::unique_ptr<boundaryConditions> bc)
{
    // One rule per condition; each segment refers to the rule of its patch
    conditions = std::move(bc);
    rules.clear();
    segmentRule.clear();
    std::map<const patchCondition*, int> index;
    for (const auto& c : conditions->conditions())
    {
        index[&c] = int(rules.size());
        rules.push_back(ruleOf(c, *geometry));
    }
    for (const auto& s : elements->segments())
    {
        const patchCondition* c = s.kind == physicalCover::segmentKind::blockEdge
            ? conditions->condition(s.edge)
            : conditions->condition(s.face);
        segmentRule.push_back(c ? index.at(c) : -1);
    }
    warnFixedOnly(*conditions, *geometry, *elements, segmentRule);
}


std::unique_ptr<nmmSolidModel> nmmSolidModel::New
(
    const caseFolder& runCase,
    const std::string& startTimeName
)
{
    parts p;
    const dictionary meshDict = dictionary::read(runCase.system()/"nmmMeshDict");
    p.geometry = std::make_unique<blockGeometry>(blockGeometry::read(meshDict));
    if (!meshDict.findEntry("cover"))
    {
        throw fatalError(runCase.system().string() + "/nmmMeshDict has no 'cover' dictionary");
    }
    const dictionary& coverDict = meshDict.subDict("cover");
    p.cover = mathematicalCover::New(coverDict, *p.geometry);
    p.elements = storedOrCut(runCase, meshDict, *p.cover, *p.geometry, p.meshOrigin);
    p.properties = std::make_unique<mechanicalProperties>(mechanicalProperties::read(runCase));

    p.controls = std::make_unique<solutionControls>
    (
        solutionControls::read(runCase.system()/"nmmSolution")
    );
    p.scheme = p.controls->newTimeScheme();
    p.largeDisplacement = p.controls->largeDisplacement();
    p.solver = linearSolver::New(p.controls->linearSolverDict());

    p.setConditions(std::make_unique<boundaryConditions>
    (
        boundaryConditions::read(runCase.timePath(startTimeName)/"D", *p.geometry)
    ));

    const nmm::gravity g = nmm::gravity::read(runCase.constant()/"g");
    if (g.active()) p.gravity = g.value();

    p.contacts = readContacts(runCase, *p.geometry, *p.properties);
    if (p.contacts) p.contactMethod = p.controls->newContactSolver();

    auto model = std::make_unique<nmmSolidModel>(std::move(p));
    model->setInitialVelocity
    (
        initialVelocity::read(runCase.timePath(startTimeName)/"U")
    );
    return model;
}

} // End namespace nmm
