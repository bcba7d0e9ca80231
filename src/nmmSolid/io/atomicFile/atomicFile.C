#include "nmmSolid/io/atomicFile/atomicFile.H"

#include "nmmSolid/global/fatalError/fatalError.H"

#include <cerrno>
#include <streambuf>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace nmm
{

namespace
{

constexpr const char* tempSuffix = ".tmp";

//- ": <reason>" for an errno value
std::string reason(int err)
{
    return err == 0 ? std::string() : ": " + std::generic_category().message(err);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * fileBuffer * * * * * * * * * * * * * * * //

class atomicFile::fileBuffer
:
    public std::streambuf
{
    int fd_ = -1;
    int error_ = 0;
    std::vector<char> buffer_ = std::vector<char>(1 << 16);

    bool writeAll(const char* p, std::size_t n)
    {
        while (n > 0 && error_ == 0)
        {
            const ssize_t done = ::write(fd_, p, n);
            if (done < 0)
            {
                if (errno != EINTR) error_ = errno;
                continue;
            }
            p += done;
            n -= static_cast<std::size_t>(done);
        }
        return error_ == 0;
    }

    bool flushBuffer()
    {
        const bool ok = writeAll(pbase(), static_cast<std::size_t>(pptr() - pbase()));
        setp(buffer_.data(), buffer_.data() + buffer_.size());
        return ok;
    }

protected:

    int_type overflow(int_type c) override
    {
        if (!flushBuffer()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof()))
        {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }

    std::streamsize xsputn(const char* s, std::streamsize n) override
    {
        // Large blocks (a base64 array) go straight to the file
        if (n < static_cast<std::streamsize>(buffer_.size()))
        {
            return std::streambuf::xsputn(s, n);
        }
        if (!flushBuffer() || !writeAll(s, static_cast<std::size_t>(n))) return 0;
        return n;
    }

    int sync() override { return flushBuffer() ? 0 : -1; }

public:

    explicit fileBuffer(const fs::path& file)
    {
        fd_ = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
        if (fd_ < 0) error_ = errno;
        setp(buffer_.data(), buffer_.data() + buffer_.size());
    }

    ~fileBuffer() override
    {
        if (fd_ >= 0) ::close(fd_);
    }

    bool isOpen() const { return fd_ >= 0; }

    //- The errno of the first failure, 0 if none
    int error() const { return error_; }

    //- Write what is buffered and close; false on any failure
    bool close()
    {
        if (fd_ < 0) return error_ == 0;
        bool ok = flushBuffer();
        if (::close(fd_) != 0 && ok)
        {
            error_ = errno;
            ok = false;
        }
        fd_ = -1;
        return ok;
    }
};


// * * * * * * * * * * * * * * * * atomicFile * * * * * * * * * * * * * * * //

fs::path atomicFile::tempName(const fs::path& final)
{
    return final.parent_path() / ("." + final.filename().string() + tempSuffix);
}


atomicFile::atomicFile(const fs::path& final)
:
    final_(final),
    temp_(tempName(final)),
    buf_(std::make_unique<fileBuffer>(temp_)),
    os_(buf_.get())
{
    if (!buf_->isOpen())
    {
        throw fatalError
        (
            "cannot create file \"" + final_.string() + "\"" + reason(buf_->error())
        );
    }
}


atomicFile::~atomicFile()
{
    if (!committed_) discard();
}


void atomicFile::discard() noexcept
{
    buf_->close();
    std::error_code ignored;
    fs::remove(temp_, ignored);
}


void atomicFile::commit()
{
    if (committed_) return;

    // A full disk may show only now, when the last of the buffer is written
    const bool written = os_.good() && buf_->close();
    if (!written)
    {
        const int err = buf_->error();
        discard();
        throw fatalError
        (
            "cannot write file \"" + final_.string() + "\"" + reason(err)
        );
    }

    std::error_code ec;
    fs::rename(temp_, final_, ec);
    if (ec)
    {
        discard();
        throw fatalError
        (
            "cannot write file \"" + final_.string() + "\": "
          + ec.message() + " (renaming \"" + temp_.string() + "\")"
        );
    }
    committed_ = true;
}


void atomicFile::write(const fs::path& file, const std::string& text)
{
    atomicFile out(file);
    out.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
    out.commit();
}


int atomicFile::cleanStale
(
    const fs::path& dir,
    const std::function<bool(const std::string&)>& isOurs
)
{
    const std::string tail(tempSuffix);
    std::vector<fs::path> stale;
    std::error_code ec;
    for (const auto& item : fs::directory_iterator(dir, ec))
    {
        const std::string name = item.path().filename().string();
        const bool hiddenTemp =
            name.size() > 1 + tail.size() && name[0] == '.'
         && name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
        if (!hiddenTemp || !item.is_regular_file(ec)) continue;

        const std::string finalName =
            name.substr(1, name.size() - 1 - tail.size());
        if (!isOurs || isOurs(finalName)) stale.push_back(item.path());
    }

    int n = 0;
    for (const fs::path& file : stale)
    {
        if (fs::remove(file, ec)) ++n;
    }
    return n;
}

} // End namespace nmm
