#include "nmmSolid/functionObjects/blockMotion/blockMotion.H"

#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

#include <cmath>

namespace nmm
{

addToRunTimeSelectionTable(functionObject, blockMotion, "blockMotion");


namespace
{

//- Index of the block named name, or an IOerror with did-you-mean
std::size_t blockIndex
(
    const std::string& foName,
    const std::string& name,
    const blockGeometry& geometry,
    const entry& where
)
{
    const std::size_t b = geometry.findBlock(name);
    if (b != blockGeometry::npos) return b;

    std::vector<std::string> names;
    std::string valid;
    for (const auto& blk : geometry.blocks())
    {
        names.push_back(blk.name());
        valid += " " + blk.name();
    }
    std::string msg = "function object '" + foName + "': unknown block '" + name + "'";
    const std::string hint = didYouMean(name, names);
    if (!hint.empty()) msg += "; " + hint;
    msg += "\n\nBlocks of system/nmmMeshDict:" + valid;
    throw IOerror(msg, where.where(), "blocks");
}


//- Sums over the elements of one block
struct blockSums
{
    double area = 0;                                    // reference
    Eigen::Vector2d position = Eigen::Vector2d::Zero(); // int x
    Eigen::Vector2d velocity = Eigen::Vector2d::Zero(); // int U
    double rotation = 0;                                // int theta
};

} // End anonymous namespace


const keywordTable& blockMotion::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t
        (
            "blockMotion",
            "centre of mass, rotation and velocity of blocks"
        );
        t.include(functionObject::commonKeywords());
        t.list("blocks", "blocks of system/nmmMeshDict, e.g. (grain1 grain2)").required();
        return t;
    }();
    return table;
}


blockMotion::blockMotion
(
    const std::string& name,
    const Time& runTime,
    const nmmSolidModel& model,
    const dictionary& dict
)
:
    functionObject(name, runTime, model, dict, "blockMotion", keywords())
{
    const entry& e = dict.lookupEntry("blocks");
    const auto names = dict.get<std::vector<std::string>>("blocks");
    if (names.empty()) throw e.error("function object '" + name + "': no blocks");
    std::vector<std::string> columns{"time"};
    for (const auto& b : names)
    {
        blocks_.push_back(blockIndex(name, b, model.geometry(), e));
        for (const char* c : {":x", ":y", ":rotation", ":Ux", ":Uy"})
        {
            columns.push_back(b + c);
        }
    }
    writeHeader(columns);
}


void blockMotion::execute()
{
    const auto& pc = model_.elements();
    const Eigen::Matrix2Xd D = model_.patchDisplacements();
    const Eigen::Matrix2Xd U = model_.patchVelocities();

    std::vector<blockSums> sums(model_.geometry().nBlocks());
    for (const auto& e : pc.elements())
    {
        const auto& m = e.moments;
        const auto T0 = physicalCover::triangleOf(model_.cover(), e);
        manifoldElement::triangleNodes T = T0;
        blockSums& s = sums[e.block];
        for (int k = 0; k < 3; ++k)
        {
            const auto p = e.patches[k];
            T.col(k) += D.col(p);
            s.position += m.w[k]*(T0.col(k) + D.col(p));
            s.velocity += m.w[k]*U.col(p);
        }
        Eigen::Matrix2d dX, dx;
        dX << T0.col(1) - T0.col(0), T0.col(2) - T0.col(0);
        dx << T.col(1) - T.col(0), T.col(2) - T.col(0);
        const Eigen::Matrix2d F = dx*dX.inverse();
        s.rotation += m.area*std::atan2(F(1, 0) - F(0, 1), F(0, 0) + F(1, 1));
        s.area += m.area;
    }

    std::vector<double> row{model_.time()};
    for (const std::size_t b : blocks_)
    {
        const blockSums& s = sums[b];
        const Eigen::Vector2d x = s.position/s.area;
        const Eigen::Vector2d u = s.velocity/s.area;
        row.insert(row.end(), {x.x(), x.y(), s.rotation/s.area, u.x(), u.y()});
    }
    writeRow(row);
}

} // End namespace nmm
