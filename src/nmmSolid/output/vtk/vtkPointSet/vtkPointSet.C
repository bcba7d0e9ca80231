#include "nmmSolid/output/vtk/vtkPointSet/vtkPointSet.H"

namespace nmm
{

std::int64_t vtkPointSet::addPoint(const Eigen::Vector3d& x)
{
    points_.push_back(x);
    return static_cast<std::int64_t>(points_.size()) - 1;
}


std::int64_t vtkPointSet::addPoint(const Eigen::Vector2d& x)
{
    return addPoint(Eigen::Vector3d(x.x(), x.y(), 0));
}


void vtkPointSet::check(const std::string& where) const
{
    pointData_.checkSize(points_.size(), where + ", point data", "points");
}

} // End namespace nmm
