#include "nmmSolid/coupling/carriedPressure/carriedPressure.H"

#include <limits>
#include <map>

namespace nmm
{

namespace
{

bool sameBodies(const locatedContact& a, const locatedContact& b)
{
    return (a.bodies[0] == b.bodies[0] && a.bodies[1] == b.bodies[1])
        || (a.bodies[0] == b.bodies[1] && a.bodies[1] == b.bodies[0]);
}


//- The nearest of before to c, among those between c's bodies if any are
long nearest(const std::vector<locatedContact>& before, const locatedContact& c)
{
    long best = -1, bestAny = -1;
    double d = std::numeric_limits<double>::infinity(), dAny = d;
    for (std::size_t i = 0; i < before.size(); ++i)
    {
        const double di = (before[i].point - c.point).squaredNorm();
        if (di < dAny) { dAny = di; bestAny = long(i); }
        if (sameBodies(before[i], c) && di < d) { d = di; best = long(i); }
    }
    return best >= 0 ? best : bestAny;
}

} // End anonymous namespace


std::vector<double> carriedPressure
(
    const std::vector<locatedContact>& before,
    const std::vector<double>& pressure,
    const std::vector<locatedContact>& now
)
{
    std::map<std::tuple<int, int, int, int>, double> byKey;
    for (std::size_t i = 0; i < before.size(); ++i) byKey[before[i].key] = pressure[i];
    std::vector<double> result;
    for (const auto& c : now)
    {
        const auto it = byKey.find(c.key);
        if (it != byKey.end()) result.push_back(it->second);
        else if (before.empty()) result.push_back(0);
        else result.push_back(pressure[std::size_t(nearest(before, c))]);
    }
    return result;
}

} // End namespace nmm
