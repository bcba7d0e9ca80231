// SPDX-License-Identifier: GPL-3.0-or-later
#include "grainRegions.H"

#include <map>

namespace
{

//- The value a pixel is grouped by: its label, or 1 (light) / 0 (dark)
std::vector<std::uint32_t> classes(const nmm::labelImage& image, bool binary)
{
    if (!binary) return image.values;
    std::vector<std::uint32_t> light(image.values.size());
    for (std::size_t i = 0; i < light.size(); ++i)
    {
        // Above half the range, in integers: 2v > max
        light[i] = 2*std::uint64_t(image.values[i]) > image.maxValue ? 1 : 0;
    }
    return light;
}

} // End anonymous namespace


nmm::grainRegions::grainRegions(const labelImage& image, bool binary)
:
    nRows_(image.nRows),
    nCols_(image.nCols),
    id_(image.values.size(), 0)
{
    const std::vector<std::uint32_t> value = classes(image, binary);
    const std::size_t nCols = std::size_t(nCols_);
    std::vector<std::size_t> stack;
    for (std::size_t start = 0; start < value.size(); ++start)
    {
        if (value[start] == 0 || id_[start] != 0) continue;
        grains_.push_back({});
        grain& g = grains_.back();
        g.label = value[start];
        const std::uint32_t mine = std::uint32_t(grains_.size());
        id_[start] = mine;
        stack.assign(1, start);
        while (!stack.empty())
        {
            const std::size_t p = stack.back();
            stack.pop_back();
            ++g.nPixels;
            const int r = int(p/nCols), c = int(p%nCols);
            if (r == 0 || c == 0 || r == nRows_ - 1 || c == nCols_ - 1) g.touchesBorder = true;
            const auto visit = [&](bool inside, std::size_t q)
            {
                if (inside && id_[q] == 0 && value[q] == g.label)
                {
                    id_[q] = mine;
                    stack.push_back(q);
                }
            };
            visit(r > 0, p - nCols);
            visit(r < nRows_ - 1, p + nCols);
            visit(c > 0, p - 1);
            visit(c < nCols_ - 1, p + 1);
        }
    }

    std::map<std::uint32_t, int> pieces, seen;
    for (const grain& g : grains_) ++pieces[g.label];
    for (std::size_t k = 0; k < grains_.size(); ++k)
    {
        grain& g = grains_[k];
        const std::string label = std::to_string(binary ? k + 1 : g.label);
        g.name = "grain" + label;
        if (!binary && pieces[g.label] > 1)
        {
            g.name += "_" + std::to_string(++seen[g.label]);
        }
    }
}


void nmm::grainRegions::drop(const std::vector<bool>& which)
{
    for (std::size_t k = 0; k < grains_.size(); ++k)
    {
        if (which[k]) grains_[k].dropped = true;
    }
    for (auto& i : id_)
    {
        if (i != 0 && grains_[i - 1].dropped) i = 0;
    }
}


std::vector<std::pair<std::uint32_t, std::vector<std::string>>>
nmm::grainRegions::splitLabels() const
{
    std::map<std::uint32_t, std::vector<std::string>> names;
    for (const grain& g : grains_) names[g.label].push_back(g.name);
    std::vector<std::pair<std::uint32_t, std::vector<std::string>>> split;
    for (auto& [label, list] : names)
    {
        if (list.size() > 1) split.emplace_back(label, std::move(list));
    }
    return split;
}
