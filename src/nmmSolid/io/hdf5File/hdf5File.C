#include "nmmSolid/io/hdf5File/hdf5File.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/atomicFile/atomicFile.H"

#include <hdf5.h>

#include <algorithm>
#include <system_error>
#include <type_traits>
#include <utility>

namespace fs = std::filesystem;

static_assert(sizeof(hid_t) == sizeof(std::int64_t),
    "hdf5File keeps handles as 64-bit hid_t (HDF5 1.10 or later)");

namespace nmm
{

namespace
{

//- Switch off HDF5's printing of its error stack: errors reach the user
//  as one fatalError instead (the stack is read for its reason)
void silenceHdf5()
{
    static const bool silenced = []
    {
        // Every file is closed by its owner; HDF5's own clean-up at exit
        // would retry a file whose closing failed (a full disk) and crash
        H5dont_atexit();
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
        return true;
    }();
    (void)silenced;
}


//- The innermost description on HDF5's error stack (the most specific
//  one), then the stack cleared
std::string hdf5Reason()
{
    std::string reason;
    H5Ewalk2
    (
        H5E_DEFAULT,
        H5E_WALK_DOWNWARD,
        [](unsigned, const H5E_error2_t* e, void* data) -> herr_t
        {
            if (e && e->desc && *e->desc)
            {
                *static_cast<std::string*>(data) = e->desc;
            }
            return 0;
        },
        &reason
    );
    H5Eclear2(H5E_DEFAULT);
    return reason;
}


//- One HDF5 identifier, closed by the function that matches its kind
class handle
{
    hid_t id_ = H5I_INVALID_HID;
    herr_t (*close_)(hid_t) = nullptr;

public:
    handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
    ~handle() { if (id_ >= 0) close_(id_); }
    handle(const handle&) = delete;
    handle& operator=(const handle&) = delete;

