#include "nmmSolid/functionObjects/functionObject/functionObject.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/case/Time/Time.H"

#include <cerrno>
#include <iomanip>
#include <system_error>
#include <limits>

namespace nmm
{

const keywordTable& functionObject::commonKeywords()
{
    static const keywordTable table = []
    {
        keywordTable t("functionObject", "keywords every function object reads");
        t.word("type", "function object type").required();
        return t;
    }();
    return table;
}


functionObject::functionObject
(
    const std::string& name,
    const Time& runTime,
    const nmmSolidModel& model,
    const dictionary& dict,
    std::string type,
    const keywordTable& keywords
)
:
    name_(name),
    type_(std::move(type)),
    file_
    (
        runTime.folder().path()/"postProcessing"/name/runTime.timeName()
      / (name + ".dat")
    ),
    // Enough digits that a difference of energies or positions survives
    // (writePrecision is for fields; these are small tables)
    precision_(std::max(runTime.writePrecision(), 12)),
    model_(model)
{
    keywords.validate(dict);
}


void functionObject::writeHeader(const std::vector<std::string>& columns)
{
    columns_ = columns;
}


void functionObject::openFile()
{
    std::error_code ec;
    std::filesystem::create_directories(file_.parent_path(), ec);
    if (ec) writeFailed(ec.value());
    errno = 0;
    os_.open(file_, std::ios::out | std::ios::trunc);
    if (!os_) writeFailed(errno);
    os_ << '#';
    for (const auto& c : columns_) os_ << ' ' << c;
    os_ << std::endl;
    if (!os_) writeFailed(errno);
}


void functionObject::writeFailed(int err) const
{
    throw fatalError
    (
        "function object '" + name_ + "': cannot write \"" + file_.string() + "\""
      + (err ? ": " + std::generic_category().message(err) : std::string())
    );
}


void functionObject::writeRow(const std::vector<double>& values)
{
    if (!os_.is_open()) openFile();
    lastRow_ = values;
    os_ << std::setprecision(precision_);
    bool first = true;
    for (const double v : values)
    {
        if (!first) os_ << ' ';
        first = false;
        os_ << v;
    }
    // Flushed per row: a run that stops early keeps what it computed, and
    // a full disk shows at the row it stops
    errno = 0;
    os_ << std::endl;
    if (!os_) writeFailed(errno);
}

} // End namespace nmm
