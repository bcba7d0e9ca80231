// SPDX-License-Identifier: GPL-3.0-or-later
#include "nmmSolid/io/boxExtent/boxExtent.H"

#include <array>
#include <iomanip>
#include <limits>
#include <sstream>

std::string nmm::boxExtent::text() const
{
    std::ostringstream os;
    os << std::setprecision(std::numeric_limits<double>::max_digits10)
       << '(' << x0 << ' ' << y0 << ")-(" << x1 << ' ' << y1 << ')';
    return os.str();
}


const nmm::keywordTable& nmm::boxExtent::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("box", "axis-aligned box");
        t.vector("min", "lower left corner (x y)", "m").required();
        t.vector("max", "upper right corner (x y)", "m").required();
        return t;
    }();
    return table;
}


nmm::boxExtent nmm::boxExtent::read(const dictionary& boxDict)
{
    keywords().validate(boxDict);
    const auto lo = boxDict.get<std::array<double, 2>>("min");
    const auto hi = boxDict.get<std::array<double, 2>>("max");
    if (!(hi[0] > lo[0] && hi[1] > lo[1]))
    {
        throw boxDict.lookupEntry("max").error("box: 'max' must exceed 'min' in "
            "both x and y (the box has no area)");
    }
    return {lo[0], lo[1], hi[0], hi[1]};
}
