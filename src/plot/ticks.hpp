// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <vector>

namespace plot {

/// Tick positions and labels for one axis, and the axis range they span.
struct tick_set {
    double lo = 0;                    ///< axis lower limit
    double hi = 1;                    ///< axis upper limit
    std::vector<double> major;        ///< major tick values, in [lo, hi]
    std::vector<double> minor;        ///< minor tick values, in [lo, hi]
    std::vector<std::string> labels;  ///< Pango markup, one per major tick
};

/// The "nice" step (1, 2 or 5 times a power of ten, 2.5 times one from 25 up) for at most
/// max_ticks ticks on [lo, hi] (or on the enclosing ticks, with `expand`), at least two of
/// them when possible. The labels of one range keep their decimals whatever the number of
/// ticks: 0.0 0.2 ... 1.0 or 0.0 0.5 1.0, never 0.00 0.25 ... 1.00.
double nice_step(double lo, double hi, int max_ticks, bool expand = true);

/// Linear ticks after MaxNLocator: multiples of a nice step. With `expand`, the range grows
/// to the enclosing ticks; a degenerate range (lo == hi) is widened around its value.
tick_set linear_ticks(double lo, double hi, int max_ticks, bool expand);

/// Ticks at multiples of pi/8, pi/4, pi/2, pi or 2 pi, labelled 0, π/4, π/2, 3π/4, π, ...
tick_set pi_ticks(double lo, double hi, int max_ticks, bool expand);

/// Ticks at whole degrees that divide the circle (1, 2, 5, 10, 15, 30, 45, 90, ...), labelled 45°.
tick_set degree_ticks(double lo, double hi, int max_ticks, bool expand);

/// Logarithmic ticks at powers of ten (labelled 10^n), minor ticks at 2..9 times them.
tick_set log_ticks(double lo, double hi, int max_ticks, bool expand);

/// Labels for ticks i*step, formatted together so that they share precision
/// ("0.0 0.5 1.0"), with a true minus sign; very large or small values as m×10^e.
std::vector<std::string> format_linear_labels(const std::vector<double>& ticks, double step);

}  // namespace plot
