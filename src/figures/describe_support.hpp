// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The words figure descriptions are made of (describe.cpp), shared with the descriptions
// of the plot kinds' own (kind_descriptions.cpp).

#include "figures/spec.hpp"
#include "plot/figure.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace figures {

/// A number as a reader says it: three significant digits, an angle axis' in fractions of pi.
std::string spoken(double v, plot::tick_kind kind);

/// A label as a screen reader should meet it: subscripts after the base (T0, T_N, c_(2k+1)),
/// Greek letters and primes spelt out, no markup.
std::string spoken_label(const std::string& markup);

/// Points along a series: its curve sampled finely where it has one, else its points.
std::vector<std::pair<double, double>> dense(const plot::series& s);

/// "a", "a and b", "a, b, and c".
std::string join(const std::vector<std::string>& items);

/// "+-A" for a range symmetric about zero, "from A to B" otherwise.
std::string extent(double lo, double hi, plot::tick_kind kind);

/// An amplitude as its spec gives it: in degrees if it was given in degrees, else in pi.
std::string spoken_amplitude(const amplitude& a);

/// What each start launched together does: "E = 2.6 goes over the top, round and round
/// (rotation)"; empty without starts.
std::string start_motions(const panel_spec& spec);

}  // namespace figures
