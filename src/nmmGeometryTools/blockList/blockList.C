// SPDX-License-Identifier: GPL-3.0-or-later
#include "nmmGeometryTools/blockList/blockList.H"

#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"
#include "nmmSolid/io/dictionary/dictionary.H"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace
{

void writeLoop(std::ostream& os, const nmm::pointLoop& loop)
{
    os << '(';
    for (std::size_t i = 0; i < loop.size(); ++i)
    {
        os << (i ? " (" : "(") << loop[i].x() << ' ' << loop[i].y() << ')';
    }
    os << ')';
}

} // End anonymous namespace


std::string nmm::blockList::text(const std::string& comment) const
{
    std::ostringstream os;
    os << std::setprecision(std::numeric_limits<double>::max_digits10);
    std::istringstream lines(comment);
    for (std::string line; std::getline(lines, line);)
    {
        os << "// " << line << '\n';
    }
    for (const shape& s : shapes_)
    {
        os << s.name << " { material " << s.material << "; polygon ";
        writeLoop(os, s.outer);
        os << ';';
        if (!s.holes.empty())
        {
            os << " holes (";
            for (const pointLoop& h : s.holes)
            {
                os << ' ';
                writeLoop(os, h);
            }
            os << " );";
        }
        os << " }\n";
    }
    return os.str();
}


void nmm::blockList::check() const
{
    const dictionary dict = dictionary::parse
    (
        "blocks (\n" + text({}) + ");\n", "<generated blocks>"
    );
    (void)blockGeometry::read(dict);
}


void nmm::blockList::write
(
    const std::filesystem::path& file,
    const std::string& comment
) const
{
    check();
    if (file.has_parent_path())
    {
        std::filesystem::create_directories(file.parent_path());
    }
    std::ofstream os(file);
    os << text(comment);
    if (!os.flush())
    {
        throw std::runtime_error("cannot write " + file.string());
    }
}


double nmm::blockList::materialArea() const
{
    double a = 0;
    for (const shape& s : shapes_)
    {
        a += loopArea(s.outer);
        for (const pointLoop& h : s.holes) a -= loopArea(h);
    }
    return a;
}


double nmm::loopArea(const pointLoop& loop)
{
    double twice = 0;
    for (std::size_t i = 0, n = loop.size(); i < n; ++i)
    {
        const auto& p = loop[i];
        const auto& q = loop[(i + 1)%n];
        twice += p.x()*q.y() - q.x()*p.y();
    }
    return 0.5*std::abs(twice);
}
