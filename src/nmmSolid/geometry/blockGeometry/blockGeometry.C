#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"

#include "nmmSolid/geometry/geometryCheck/geometryCheck.H"
#include "nmmSolid/geometry/patchSelectors/patchSelector/patchSelector.H"
#include "nmmSolid/io/dictionary/token.H"

#include <algorithm>
#include <array>
#include <ostream>

namespace nmm
{

namespace
{

using xyList = std::vector<std::array<double, 2>>;

pointLoop toPoints(const xyList& xy)
{
    pointLoop pts;
    pts.reserve(xy.size());
    for (const auto& p : xy) pts.emplace_back(p[0], p[1]);
    return pts;
}


//- Run read(); an error from the dictionary layer (a missing or unknown
//  keyword, a malformed list) gets the prefix that names the item
template<class Read>
auto naming(const std::string& prefix, Read&& read) -> decltype(read())
{
    try
    {
        return read();
    }
    catch (const IOerror& err)
    {
        if (err.message().compare(0, prefix.size(), prefix) == 0) throw;
        throw IOerror(prefix + err.message(), err.where(), err.keyword());
    }
}


std::size_t indexOf
(
    const std::unordered_map<std::string, std::size_t>& index,
    const std::string& name
)
{
    const auto it = index.find(name);
    return it == index.end() ? blockGeometry::npos : it->second;
}


//- One item of the 'blocks' list, read and checked on its own
block readBlock(const entry& item)
{
    const dictionary& dict = item.dict();
    blockGeometry::blockKeywords().validate(dict);
    const geometryCheck::subject who{"Block", item.keyword(), item.where()};

    pointLoop outer = toPoints(dict.get<xyList>("polygon"));
    geometryCheck::checkLoop(outer, "polygon", who);

    std::vector<pointLoop> holes;
    if (dict.found("holes"))
    {
        for (const auto& xy : dict.get<std::vector<xyList>>("holes"))
        {
            holes.push_back(toPoints(xy));
            geometryCheck::checkLoop
            (
                holes.back(), block::loopName(holes.size()), who
            );
        }
    }
    block b
    (
        item.keyword(),
        blockGeometry::blockKeywords().get<std::string>(dict, "material"),
        std::move(outer),
        std::move(holes),
        item.where()
    );
    geometryCheck::checkHoles(b);
    b.setFixed(blockGeometry::blockKeywords().get<bool>(dict, "fixed"));
    return b;
}


//- The items of a list entry ( name { ... } ... ), or of a dictionary
//  entry { name { ... } ... }
std::vector<std::unique_ptr<entry>> namedItems(const entry& e)
{
    if (!e.isDict()) return dictionary::entryList(e);
    std::vector<std::unique_ptr<entry>> items;
    for (const auto& item : e.dict().entries())
    {
        if (!item->isDict())
        {
            throw item->error("expected '" + item->keyword() + " { ... }' in '"
                + e.keyword() + "'");
        }
        items.push_back(item->clone(nullptr));
    }
    return items;
}

} // End anonymous namespace


const keywordTable& blockGeometry::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("nmmMeshDict", "geometry (blocks, joints, patches) and "
            "mathematical cover");
        t.list("blocks", "bodies of material: ( name { material ..; polygon "
            "(..); holes (..); } ... )").required();
        t.list("joints", "cracks inside blocks: ( name { points (..); } ... )");
        t.any("patches", "named sets of boundary edges: { name { type ..; } ... }");
        t.subDict("cover", "the mathematical cover (read by the mesh)");
        t.scalar("snapTolerance", "vertices closer than this to another block's "
            "vertex or edge are moved onto it before the overlap check, so that "
            "rounded coordinates touch instead of overlapping; relative to the "
            "model size (the diagonal of the blocks' box); 0 snaps nothing")
            .range(0, 1e-3).defaultValue(defaultSnapTolerance);
        return t;
    }();
    return table;
}


const keywordTable& blockGeometry::blockKeywords()
{
    static const keywordTable table = []
    {
        keywordTable t("block", "a polygon of material, with optional holes");
        t.word("material", "name of the block's material in "
            "constant/mechanicalProperties")
            .required();
        t.list("polygon", "outer loop ((x y) ...), either way round; a closing "
            "vertex equal to the first is dropped").required();
        t.list("holes", "loops strictly inside the polygon: ( ((x y) ...) ... )");
        t.boolean("fixed", "the block neither moves nor deforms (a container's "
            "walls, a floor): it has no unknowns, and a contact with it acts on "
            "the other body only").defaultValue("no");
        return t;
    }();
    return table;
}


const keywordTable& blockGeometry::jointKeywords()
{
    static const keywordTable table = []
    {
        keywordTable t("joint", "a crack: an open polyline inside one block");
        t.list("points", "the polyline ((x y) ...); an end inside the block is a "
            "crack tip, an end on its boundary a crack mouth").required();
        return t;
    }();
    return table;
}


void blockGeometry::printHelp(std::ostream& os)
{
    keywords().printHelp(os);
    os << "\n";
    blockKeywords().printHelp(os);
    os << "\n";
    jointKeywords().printHelp(os);
    os << "\n";
    patchSelector::printHelp(os);
}


blockGeometry blockGeometry::read(const dictionary& nmmMeshDict)
{
    keywords().validate(nmmMeshDict);
    blockGeometry g;
    g.readBlocks(nmmMeshDict);
    g.readJoints(nmmMeshDict);
    g.readPatches(nmmMeshDict);
    return g;
}


