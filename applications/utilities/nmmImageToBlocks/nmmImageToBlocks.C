/*---------------------------------------------------------------------------*\
Application
    nmmImageToBlocks

Description
    Blocks from a segmented image of grains, read from
    system/nmmImageToBlocksDict, written to constant/geometry/<output>
    with a preview constant/geometry/<output>.png. system/nmmMeshDict
    includes the list (an #include is relative to the including file's
    folder, hence <constant>):

        blocks ( #include "<constant>/geometry/grains" );

    The image is a label image (one integer per grain, 0 = pore), or a
    binary image (grains light on dark); PNG (grey, 1 to 16 bits, or
    palette indices) or TIFF (one unsigned integer sample, 1 to 32
    bits). An image of more than maxPixels pixels is refused from its
    header, before it is decoded. Pixel (row, col)
    spans x = col*pixelSize to (col + 1)*pixelSize and, row 0 being the
    top of the picture, y = (nRows - row - 1)*pixelSize to
    (nRows - row)*pixelSize: the picture stands upright in the solver.

    Grains that touch in the image become blocks that share their
    boundary exactly, vertex for vertex, so that the solver finds them
    touching and can bond them:
      1. grains are the 4-connected pieces of one label, or of the light
         pixels (nmm::grainRegions says why 4 and not 8); grains touching
         the border and grains below minGrainArea may be dropped, i.e.
         made pore, first;
      2. the boundaries between all grains and the pore are traced along
         pixel edges as one planar graph and cut at the junctions into
         chains, each shared by exactly two regions; a corner where a
         grain would touch itself is opened by a quarter pixel
         (nmm::traceBoundaries). This is written here because contour
         tracers such as OpenCV's findContours follow pixel centres, one
         region at a time: two touching grains get two different
         outlines, a pixel apart;
      3. all chains are simplified together, each once, with CGAL's
         topology-preserving polyline simplification
         (nmm::simplifyChains), so that no two chains cross and
         junctions stay; every traced pixel corner stays within
         simplifyTolerance of the result, whose vertices lie on the
         traced boundary (pixel corners, and from sqrt(2)/4 pixel on
         midpoints of pixel edges, which let a diagonal staircase
         become straight);
      4. each grain's loops are linked from its chains: the outer loop
         and its holes (nmm::assembleLoops). A grain whose simplified
         loops are not a valid block (checked by the mesh reader) keeps
         its chains as traced and the rest are simplified again around
         them; the log names it.
    With simplifyTolerance 0 only straight runs of pixel edges are
    merged: the blocks are the staircases of the pixels, and their areas
    are the pixel counts times pixelSize^2, except that an opened corner
    moves 1/16 pixel^2 from the grain that touched itself there to the
    regions beside it.

    The log gives the image's size, the grains and pieces, those dropped
    and why, the vertices before and after simplification, the area of
    the grains (traced and written) and the porosity 1 - (grain area)/
    (image area).

Usage
    nmmImageToBlocks [-case <dir>] [-help]
\*---------------------------------------------------------------------------*/
// SPDX-License-Identifier: GPL-3.0-or-later

#include "chainSimplifier.H"
#include "grainLoops.H"
#include "grainRegions.H"
#include "labelImage.H"
#include "pixelBoundaries.H"

#include "nmmGeometryTools/blockList/blockList.H"
#include "nmmGeometryTools/geometryCase/geometryCase.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/io/countAndNames/countAndNames.H"
#include "nmmSolid/io/dictionary/dictionary.H"
#include "nmmSolid/io/dictionary/keywordTable.H"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_set>

namespace fs = std::filesystem;

