// SPDX-License-Identifier: GPL-3.0-or-later
#include "grainLoops.H"

#include <unordered_map>

std::vector<std::vector<nmm::chainSide>> nmm::chainsOfGrains
(
    const std::vector<boundaryChain>& chains,
    std::size_t nGrains
)
{
    std::vector<std::vector<chainSide>> sides(nGrains + 1);
    for (std::size_t c = 0; c < chains.size(); ++c)
    {
        sides[chains[c].left].push_back({c, true});
        sides[chains[c].right].push_back({c, false});
    }
    return sides;
}


std::int64_t nmm::twiceArea(const std::vector<gridPoint>& loop)
{
    std::int64_t a = 0;
    for (std::size_t i = 0, n = loop.size(); i < n; ++i)
    {
        const gridPoint& p = loop[i];
        const gridPoint& q = loop[(i + 1)%n];
        a += p.x*q.y - q.x*p.y;
    }
    return a;
}


std::optional<nmm::grainLoops> nmm::assembleLoops
(
    const std::vector<chainSide>& sides,
    const std::vector<boundaryChain>& chains,
    const std::vector<std::vector<gridPoint>>& points
)
{
    const auto startOf = [&](const chainSide& s)
    {
        return s.forward ? chains[s.chain].startNode : chains[s.chain].endNode;
    };
    const auto endOf = [&](const chainSide& s)
    {
        return s.forward ? chains[s.chain].endNode : chains[s.chain].startNode;
    };
    std::unordered_map<std::size_t, std::size_t> startingAt;
    for (std::size_t i = 0; i < sides.size(); ++i)
    {
        if (!startingAt.emplace(startOf(sides[i]), i).second) return std::nullopt;
    }

    grainLoops result;
    bool haveOuter = false;
    std::vector<bool> used(sides.size(), false);
    for (std::size_t first = 0; first < sides.size(); ++first)
    {
        if (used[first]) continue;
        std::vector<gridPoint> loop;
        for (std::size_t i = first;;)
        {
            used[i] = true;
            const std::vector<gridPoint>& p = points[sides[i].chain];
            if (sides[i].forward) loop.insert(loop.end(), p.begin(), p.end() - 1);
            else loop.insert(loop.end(), p.rbegin(), p.rend() - 1);
            const auto next = startingAt.find(endOf(sides[i]));
            if (next == startingAt.end()) return std::nullopt;
            i = next->second;
            if (i == first) break;
            if (used[i]) return std::nullopt;
        }
        const std::int64_t a = twiceArea(loop);
        if (loop.size() < 3 || a == 0 || (a > 0 && haveOuter)) return std::nullopt;
        if (a > 0)
        {
            result.outer = std::move(loop);
            haveOuter = true;
        }
        else
        {
            result.holes.push_back(std::move(loop));
        }
    }
    if (!haveOuter) return std::nullopt;
    return result;
}