void blockGeometry::readBlocks(const dictionary& dict)
{
    const entry& list = dict.lookupEntry("blocks");
    const auto items = namedItems(list);
    if (items.empty())
    {
        throw list.error("no blocks: the list needs at least one block");
    }
    blocks_.reserve(items.size());
    for (const auto& item : items)
    {
        // Missing keywords are reported with the dictionary's name
        item->dict().setName("blocks/" + item->keyword());
        blocks_.push_back
        (
            naming("Block '" + item->keyword() + "': ", [&] { return readBlock(*item); })
        );
        bounds_.extend(blocks_.back().bounds());
        blockIndex_.emplace(blocks_.back().name(), blocks_.size() - 1);
    }
    snapBlocks(keywords().get<double>(dict, "snapTolerance"));
    geometryCheck::checkOverlaps(blocks_, snapDistance_);
}


void blockGeometry::snapBlocks(double snapTolerance)
{
    snapDistance_ = snapTolerance*modelSize();
    snapMoves_ = vertexSnap::snap(blocks_, snapDistance_);
    if (snapMoves_.empty()) return;

    std::vector<bool> changed(blocks_.size(), false);
    for (const auto& m : snapMoves_)
    {
        changed[m.block] = true;
        if (m.added) changed[m.ontoBlock] = true;
    }
    const std::string note = " (after snapping the vertices within snapTolerance "
        + formatScalar(snapTolerance) + " of the model size, "
        + geometryCheck::measureText(snapDistance_) + " m, of another block onto "
        "it; a smaller snapTolerance, or 0, snaps less)";
    bounds_.setEmpty();
    for (std::size_t b = 0; b < blocks_.size(); ++b)
    {
        if (changed[b]) geometryCheck::recheckSnapped(blocks_[b], note);
        bounds_.extend(blocks_[b].bounds());
    }
}


void blockGeometry::readJoints(const dictionary& dict)
{
    const entry* list = dict.findEntry("joints");
    if (!list) return;
    for (const auto& item : namedItems(*list))
    {
        if (findBlock(item->keyword()) != npos)
        {
            throw item->error("Joint '" + item->keyword() + "' has the name of "
                "a block; names of blocks and joints must differ");
        }
        item->dict().setName("joints/" + item->keyword());
        const auto points = naming("Joint '" + item->keyword() + "': ", [&]
        {
            jointKeywords().validate(item->dict());
            return toPoints(item->dict().get<xyList>("points"));
        });
        joints_.emplace_back(item->keyword(), points, item->where());
        jointIndex_.emplace(item->keyword(), joints_.size() - 1);
        geometryCheck::checkPolyline(joints_.back());
    }
    geometryCheck::locateJoints(joints_, blocks_);
}


void blockGeometry::readPatches(const dictionary& dict)
{
    const entry* list = dict.findEntry("patches");
    if (!list) return;
    for (const auto& item : namedItems(*list))
    {
        geometryPatch p;
        p.name = item->keyword();
        p.where = item->where();
        const auto selector = naming("Patch '" + p.name + "': ", [&]
        {
            auto sel = patchSelector::New(*item);
            p.type = item->dict().get<std::string>("type");
            sel->select(*this, p);
            return sel;
        });

        std::sort(p.edges.begin(), p.edges.end());
        p.edges.erase(std::unique(p.edges.begin(), p.edges.end()), p.edges.end());
        std::sort(p.jointFaces.begin(), p.jointFaces.end());
        p.jointFaces.erase
        (
            std::unique(p.jointFaces.begin(), p.jointFaces.end()),
            p.jointFaces.end()
        );
        if (p.empty())
        {
            const std::string hint = selector->emptyHint(*this);
            throw item->error("Patch '" + p.name + "' selects no edge"
                + (hint.empty() ? "" : ": " + hint));
        }
        patches_.push_back(std::move(p));
    }
}


std::size_t blockGeometry::findBlock(const std::string& name) const
{
    return indexOf(blockIndex_, name);
}


std::size_t blockGeometry::findJoint(const std::string& name) const
{
    return indexOf(jointIndex_, name);
}


const geometryPatch* blockGeometry::findPatch(const std::string& name) const
{
    for (const auto& p : patches_)
    {
        if (p.name == name) return &p;
    }
    return nullptr;
}


const geometryPatch& blockGeometry::patch(const std::string& name) const
{
    if (const geometryPatch* p = findPatch(name)) return *p;
    std::vector<std::string> names;
    std::string valid;
    for (const auto& p : patches_)
    {
        names.push_back(p.name);
        valid += " " + p.name;
    }
    const std::string hint = didYouMean(name, names);
    throw IOerror("There is no patch '" + name + "'" + (hint.empty() ? "" : "; " + hint)
        + " (patches:" + (valid.empty() ? " none" : valid) + ")");
}


std::size_t blockGeometry::nVertices() const
{
    std::size_t n = 0;
    for (const auto& b : blocks_) n += b.nEdges();
    return n;
}


std::size_t blockGeometry::nHoles() const
{
    std::size_t n = 0;
    for (const auto& b : blocks_) n += b.nHoles();
    return n;
}


double blockGeometry::area() const
{
    double a = 0;
    for (const auto& b : blocks_) a += b.area();
    return a;
}

} // End namespace nmm