namespace
{

const nmm::keywordTable& keywords()
{
    static const nmm::keywordTable table = []
    {
        nmm::keywordTable t("nmmImageToBlocksDict", "blocks from a segmented image of grains");
        t.fileName("image", "the image, relative to the case folder: PNG (grey, "
            "1-16 bit, or palette indices) or TIFF (one unsigned integer sample, "
            "1-32 bit)").required();
        t.word("type", "label: one integer per grain, 0 = pore; binary: grains "
            "are the 4-connected regions of light pixels (above half the range)")
            .required().choices({"label", "binary"});
        t.scalar("pixelSize", "side of a (square) pixel", "m").required().above(0);
        t.scalar("simplifyTolerance", "largest distance of the traced pixel boundary "
            "from the simplified one (0: only straight runs merged; 1-2 pixels "
            "smooth the staircase)", "m")
            .required().atLeast(0);
        t.scalar("minGrainArea", "grains of a smaller pixel area are dropped (made pore)",
            "m^2").defaultValue(0).atLeast(0);
        t.boolean("dropBorderGrains", "drop (make pore) the grains that touch the "
            "image's border").defaultValue("no");
        t.word("material", "material of every block").required();
        t.fileName("output", "name of the block list under constant/geometry")
            .defaultValue("grains");
        t.integer("maxPixels", "larger images are refused from their header, before "
            "decoding (about 28 bytes of memory a pixel: the default, 10,000 x "
            "10,000, takes about 2.6 GB)")
            .defaultValue("100000000").range(1, 2147483647);
        return t;
    }();
    return table;
}


struct settings
{
    fs::path image;
    bool binary = false;
    double pixelSize = 0;
    double tolerance = 0;
    double minGrainArea = 0;
    bool dropBorderGrains = false;
    std::string material;
    fs::path output;
    std::uint64_t maxPixels = 0;
};

settings readSettings(const nmm::dictionary& dict, const fs::path& casePath)
{
    const nmm::keywordTable& k = keywords();
    settings s;
    s.image = casePath / k.getFileName(dict, "image");
    s.binary = k.get<std::string>(dict, "type") == "binary";
    s.pixelSize = k.get<double>(dict, "pixelSize");
    s.tolerance = k.get<double>(dict, "simplifyTolerance");
    s.minGrainArea = k.get<double>(dict, "minGrainArea");
    s.dropBorderGrains = k.get<bool>(dict, "dropBorderGrains");
    s.material = k.get<std::string>(dict, "material");
    s.output = k.getFileName(dict, "output");
    s.maxPixels = std::uint64_t(k.get<long long>(dict, "maxPixels"));
    return s;
}


template<class T>
void row(const std::string& name, const T& value)
{
    std::cout << "    " << std::left << std::setw(30) << (name + ":") << std::right
        << value << "\n";
}

nmm::labelImage readImage(const settings& s, const nmm::dictionary& dict)
{
    const std::string what = "cannot read the image \"" + s.image.string() + "\": ";
    try
    {
        return nmm::readLabelImage(s.image, !s.binary, s.maxPixels);
    }
    catch (const nmm::imageTooLarge& e)
    {
        const char* key = dict.findEntry("maxPixels") ? "maxPixels" : "image";
        throw dict.lookupEntry(key).error(what + e.what());
    }
    catch (const std::runtime_error& e)
    {
        throw dict.lookupEntry("image").error(what + e.what());
    }
}


void reportGrains(const nmm::grainRegions& regions, const settings& s, const nmm::dictionary& dict)
{
    const std::size_t n = regions.grains().size();
    if (n == 0)
    {
        throw dict.lookupEntry("image").error("the image \"" + s.image.string()
            + "\" has no grains: "
            + (s.binary ? "no pixel is light (above half the range)"
                        : "every pixel is 0 (pore)"));
    }
    std::cout << "\nGrains\n";
    if (s.binary)
    {
        row("grains", std::to_string(n) + " (4-connected regions of light pixels)");
        return;
    }
    const auto split = regions.splitLabels();
    std::set<std::uint32_t> labels;
    for (const auto& g : regions.grains()) labels.insert(g.label);
    row("labels", labels.size());
    row("grains", std::to_string(n) + " (4-connected pieces of one label)");
    for (const auto& [label, names] : split)
    {
        row("label " + std::to_string(label) + " in pieces", nmm::countAndNames(names));
    }
}


//- Make pore the grains the filters drop; at least one must stay
void dropGrains(nmm::grainRegions& regions, const settings& s, const nmm::dictionary& dict)
{
    const double pixelArea = s.pixelSize*s.pixelSize;
    std::vector<bool> drop(regions.grains().size(), false);
    std::vector<std::string> border, small;
    for (std::size_t k = 0; k < drop.size(); ++k)
    {
        const auto& g = regions.grains()[k];
        if (s.dropBorderGrains && g.touchesBorder) border.push_back(g.name);
        else if (double(g.nPixels)*pixelArea < s.minGrainArea) small.push_back(g.name);
        else continue;
        drop[k] = true;
    }
    if (s.dropBorderGrains) row("dropped at the border", nmm::countAndNames(border));
    if (s.minGrainArea > 0) row("dropped below minGrainArea", nmm::countAndNames(small));
    if (border.size() + small.size() == drop.size())
    {
        std::ostringstream os;
        os << "every grain of the image is dropped: " << border.size()
           << " touch the image's border (dropBorderGrains) and " << small.size()
           << " are smaller than minGrainArea " << s.minGrainArea << " m^2";
        throw dict.lookupEntry(border.size() >= small.size() ? "dropBorderGrains"
            : "minGrainArea").error(os.str());
    }
    regions.drop(drop);
    row("kept", drop.size() - border.size() - small.size());
}


nmm::pointLoop toMetres(const std::vector<nmm::gridPoint>& loop, double pixelSize)
{
    nmm::pointLoop p;
    p.reserve(loop.size());
    for (const auto& q : loop)
    {
        p.emplace_back
        (
            double(q.x)/nmm::gridPerPixel*pixelSize,
            double(q.y)/nmm::gridPerPixel*pixelSize
        );
    }
    return p;
}


//- Whether the mesh reader accepts the shape as a block on its own
bool validBlock(const nmm::blockList::shape& s)
{
    nmm::blockList one;
    one.add(s);
    try
    {
        one.check();
        return true;
    }
    catch (const nmm::IOerror&)
    {
        return false;
    }
}


struct outlines
{
    std::vector<nmm::blockList::shape> shapes;
    std::size_t nVertices = 0;               // distinct, as written
    std::vector<std::string> keptAsTraced;
};

//- Kept grains by label, pieces in image order
std::vector<std::size_t> blockOrder(const nmm::grainRegions& regions)
{
    std::vector<std::size_t> order;
    for (std::size_t g = 0; g < regions.grains().size(); ++g)
    {
        if (!regions.grains()[g].dropped) order.push_back(g);
    }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b)
    {
        return regions.grains()[a].label < regions.grains()[b].label;
    });
    return order;
}

