// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a render will cost, estimated from its specs before any work: the seconds of
// computing and drawing (panels x amplitudes x methods x levels x samples x frames, each
// weighted by what it really costs: an iteration's order and its MPFR levels close to pi),
// and the memory its series take. The unit costs are measured (bench/calibrate_costs.md).

#include "figures/catalog.hpp"

#include <string>
#include <vector>

namespace figures {

/// The most seconds of one core a render may be estimated to take: 15 minutes on the
/// machine the unit costs were measured on (about 8 minutes on 2 cores, which share the
/// figures, files and frames).
inline constexpr double max_render_seconds = 900;

/// The most memory a render's series (the points of its curves) may be estimated to take.
inline constexpr double max_render_series_bytes = 1024.0 * 1024 * 1024;

/// One figure of a render: drawn once per file (a still figure), or once per frame.
struct costed_figure {
    const entry* figure = nullptr;     ///< the figure
    int frames = 0;                    ///< frames drawn (an animation), 0 for a still figure
    std::vector<std::string> formats;  ///< the formats of its files (a format twice: two files)
    double raster_pixels = 0;          ///< pixels of each raster drawn
};

/// The largest part of an estimate, for the message.
struct cost_part {
    std::string where;   ///< "figure 'x' panel 2 (spectrum)"
    std::string key;     ///< what to reduce there: "methods (order:200 x 12) and theta0 (3 close to pi)"
    double seconds = 0;  ///< its seconds
};

/// A render's estimated cost.
struct cost_estimate {
    double seconds = 0;       ///< of one core, on the reference machine
    double series_bytes = 0;  ///< memory of the series built at once (the largest figure's)
    cost_part largest;        ///< the part that costs most seconds
    cost_part largest_memory; ///< the figure whose series take most memory
};

/// The estimate for figures built with `options` (their panels as panels_of gives them).
cost_estimate estimate_cost(const std::vector<costed_figure>& figures, const build_options& options);

/// Throws bad_input, before any work, if the estimate is over max_render_seconds or
/// max_render_series_bytes, naming the estimate, the bound, and the panel and key that cost most.
void check_cost(const std::vector<costed_figure>& figures, const build_options& options);

}  // namespace figures
