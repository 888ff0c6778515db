// SPDX-License-Identifier: GPL-3.0-or-later
// "Did you mean": the edit distance of two names and the nearest of a list, written once for
// every layer (the formula's functions, TeX macros, spec and style keys, theme names).
// Header-only, and every layer may include src/common (tests/layering_test.sh).
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace common {

/// Words longer than this are no typo of a name (and would cost length squared): they get
/// no suggestion, and edit_distance reports them as far from everything.
inline constexpr std::size_t max_suggest_length = 64;

/// The optimal string alignment distance of a and b: insertions, deletions, substitutions and
/// swaps of two neighbouring bytes count one each. max_suggest_length + 1 if either is longer
/// than max_suggest_length.
inline std::size_t edit_distance(std::string_view a, std::string_view b) {
    if (a.size() > max_suggest_length || b.size() > max_suggest_length) return max_suggest_length + 1;
    // Three rows of the table: i - 2, i - 1 and i.
    std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
                row[j] = std::min(row[j], before[j - 2] + 1);
            }
        }
        std::swap(before, previous);
        std::swap(previous, row);
    }
    return previous[b.size()];
}

/// The first of `names` nearest to `word` at an edit distance below `below`, or empty (always
/// for a word longer than max_suggest_length, whatever `below`).
/// Names is any range of things a std::string_view can be made from.
template <class Names>
std::string nearest_name(std::string_view word, const Names& names, std::size_t below) {
    std::string best;
    if (word.size() > max_suggest_length) return best;
    for (const auto& name : names) {
        const std::string_view n(name);
        const std::size_t d = edit_distance(word, n);
        if (d < below) {
            below = d;
            best = n;
        }
    }
    return best;
}

}  // namespace common
