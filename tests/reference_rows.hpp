// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The fields of the mpmath reference rows as the numeric tests read them: numbers,
// amplitudes written "pi-d" or "0.99pi", lists within a field, and ulps to compare in.

#include "pendulum/amplitude.hpp"

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

namespace test_support::rows {

/// A field as a double (strtod: the nearest double to the decimal written).
inline double number(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

/// One ulp of x (the gap to the next double away from zero).
inline double ulp(double x) { return std::nextafter(std::fabs(x), INFINITY) - std::fabs(x); }

/// The amplitude of a reference row: "pi-d" (d a double), "0.99pi" or a double, as the
/// scripts write them.
inline pendulum::amplitude amplitude_of(const std::string& text) {
    if (text.rfind("pi-", 0) == 0) return pendulum::amplitude::from_pi(number(text.substr(3)));
    if (text == "0.99pi") return pendulum::amplitude(0.99 * std::numbers::pi);
    return pendulum::amplitude(number(text));
}

/// A field cut at `sep` (a list within one CSV field).
inline std::vector<std::string> split_at(const std::string& text, char sep) {
    std::vector<std::string> out;
    std::size_t from = 0;
    for (;;) {
        const auto at = text.find(sep, from);
        out.push_back(text.substr(from, at - from));
        if (at == std::string::npos) return out;
        from = at + 1;
    }
}

}  // namespace test_support::rows
