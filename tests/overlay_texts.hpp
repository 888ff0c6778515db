// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The texts a LaTeX overlay (pdf_tex, eps_tex) shows, to compare two routes' overlays.

#include "process.hpp"

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace test_support {

/// The texts of a LaTeX overlay, without their size commands, sorted: what it shows.
inline std::multiset<std::string> overlay_texts(const std::filesystem::path& pdf_tex) {
    std::multiset<std::string> texts;
    std::istringstream in(slurp(pdf_tex));
    const std::string smash = "\\smash{";
    for (std::string line; std::getline(in, line);) {
        const auto at = line.find(smash);
        if (at == std::string::npos) continue;
        const auto text = line.find(' ', at + smash.size());  // after the size command
        texts.insert(line.substr(text + 1));
    }
    return texts;
}

/// The texts one overlay has and the other has not, one per line, or "".
inline std::string text_difference(const std::multiset<std::string>& a, const std::multiset<std::string>& b) {
    std::vector<std::string> only_a;
    std::vector<std::string> only_b;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(only_a));
    std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(only_b));
    std::string out;
    for (const auto& t : only_a) out += "\n  only in the PDF: " + t;
    for (const auto& t : only_b) out += "\n  only in the overlay: " + t;
    return out;
}

}  // namespace test_support
