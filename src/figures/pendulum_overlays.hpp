// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The teaching overlays of a pendulum panel, each computed from the exact motion (not
// integrated): energy bars (kinetic, potential, total, in units of m g L), the bob's velocity
// and acceleration as arrows, and a period timer that shows the measured period once the bob
// has completed one.

#include "figures/plots.hpp"
#include "figures/spec.hpp"
#include "pendulum/motion.hpp"
#include "plot/figure.hpp"

#include <optional>
#include <string>
#include <vector>

namespace figures {

/// A start of a pendulum panel: its exact motion and its legend text.
struct overlay_start {
    pendulum::motion motion;  ///< the exact motion
    std::string label;        ///< "ϑ0 = 170°", "E = 2.6" (markup)
};

/// The energies of the bob per m g L at one time.
struct bob_energies {
    double kinetic = 0;    ///< theta'^2 / 2, theta' in units of w0
    double potential = 0;  ///< 1 - cos theta, as 2 sin^2(theta / 2)
    double total = 0;      ///< the motion's energy E, constant
};

/// The energies at time w0 t, from the exact theta and theta'.
bob_energies energies_at(const pendulum::motion& m, double w0_t);

/// The bob's velocity (units of w0 L) and acceleration (units of g) at time w0 t, the pivot
/// at the origin, y up: the acceleration is the tangential part -sin(theta) plus the
/// centripetal theta'^2 along the rod, towards the pivot.
struct bob_vectors {
    double vx = 0;  ///< velocity, x
    double vy = 0;  ///< velocity, y
    double ax = 0;  ///< acceleration, x
    double ay = 0;  ///< acceleration, y
};

/// The bob's velocity and acceleration at time w0 t, from the exact theta and theta'.
bob_vectors vectors_at(const pendulum::motion& m, double w0_t);

/// The largest speed of the whole motion, sqrt(2 E) at the bottom, in units of w0 L.
double largest_speed(const pendulum::motion& m);

/// The largest acceleration of the whole motion, in units of g.
double largest_acceleration(const pendulum::motion& m);

/// The period (a rotation's revolution) in units of 1/w0, measured on the exact motion as a
/// stopwatch would: between two passages through the bottom in the same direction (a
/// rotation: the time to go once round); none on the separatrix.
std::optional<double> measured_period(const pendulum::motion& m);

/// The longest arrow, in rod lengths: its tip stays within 1.17 rod lengths of the pivot,
/// inside the drawing's 1.2.
inline constexpr double longest_arrow = 0.6;

/// How far the drawing reaches right of the pivot with energy bars (rod lengths).
inline constexpr double energy_bars_right = 2.35;

/// The bars' baseline and height of the largest energy of the panel (rod lengths).
inline constexpr double energy_bars_base = -1.1;
/// The height of the panel's largest total energy.
inline constexpr double energy_bars_height = 2.2;

/// The parts of the overlays that do not move: the room for the bars on the right, each
/// start's total energy bar, and a line above the drawing for the timer or for an animation's
/// clock (`clock`): plot::panel::overlay_line.
void add_overlays_still(plot::panel& panel, const panel_spec& p, const std::vector<overlay_start>& starts,
                        bool clock = false);

/// The overlays at time w0 t: kinetic and potential bars, arrows and the timer's text.
void add_overlays_at(plot::panel& panel, const panel_context& c, const panel_spec& p,
                     const std::vector<overlay_start>& starts, double w0_t);

/// The period timer's text at time w0 t, of the panel's first start (named when there are
/// several): the time running, then the measured period from
/// the frame nearest its completion on (frame_step: w0 t between frames; seconds with a
/// [pendulum] table, else T0 = 2 pi / w0).
std::string timer_text(const figure_spec& spec, const std::vector<overlay_start>& starts, double w0_t,
                       double frame_step = 0);

}  // namespace figures
