#include "nmmSolid/output/vtk/vtkDataArray/vtkDataArray.H"

#include "nmmSolid/global/fatalError/fatalError.H"

#include <algorithm>

namespace nmm
{

vtkDataArray::vtkDataArray(std::string name, int nComponents, values v)
:
    name_(std::move(name)),
    nComponents_(nComponents),
    values_(std::move(v))
{
    // An unnamed array cannot be selected in ParaView, nor told apart
    if (name_.empty())
    {
        throw fatalError("VTK data array without a name");
    }
    const std::size_t n = std::visit([](const auto& x) { return x.size(); }, values_);
    if (nComponents_ < 1 || n % static_cast<std::size_t>(nComponents_) != 0)
    {
        throw fatalError
        (
            "VTK data array \"" + name_ + "\": " + std::to_string(n)
          + " values do not make tuples of " + std::to_string(nComponents_)
          + " components"
        );
    }
}


vtkDataArray vtkDataArray::scalar(std::string name, std::vector<double> v)
{
    return vtkDataArray(std::move(name), 1, std::move(v));
}


vtkDataArray vtkDataArray::vector
(
    std::string name,
    const std::vector<Eigen::Vector3d>& v
)
{
    std::vector<double> flat;
    flat.reserve(3*v.size());
    for (const auto& x : v) flat.insert(flat.end(), {x.x(), x.y(), x.z()});
    return vtkDataArray(std::move(name), 3, std::move(flat));
}


vtkDataArray vtkDataArray::vector
(
    std::string name,
    const std::vector<Eigen::Vector2d>& v
)
{
    std::vector<double> flat;
    flat.reserve(3*v.size());
    for (const auto& x : v) flat.insert(flat.end(), {x.x(), x.y(), 0.0});
    return vtkDataArray(std::move(name), 3, std::move(flat));
}


vtkDataArray vtkDataArray::symmTensor
(
    std::string name,
    const std::vector<vtkSymmTensor>& v
)
{
    std::vector<double> flat;
    flat.reserve(6*v.size());
    for (const auto& t : v) flat.insert(flat.end(), t.data(), t.data() + 6);
    vtkDataArray a(std::move(name), 6, std::move(flat));
    a.componentNames_ = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};
    return a;
}


vtkDataArray vtkDataArray::symmTensor
(
    std::string name,
    const std::vector<Eigen::Matrix3d>& v
)
{
    std::vector<vtkSymmTensor> sym;
    sym.reserve(v.size());
    for (const auto& m : v)
    {
        vtkSymmTensor t;
        t << m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(1, 2), m(0, 2);
        sym.push_back(t);
    }
    return symmTensor(std::move(name), sym);
}


vtkDataArray vtkDataArray::int32(std::string name, std::vector<std::int32_t> v)
{
    return vtkDataArray(std::move(name), 1, std::move(v));
}


vtkDataArray vtkDataArray::int32
(
    std::string name,
    int nComponents,
    std::vector<std::int32_t> v
)
{
    return vtkDataArray(std::move(name), nComponents, std::move(v));
}


vtkDataArray vtkDataArray::int64(std::string name, std::vector<std::int64_t> v)
{
    return vtkDataArray(std::move(name), 1, std::move(v));
}


vtkDataArray vtkDataArray::float64
(
    std::string name,
    int nComponents,
    std::vector<double> v
)
{
    return vtkDataArray(std::move(name), nComponents, std::move(v));
}


std::size_t vtkDataArray::nTuples() const
{
    const std::size_t n = std::visit([](const auto& x) { return x.size(); }, values_);
    return n/static_cast<std::size_t>(nComponents_);
}


vtkDataArray::valueType vtkDataArray::type() const
{
    switch (values_.index())
    {
        case 1: return valueType::int32;
        case 2: return valueType::int64;
        default: return valueType::float64;
    }
}


const char* vtkDataArray::typeName(valueType t)
{
    switch (t)
    {
        case valueType::int32: return "Int32";
        case valueType::int64: return "Int64";
        case valueType::float64: break;
    }
    return "Float64";
}


// * * * * * * * * * * * * * * * * vtkArrayList * * * * * * * * * * * * * * //

void vtkArrayList::add(vtkDataArray a)
{
    if (find(a.name()))
    {
        throw fatalError("VTK data array \"" + a.name() + "\" added twice");
    }
    arrays_.push_back(std::move(a));
}


const vtkDataArray* vtkArrayList::find(const std::string& name) const
{
    const auto it = std::find_if(arrays_.begin(), arrays_.end(),
        [&](const vtkDataArray& a) { return a.name() == name; });
    return it == arrays_.end() ? nullptr : &*it;
}


void vtkArrayList::checkSize
(
    std::size_t n,
    const std::string& what,
    const std::string& nWhat
) const
{
    for (const vtkDataArray& a : arrays_)
    {
        if (a.nTuples() != n)
        {
            throw fatalError
            (
                what + ": array \"" + a.name() + "\" has "
              + std::to_string(a.nTuples()) + " tuples for "
              + std::to_string(n) + " " + nWhat
            );
        }
    }
}

} // End namespace nmm