std::size_t distinctPoints(const std::vector<std::vector<nmm::gridPoint>>& chains)
{
    std::unordered_set<std::uint64_t> seen;
    for (const auto& c : chains)
    {
        for (const auto& p : c)
        {
            seen.insert(std::uint64_t(std::uint32_t(p.x)) << 32 | std::uint32_t(p.y));
        }
    }
    return seen.size();
}

//- Simplify, link each grain's loops, and fall back to the traced
//  chains of the grains whose simplified loops are not a valid block
outlines makeOutlines
(
    const nmm::grainRegions& regions,
    const nmm::boundaryGraph& graph,
    const settings& s
)
{
    const auto sides = nmm::chainsOfGrains(graph.chains, regions.grains().size());
    const std::vector<std::size_t> order = blockOrder(regions);
    std::vector<bool> keep(graph.chains.size(), false);
    outlines result;
    for (;;)
    {
        const auto points = nmm::simplifyChains(graph.chains, s.tolerance/s.pixelSize, keep);
        result.shapes.clear();
        std::vector<std::size_t> failed;
        for (const std::size_t g : order)
        {
            const auto loops = nmm::assembleLoops(sides[g + 1], graph.chains, points);
            nmm::blockList::shape shape{regions.grains()[g].name, s.material, {}, {}};
            if (loops)
            {
                shape.outer = toMetres(loops->outer, s.pixelSize);
                for (const auto& h : loops->holes) shape.holes.push_back(toMetres(h, s.pixelSize));
            }
            if (loops && validBlock(shape)) result.shapes.push_back(std::move(shape));
            else failed.push_back(g);
        }
        if (failed.empty())
        {
            result.nVertices = distinctPoints(points);
            return result;
        }
        bool more = false;
        for (const std::size_t g : failed)
        {
            result.keptAsTraced.push_back(regions.grains()[g].name);
            for (const auto& side : sides[g + 1])
            {
                more = more || !keep[side.chain];
                keep[side.chain] = true;
            }
        }
        if (!more)
        {
            throw std::logic_error("grain " + regions.grains()[failed.front()].name
                + " is not a valid block even as traced");
        }
    }
}


