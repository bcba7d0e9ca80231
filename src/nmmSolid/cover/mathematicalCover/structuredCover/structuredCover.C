#include "nmmSolid/cover/mathematicalCover/structuredCover/structuredCover.H"

#include "nmmSolid/cover/physicalCover/physicalCover.H"
#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"

#include <algorithm>
#include <cmath>

namespace nmm
{

addToRunTimeSelectionTable(mathematicalCover, structuredCover, "structured");


const keywordTable& structuredCover::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("structured", "regular right triangles, squares split "
            "with alternating diagonals (union-jack pattern)");
        t.word("type", "cover type").required();
        t.include(physicalCover::keywords());
        t.scalar("cellSize", "square side (triangle leg length)", "m")
            .required().above(0);
        t.scalar("margin", "cover extends at least this far beyond the "
            "blocks (rounded up to whole cells below and left); "
            "default one cellSize", "m").atLeast(0);
        return t;
    }();
    return table;
}


structuredCover::structuredCover
(
    const dictionary& coverDict,
    const blockGeometry& geometry
)
:
    mathematicalCover(keywords().get<double>(coverDict, "cellSize"))
{
    const double h = cellSize();
    const double margin = coverDict.found("margin")
        ? keywords().get<double>(coverDict, "margin") : h;
    // Nodes are counted from the blocks' lowest corner, which is then a
    // node exactly: a node an ulp away from a block vertex or edge would
    // cut slivers of area 1e-30 off the material
    const Eigen::Vector2d anchor = geometry.bounds().min();
    const double cellsBefore = std::ceil(margin/h - 1e-9);
    Eigen::AlignedBox2d box = coverBox(geometry, margin);
    box.min() = anchor - Eigen::Vector2d::Constant(cellsBefore*h);

    // Counted in double before anything is allocated; a quotient that is a
    // whole number but for round-off (1.2/0.1) is not rounded up
    const double nx = std::max(1.0, std::ceil(box.sizes().x()/h - 1e-9));
    const double ny = std::max(1.0, std::ceil(box.sizes().y()/h - 1e-9));
    checkSize(2*nx*ny, coverDict, "cellSize");

    const label ni = label(nx), nj = label(ny);
    // The last row and column reach at least the box, which the rounding
    // above may have missed by a hair
    auto coordinate = [h, cellsBefore](double lo, double hi, label i, label n)
    {
        const double x = lo + (i - cellsBefore)*h;
        return i == n ? std::max(x, hi) : x;
    };
    std::vector<Eigen::Vector2d> nodes;
    nodes.reserve(std::size_t(ni + 1)*(nj + 1));
    for (label j = 0; j <= nj; ++j)
    {
        const double y = coordinate(anchor.y(), box.max().y(), j, nj);
        for (label i = 0; i <= ni; ++i)
        {
            nodes.emplace_back(coordinate(anchor.x(), box.max().x(), i, ni), y);
        }
    }

    auto node = [ni](label i, label j) { return j*(ni + 1) + i; };
    std::vector<triangle> triangles;
    triangles.reserve(std::size_t(2)*ni*nj);
    for (label j = 0; j < nj; ++j)
    {
        for (label i = 0; i < ni; ++i)
        {
            const label a = node(i, j), b = node(i + 1, j);
            const label c = node(i + 1, j + 1), d = node(i, j + 1);
            if ((i + j) % 2 == 0)       // diagonal a-c
            {
                triangles.push_back({a, b, c});
                triangles.push_back({a, c, d});
            }
            else                        // diagonal b-d
            {
                triangles.push_back({a, b, d});
                triangles.push_back({b, c, d});
            }
        }
    }
    set(std::move(nodes), std::move(triangles), geometry, coverDict);
}

} // End namespace nmm
