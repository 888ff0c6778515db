// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The builders of the plot kinds, one file each, for the plot table (plots.cpp).

#include "figures/plots.hpp"
#include "figures/spec.hpp"
#include "plot/figure.hpp"

namespace figures {

/// theta(t) of each method at the panel's amplitude.
plot::panel trajectory_panel(const panel_context& c, const panel_spec& p);
/// The time cursor and a dot per method at time w0 t.
void add_trajectory_frame(plot::panel& panel, const panel_context& c, const panel_spec& p, double w0_t);

/// Orbits in the phase plane, one per amplitude and method, and the separatrix.
plot::panel phase_panel(const panel_context& c, const panel_spec& p);
/// A dot per orbit and method at time w0 t.
void add_phase_frame(plot::panel& panel, const panel_context& c, const panel_spec& p, double w0_t);

/// T/T0 of each method against the amplitude, or its error.
plot::panel period_panel(const panel_context& c, const panel_spec& p);

/// One Fourier coefficient of each method against the amplitude.
plot::panel coefficient_panel(const panel_context& c, const panel_spec& p);

/// The period error of the iteration against its order, per amplitude.
plot::panel convergence_panel(const panel_context& c, const panel_spec& p);

/// The magnitudes of the Fourier coefficients, per amplitude and method.
plot::panel spectrum_panel(const panel_context& c, const panel_spec& p);

/// The pendulum's drawing: the bob's path and the amplitude (the rods at t = 0 when still).
plot::panel pendulum_panel(const panel_context& c, const panel_spec& p);
/// The rods, bobs, trails and pivot at time w0 t.
void add_pendulum_frame(plot::panel& panel, const panel_context& c, const panel_spec& p, double w0_t);

/// Adds the rods, bobs, trails and pivot of a pendulum panel at time w0 t.
void add_pendulum_state(plot::panel& panel, const panel_spec& p, double w0_t);

}  // namespace figures