void reportBoundaries(const nmm::boundaryGraph& graph, const outlines& o, const settings& s)
{
    std::size_t shared = 0;
    for (const auto& c : graph.chains) shared += c.left != 0 && c.right != 0;
    std::ostringstream tol;
    tol << o.nVertices << " (simplifyTolerance " << s.tolerance << " m = "
        << s.tolerance/s.pixelSize << " pixel)";
    std::cout << "\nBoundaries\n";
    row("chains", std::to_string(graph.chains.size()) + " (" + std::to_string(shared)
        + " between two grains)");
    row("corners opened", graph.nOpenedCorners);
    row("vertices traced", graph.nVertices);
    row("vertices simplified", tol.str());
    if (!o.keptAsTraced.empty())
    {
        row("kept as traced", nmm::countAndNames(o.keptAsTraced)
            + ": simplified, not a valid block");
    }
}


void reportAreas
(
    const nmm::grainRegions& regions,
    const nmm::blockList& blocks,
    const settings& s
)
{
    const double pixelArea = s.pixelSize*s.pixelSize;
    const double imageArea = double(regions.nRows())*double(regions.nCols())*pixelArea;
    double traced = 0;
    for (const auto& g : regions.grains())
    {
        if (!g.dropped) traced += double(g.nPixels)*pixelArea;
    }
    const double written = blocks.materialArea();
    std::cout << "\nAreas\n";
    row("image [m^2]", imageArea);
    row("grains, pixels [m^2]", traced);
    row("grains, blocks [m^2]", written);
    row("porosity, pixels", 1 - traced/imageArea);
    row("porosity, blocks", 1 - written/imageArea);
}


int run(int argc, char* argv[])
{
    nmm::argList args("nmmImageToBlocks",
        "Write the grains of a segmented image as blocks, from system/nmmImageToBlocksDict");
    args.addKeywordHelp("system/nmmImageToBlocksDict", keywords());
    args.setDocumentation
    (
        "Reads a label or binary image (PNG or TIFF), traces the boundaries "
        "between grains along pixel edges so that touching grains share them "
        "exactly, simplifies them with CGAL (topology kept), and writes "
        "constant/geometry/<output> for nmmMeshDict's 'blocks' and a preview "
        "PNG. Exit code 1 when the input is wrong."
    );
    if (args.parse(argc, argv) == nmm::argList::parseResult::done) return 0;
    args.printBanner(std::cout);

    const fs::path casePath = args.casePath();
    const nmm::dictionary dict = nmm::readUtilityDict(casePath, "nmmImageToBlocksDict");
    keywords().validate(dict);
    const settings s = readSettings(dict, casePath);

    const nmm::labelImage image = readImage(s, dict);
    std::cout << "Image\n";
    row("file", s.image.lexically_relative(casePath).string());
    row("format", image.format);
    std::ostringstream size;
    size << image.nCols << " x " << image.nRows << " pixels, " << image.nCols*s.pixelSize
        << " x " << image.nRows*s.pixelSize << " m";
    row("size", size.str());

    nmm::grainRegions regions(image, s.binary);
    reportGrains(regions, s, dict);
    dropGrains(regions, s, dict);

    const nmm::boundaryGraph graph = nmm::traceBoundaries(regions);
    const outlines o = makeOutlines(regions, graph, s);
    reportBoundaries(graph, o, s);

    nmm::blockList blocks;
    std::size_t nWritten = 0;
    for (const auto& shape : o.shapes)
    {
        nWritten += shape.outer.size();
        for (const auto& h : shape.holes) nWritten += h.size();
        blocks.add(shape);
    }
    reportAreas(regions, blocks, s);

    const auto w = nmm::writeGeometry(casePath, s.output, blocks,
        "Written by nmmImageToBlocks from system/nmmImageToBlocksDict and "
        + s.image.filename().string() + ": edit those, not this");
    std::cout << "\nWriting\n"
        << "    " << w.file.lexically_relative(casePath).string() << " (" << blocks.size()
        << " blocks, " << nWritten << " vertices)\n"
        << "    " << w.preview.lexically_relative(casePath).string() << "\n\nEnd\n";
    return 0;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    return nmm::catchFatalErrors([&] { return run(argc, argv); });
}
