#include "nmmSolid/output/vtk/vtkPolygonMesh/vtkPolygonMesh.H"

#include "nmmSolid/global/fatalError/fatalError.H"

namespace nmm
{

std::int64_t vtkPolygonMesh::addPoint(const Eigen::Vector3d& x)
{
    points_.push_back(x);
    return static_cast<std::int64_t>(points_.size()) - 1;
}


std::int64_t vtkPolygonMesh::addPoint(const Eigen::Vector2d& x)
{
    return addPoint(Eigen::Vector3d(x.x(), x.y(), 0));
}


std::int64_t vtkPolygonMesh::addCell(const std::vector<std::int64_t>& polygon)
{
    const std::string which = "VTK polygon " + std::to_string(nCells());
    if (polygon.size() < 3)
    {
        throw fatalError
        (
            which + " has " + std::to_string(polygon.size())
          + " vertices; a polygon needs at least 3"
        );
    }
    for (const std::int64_t i : polygon)
    {
        if (i < 0)
        {
            throw fatalError(which + " has the negative point index "
                + std::to_string(i));
        }
    }
    connectivity_.insert(connectivity_.end(), polygon.begin(), polygon.end());
    offsets_.push_back(static_cast<std::int64_t>(connectivity_.size()));
    return static_cast<std::int64_t>(offsets_.size()) - 1;
}


void vtkPolygonMesh::reserveCells(std::size_t nCells, std::size_t nCellPoints)
{
    offsets_.reserve(nCells);
    connectivity_.reserve(nCellPoints);
}


std::vector<std::int64_t> vtkPolygonMesh::cell(std::size_t i) const
{
    const std::int64_t start = i == 0 ? 0 : offsets_.at(i - 1);
    return std::vector<std::int64_t>
    (
        connectivity_.begin() + start,
        connectivity_.begin() + offsets_.at(i)
    );
}


void vtkPolygonMesh::check(const std::string& where) const
{
    const auto n = static_cast<std::int64_t>(points_.size());
    std::size_t celli = 0;
    for (std::size_t k = 0; k < connectivity_.size(); ++k)
    {
        while (static_cast<std::int64_t>(k) >= offsets_[celli]) ++celli;
        if (connectivity_[k] >= n)
        {
            throw fatalError
            (
                where + ": polygon " + std::to_string(celli)
              + " refers to point " + std::to_string(connectivity_[k])
              + " of " + std::to_string(n)
            );
        }
    }
    pointData_.checkSize(points_.size(), where + ", point data", "points");
    cellData_.checkSize(nCells(), where + ", cell data", "cells");
}

} // End namespace nmm
