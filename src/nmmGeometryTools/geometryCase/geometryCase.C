#include "nmmGeometryTools/geometryCase/geometryCase.H"

#include "nmmGeometryTools/blockPreview/blockPreview.H"

namespace nmm
{

dictionary readUtilityDict(const std::filesystem::path& casePath, const std::string& dictName)
{
    readOptions ro;
    ro.caseDir = casePath;
    return dictionary::read(casePath/"system"/dictName, ro);
}


writtenGeometry writeGeometry
(
    const std::filesystem::path& casePath,
    const std::filesystem::path& output,
    const blockList& blocks,
    const std::string& comment
)
{
    writtenGeometry w;
    w.file = casePath/"constant"/"geometry"/output;
    w.preview = w.file.string() + ".png";
    blocks.write(w.file, comment);
    writeBlockPreview(w.preview, blocks);
    return w;
}

} // End namespace nmm
