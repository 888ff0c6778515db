// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "figures/build_options.hpp"
#include "figures/panel_support.hpp"
#include "figures/plot_builders.hpp"
#include "figures/spec.hpp"
#include "plot/figure.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace figures {

/// The spec's panels with the command line's amplitudes put in: one trajectory panel per
/// amplitude in place of the trajectory panels (keeping their paper file names in order),
/// and the amplitude lists of phase, convergence and spectrum panels replaced.
std::vector<panel_spec> panels_with(const figure_spec& spec, const build_options& options);

/// The figure's grid and sizes, without its panels: enough to know its page size.
plot::figure figure_grid(const figure_spec& spec, const build_options& options = {});

/// The figure a spec describes, its data computed by the core library.
plot::figure build_figure(const figure_spec& spec, const build_options& options = {});

/// Adds what moves at time w0 t: the pendulums, a time cursor and a dot per method on
/// trajectories, a dot per orbit on phase panels. `panels` are the specs f was built from;
/// `frame_step` is the time w0 t since the previous frame (0: none), over which a pendulum's
/// bob leaves its motion streak. `history` is the w0 t before 0 that is the motion's past (a
/// seamless loop's round before the seam), which a trail may reach back into.
void add_frame_state(plot::figure& f, const figure_spec& spec, const std::vector<panel_spec>& panels, double w0_t,
                     double frame_step = 0, double history = 0);

/// The name of the i-th panel (from 0): a, b, ..., z, aa, ab, ...
std::string panel_name(std::size_t i);

}  // namespace figures
