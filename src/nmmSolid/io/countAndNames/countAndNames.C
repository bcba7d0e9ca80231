// SPDX-License-Identifier: GPL-3.0-or-later
#include "nmmSolid/io/countAndNames/countAndNames.H"

#include <algorithm>

std::string nmm::countAndNames(const std::vector<std::string>& names, std::size_t most)
{
    std::string text = std::to_string(names.size());
    if (names.empty()) return text;
    text += " (";
    for (std::size_t i = 0; i < std::min(names.size(), most); ++i)
    {
        text += (i ? " " : "") + names[i];
    }
    return text + (names.size() > most ? " ...)" : ")");
}
