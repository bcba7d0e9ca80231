#include "nmmSolid/coupling/blockOutlines/blockOutlines.H"

#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

namespace nmm
{

blockOutlines::blockOutlines(const nmmSolidModel& model)
:
    model_(model),
    boundaries_(model.cover(), model.elements(), model.geometry())
{}


std::vector<std::vector<poreSpace::loop>> blockOutlines::at(const Eigen::VectorXd& D) const
{
    const auto& cover = model_.cover();
    const auto& pc = model_.elements();
    const Eigen::Matrix2Xd patchD = model_.space().patchDisplacements(D);
    std::vector<std::vector<poreSpace::loop>> blocks(model_.geometry().blocks().size());
    for (const contactLoop& l : boundaries_.loops())
    {
        if (l.type == contactLoop::kind::jointFace) continue;
        poreSpace::loop points;
        points.reserve(l.vertices.size());
        for (const auto& v : l.vertices)
        {
            points.push_back(contactBoundaries::position(cover, pc, v, patchD));
        }
        auto& loops = blocks[std::size_t(l.block)];
        if (l.type == contactLoop::kind::outer) loops.insert(loops.begin(), std::move(points));
        else loops.push_back(std::move(points));
    }
    return blocks;
}

} // End namespace nmm