    hid_t get() const { return id_; }
    bool valid() const { return id_ >= 0; }
};


template<class T> hid_t memoryType();
template<> hid_t memoryType<double>() { return H5T_NATIVE_DOUBLE; }
template<> hid_t memoryType<std::int32_t>() { return H5T_NATIVE_INT32; }
template<> hid_t memoryType<std::int64_t>() { return H5T_NATIVE_INT64; }

// Stored little-endian whatever the machine, so files travel
template<class T> hid_t fileType();
template<> hid_t fileType<double>() { return H5T_IEEE_F64LE; }
template<> hid_t fileType<std::int32_t>() { return H5T_STD_I32LE; }
template<> hid_t fileType<std::int64_t>() { return H5T_STD_I64LE; }

template<class T> const char* typeWord();
template<> const char* typeWord<double>() { return "double"; }
template<> const char* typeWord<std::int32_t>() { return "int32"; }
template<> const char* typeWord<std::int64_t>() { return "int64"; }


//- The stored type can be read as T without losing anything
template<class T>
bool readableAs(hid_t storedType)
{
    const H5T_class_t cls = H5Tget_class(storedType);
    const std::size_t size = H5Tget_size(storedType);
    if constexpr (std::is_floating_point_v<T>)
    {
        return cls == H5T_FLOAT && size <= sizeof(T);
    }
    else
    {
        return cls == H5T_INTEGER && size <= sizeof(T)
            && (H5Tget_sign(storedType) == H5T_SGN_2 || size < sizeof(T));
    }
}


std::string quoted(const std::string& s)
{
    return "\"" + s + "\"";
}


std::string attributeWord(const std::string& object, const std::string& name)
{
    return "attribute " + quoted(name) + " of " + quoted(object);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Construction * * * * * * * * * * * * * * * //

hdf5File::hdf5File(fs::path path, bool create)
:
    path_(std::move(path)),
    writable_(create)
{
    silenceHdf5();
    if (create)
    {
        temp_ = atomicFile::tempName(path_);
        file_ = H5Fcreate(temp_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
        if (file_ < 0)
        {
            fail("cannot create the file (writing \"" + temp_.string() + "\")");
        }
    }
    else
    {
        std::error_code ec;
        if (!fs::is_regular_file(path_, ec))
        {
            throw fatalError("cannot find file " + quoted(path_.string()));
        }
        file_ = H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        if (file_ < 0) fail("cannot open the file (not an HDF5 file?)");
    }
}


hdf5File hdf5File::create(const fs::path& path)
{
    return hdf5File(path, true);
}


hdf5File hdf5File::openRead(const fs::path& path)
{
    return hdf5File(path, false);
}


hdf5File::hdf5File(hdf5File&& other) noexcept
:
    path_(std::move(other.path_)),
    temp_(std::move(other.temp_)),
    file_(std::exchange(other.file_, -1)),
    writable_(std::exchange(other.writable_, false))
{
    other.temp_.clear();
}


hdf5File& hdf5File::operator=(hdf5File&& other) noexcept
{
    if (this != &other)
    {
        close();
        path_ = std::move(other.path_);
        temp_ = std::move(other.temp_);
        other.temp_.clear();
        file_ = std::exchange(other.file_, -1);
        writable_ = std::exchange(other.writable_, false);
    }
    return *this;
}


hdf5File::~hdf5File()
{
    close();
}


void hdf5File::close() noexcept
{
    if (file_ >= 0)
    {
        H5Fclose(file_);
        H5Eclear2(H5E_DEFAULT);
        file_ = -1;
    }
    if (!temp_.empty())
    {
        // Not committed: the half-made file must not stay around
        std::error_code ignored;
        fs::remove(temp_, ignored);
        temp_.clear();
    }
}


void hdf5File::commit()
{
    requireWritable("commit");
    const herr_t closed = H5Fclose(file_);
    file_ = -1;
    if (closed < 0) fail("cannot write the file (closing \"" + temp_.string() + "\")");

    std::error_code ec;
    fs::rename(temp_, path_, ec);
    if (ec)
    {
        throw fatalError
        (
            "HDF5 file " + quoted(path_.string()) + ": cannot write the file: "
          + ec.message() + " (renaming \"" + temp_.string() + "\")"
        );
    }
    temp_.clear();
    writable_ = false;
}


// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

void hdf5File::fail(const std::string& what) const
{
    const std::string reason = hdf5Reason();
    throw fatalError
    (
        "HDF5 file " + quoted(path_.string()) + ": " + what
      + (reason.empty() ? std::string() : " (" + reason + ")")
    );
}


void hdf5File::requireWritable(const std::string& what) const
{
    if (file_ < 0)
    {
        throw fatalError("HDF5 file " + quoted(path_.string())
            + ": " + what + ": the file is closed");
    }
    if (!writable_)
    {
        throw fatalError("HDF5 file " + quoted(path_.string())
            + ": " + what + ": the file is open read-only");
    }
}


bool hdf5File::exists(const std::string& name) const
{
    if (file_ < 0) return false;
    // H5Lexists fails rather than answer for a path whose parent is
    // missing, so the path is walked one component at a time
    std::string prefix;
    std::size_t start = 0;
    while (start <= name.size())
    {
        const std::size_t slash = std::min(name.find('/', start), name.size());
        const std::string part = name.substr(start, slash - start);
        start = slash + 1;
        if (part.empty()) continue;
        prefix += "/" + part;
        if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0)
        {
            H5Eclear2(H5E_DEFAULT);
            return false;
        }
    }
    return true;
}


std::vector<std::string> hdf5File::members(const std::string& group) const
{
    const handle g(H5Gopen2(file_, group.c_str(), H5P_DEFAULT), H5Gclose);
    if (!g.valid()) fail("cannot open group " + quoted(group));

    H5G_info_t info;
    if (H5Gget_info(g.get(), &info) < 0) fail("cannot read group " + quoted(group));

    std::vector<std::string> names;
    for (hsize_t i = 0; i < info.nlinks; ++i)
    {
        const ssize_t n = H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME,
            H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
        if (n < 0) fail("cannot read group " + quoted(group));
        std::string s(static_cast<std::size_t>(n) + 1, '\0');
        H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i,
            s.data(), s.size(), H5P_DEFAULT);
        s.resize(static_cast<std::size_t>(n));
        names.push_back(std::move(s));
    }
    return names;
}


// * * * * * * * * * * * * * * * * Writing * * * * * * * * * * * * * * * * //

void hdf5File::createGroup(const std::string& name)
{
    requireWritable("cannot create group " + quoted(name));
    if (exists(name)) return;
    const handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    H5Pset_create_intermediate_group(lcpl.get(), 1);
    const handle g(H5Gcreate2(file_, name.c_str(), lcpl.get(), H5P_DEFAULT,
        H5P_DEFAULT), H5Gclose);
    if (!g.valid()) fail("cannot create group " + quoted(name));
}


template<class T>
void hdf5File::writeData
(
    const std::string& name,
    const std::vector<std::size_t>& dims,
    const T* data
)
{
    const std::string what = "cannot write dataset " + quoted(name);
    requireWritable(what);

    // Replacing a dataset: the old one is unlinked (its space is not
    // reclaimed, which does not matter for files written once)
    if (exists(name) && H5Ldelete(file_, name.c_str(), H5P_DEFAULT) < 0)
    {
        fail(what);
    }

    const std::vector<hsize_t> hdims(dims.begin(), dims.end());
    const handle space(H5Screate_simple(int(hdims.size()), hdims.data(), nullptr),
        H5Sclose);
    const handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    H5Pset_create_intermediate_group(lcpl.get(), 1);
    const handle dset(H5Dcreate2(file_, name.c_str(), fileType<T>(), space.get(),
        lcpl.get(), H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
    if (!space.valid() || !dset.valid()) fail(what);

    std::size_t n = 1;
    for (const std::size_t d : dims) n *= d;
    // An empty dataset has nothing to transfer (and no buffer to give)
    if (n > 0 && H5Dwrite(dset.get(), memoryType<T>(), H5S_ALL, H5S_ALL,
        H5P_DEFAULT, data) < 0)
    {
        fail(what);
    }
}


void hdf5File::write(const std::string& name, const std::vector<double>& v)
{
    writeData(name, {v.size()}, v.data());
}


void hdf5File::write(const std::string& name, const std::vector<std::int32_t>& v)
{
    writeData(name, {v.size()}, v.data());
}


void hdf5File::write(const std::string& name, const std::vector<std::int64_t>& v)
{
    writeData(name, {v.size()}, v.data());
}


namespace
{

template<class T>
void checkShape(const hdf5File& f, const std::string& name, const hdf5File::array2D<T>& a)
{
    if (a.values.size() != a.rows*a.cols)
    {
        throw fatalError("HDF5 file " + quoted(f.path().string())
            + ": cannot write dataset " + quoted(name) + ": "
            + std::to_string(a.values.size()) + " values for "
            + std::to_string(a.rows) + " x " + std::to_string(a.cols));
    }
}

} // End anonymous namespace


void hdf5File::write(const std::string& name, const array2D<double>& a)
{
    checkShape(*this, name, a);
    writeData(name, {a.rows, a.cols}, a.values.data());
}


void hdf5File::write(const std::string& name, const array2D<std::int32_t>& a)
{
    checkShape(*this, name, a);
    writeData(name, {a.rows, a.cols}, a.values.data());
}


namespace
{

//- Create attribute name on object (replacing one of that name), scalar
//  space, and write the value through memType
bool putAttribute
(
    hid_t file,
    const std::string& object,
    const std::string& name,
    hid_t storedType,
    hid_t memType,
    const void* value
)
{
    const htri_t there = H5Aexists_by_name(file, object.c_str(), name.c_str(),
        H5P_DEFAULT);
    if (there < 0) return false;
    if (there > 0
     && H5Adelete_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT) < 0)
    {
        return false;
    }
    const handle space(H5Screate(H5S_SCALAR), H5Sclose);
    const handle attr(H5Acreate_by_name(file, object.c_str(), name.c_str(),
        storedType, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    return attr.valid() && H5Awrite(attr.get(), memType, value) >= 0;
}

} // End anonymous namespace


void hdf5File::writeAttribute
(
    const std::string& object,
    const std::string& name,
    const std::string& value
)
{
    const std::string what = "cannot write " + attributeWord(object, name);
    requireWritable(what);
    // Fixed-length, NUL-padded: readable by h5dump, h5py and ParaView alike
    const handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type.get(), std::max<std::size_t>(value.size(), 1));
    H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
    const std::string padded = value.empty() ? std::string(1, '\0') : value;
    if (!putAttribute(file_, object, name, type.get(), type.get(), padded.data()))
    {
        fail(what);
    }
}


void hdf5File::writeAttribute
(
    const std::string& object,
    const std::string& name,
    double value
)
{
    const std::string what = "cannot write " + attributeWord(object, name);
    requireWritable(what);
    if (!putAttribute(file_, object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value))
    {
        fail(what);
    }
}


void hdf5File::writeAttribute
(
    const std::string& object,
    const std::string& name,
    std::int64_t value
)
{
    const std::string what = "cannot write " + attributeWord(object, name);
    requireWritable(what);
    if (!putAttribute(file_, object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value))
    {
        fail(what);
    }
}


// * * * * * * * * * * * * * * * * Reading * * * * * * * * * * * * * * * * //

template<class T>
std::vector<T> hdf5File::readData
(
    const std::string& name,
    int rank,
    std::vector<std::size_t>& dims
) const
{
    const std::string what = "cannot read dataset " + quoted(name);
    if (file_ < 0) fail(what + ": the file is closed");
    if (!exists(name))
    {
        throw fatalError("HDF5 file " + quoted(path_.string())
            + ": there is no dataset " + quoted(name));
    }
    const handle dset(H5Dopen2(file_, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!dset.valid()) fail(what + " (not a dataset?)");

    const handle type(H5Dget_type(dset.get()), H5Tclose);
    if (!type.valid()) fail(what);
    if (!readableAs<T>(type.get()))
    {
        throw fatalError("HDF5 file " + quoted(path_.string()) + ": dataset "
            + quoted(name) + " does not hold " + typeWord<T>() + " values");
    }

    const handle space(H5Dget_space(dset.get()), H5Sclose);
    const int ndims = space.valid() ? H5Sget_simple_extent_ndims(space.get()) : -1;
    if (ndims < 0) fail(what);
    if (ndims != rank)
    {
        throw fatalError("HDF5 file " + quoted(path_.string()) + ": dataset "
            + quoted(name) + " has " + std::to_string(ndims)
            + " dimensions, expected " + std::to_string(rank));
    }
    std::vector<hsize_t> hdims(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space.get(), hdims.data(), nullptr);
    dims.assign(hdims.begin(), hdims.end());

    std::size_t n = 1;
    for (const std::size_t d : dims) n *= d;
    std::vector<T> values(n);
    if (n > 0 && H5Dread(dset.get(), memoryType<T>(), H5S_ALL, H5S_ALL,
        H5P_DEFAULT, values.data()) < 0)
    {
        fail(what);
    }
    return values;
}


template<class T>
std::vector<T> hdf5File::read(const std::string& name) const
{
    std::vector<std::size_t> dims;
    return readData<T>(name, 1, dims);
}


template<class T>
hdf5File::array2D<T> hdf5File::read2D(const std::string& name) const
{
    std::vector<std::size_t> dims;
    array2D<T> a;
    a.values = readData<T>(name, 2, dims);
    a.rows = dims[0];
    a.cols = dims[1];
    return a;
}


template<class T>
hdf5File::array2D<T> hdf5File::read2D
(
    const std::string& name,
    std::size_t cols
) const
{
    array2D<T> a = read2D<T>(name);
    if (a.cols != cols)
    {
        throw fatalError("HDF5 file " + quoted(path_.string()) + ": dataset "
            + quoted(name) + " has " + std::to_string(a.cols)
            + " columns, expected " + std::to_string(cols));
    }
    return a;
}


template std::vector<double> hdf5File::read<double>(const std::string&) const;
template std::vector<std::int32_t> hdf5File::read<std::int32_t>(const std::string&) const;
template std::vector<std::int64_t> hdf5File::read<std::int64_t>(const std::string&) const;
template hdf5File::array2D<double>
    hdf5File::read2D<double>(const std::string&) const;
template hdf5File::array2D<std::int32_t>
    hdf5File::read2D<std::int32_t>(const std::string&) const;
template hdf5File::array2D<double>
    hdf5File::read2D<double>(const std::string&, std::size_t) const;
template hdf5File::array2D<std::int32_t>
    hdf5File::read2D<std::int32_t>(const std::string&, std::size_t) const;


bool hdf5File::hasAttribute(const std::string& object, const std::string& name) const
{
    if (file_ < 0 || !exists(object)) return false;
    const htri_t there = H5Aexists_by_name(file_, object.c_str(), name.c_str(),
        H5P_DEFAULT);
    H5Eclear2(H5E_DEFAULT);
    return there > 0;
}


namespace
{

//- Open an attribute, or throw the missing-attribute error
handle openAttribute
(
    const hdf5File& f,
    hid_t file,
    const std::string& object,
    const std::string& name
)
{
    if (!f.hasAttribute(object, name))
    {
        throw fatalError("HDF5 file " + quoted(f.path().string())
            + ": there is no " + attributeWord(object, name));
    }
    return handle(H5Aopen_by_name(file, object.c_str(), name.c_str(),
        H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
}

} // End anonymous namespace


void hdf5File::readAttribute
(
    const std::string& object,
    const std::string& name,
    const char* kind,
    bool (*accepts)(std::int64_t type),
    const std::function<bool(std::int64_t attribute, std::int64_t type)>& read
) const
{
    const std::string what = "cannot read " + attributeWord(object, name);
    const handle attr = openAttribute(*this, file_, object, name);
    const handle type(attr.valid() ? H5Aget_type(attr.get()) : -1, H5Tclose);
    if (!type.valid()) fail(what);
    if (!accepts(type.get()))
    {
        throw fatalError("HDF5 file " + quoted(path_.string()) + ": "
            + attributeWord(object, name) + " is not " + kind);
    }
    if (!read(attr.get(), type.get())) fail(what);
}


std::string hdf5File::readStringAttribute
(
    const std::string& object,
    const std::string& name
) const
{
    std::string s;
    const auto isString = [](std::int64_t type) { return H5Tget_class(type) == H5T_STRING; };
    readAttribute(object, name, "a string", isString, [&](std::int64_t attr, std::int64_t type)
    {
        if (H5Tis_variable_str(type) > 0)
        {
            // Written by other tools (h5py writes variable-length strings)
            const handle memType(H5Tcopy(H5T_C_S1), H5Tclose);
            H5Tset_size(memType.get(), H5T_VARIABLE);
            char* text = nullptr;
            if (H5Aread(attr, memType.get(), &text) < 0) return false;
            s = text ? text : "";
            H5free_memory(text);
            return true;
        }
        s.assign(H5Tget_size(type), '\0');
        if (H5Aread(attr, type, s.data()) < 0) return false;
        s.resize(std::min(s.find('\0'), s.size()));
        return true;
    });
    return s;
}


double hdf5File::readDoubleAttribute
(
    const std::string& object,
    const std::string& name
) const
{
    double v = 0;
    const auto isNumber = [](std::int64_t type)
    {
        const H5T_class_t cls = H5Tget_class(type);
        return cls == H5T_FLOAT || cls == H5T_INTEGER;
    };
    readAttribute(object, name, "a number", isNumber, [&](std::int64_t attr, std::int64_t)
    {
        return H5Aread(attr, H5T_NATIVE_DOUBLE, &v) >= 0;
    });
    return v;
}


std::int64_t hdf5File::readIntAttribute
(
    const std::string& object,
    const std::string& name
) const
{
    std::int64_t v = 0;
    const auto isInteger = [](std::int64_t type) { return readableAs<std::int64_t>(type); };
    readAttribute(object, name, "an integer", isInteger, [&](std::int64_t attr, std::int64_t)
    {
        return H5Aread(attr, H5T_NATIVE_INT64, &v) >= 0;
    });
    return v;
}

} // End namespace nmm
