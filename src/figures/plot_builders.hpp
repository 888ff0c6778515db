// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The builders of the plot kinds, one file each, for the plot table (plots.cpp).

#include "figures/plots.hpp"
#include "figures/spec.hpp"
#include "plot/figure.hpp"
#include "plot/theme.hpp"

#include <functional>
#include <vector>

namespace figures {

/// The keys of each kind (kind_keys.cpp): those its row lists in `keys`, read in an order
/// that lets one key's reading use another's.
void trajectory_keys(key_reading& k);
/// The keys of a phase panel.
void phase_keys(key_reading& k);
/// The keys of a period panel.
void period_keys(key_reading& k);
/// The keys of a coefficient panel.
void coefficient_keys(key_reading& k);
/// The keys of a convergence panel.
void convergence_keys(key_reading& k);
/// The keys of a spectrum panel.
void spectrum_keys(key_reading& k);
/// The keys of a pendulum panel.
void pendulum_keys(key_reading& k);

/// How the drawing shows one pendulum (start i by method j): the one source of its look for
/// the drawing and for its description.
struct pendulum_glyph {
    std::string label;           ///< its legend text (markup): the method, the start, or both
    plot::line_style rod;        ///< the rod's line before a theme's style (never none: solid)
    plot::marker_style bob;      ///< the bob's marker: filled for the exact pendulum, else open
};

/// The look of each pendulum of a pendulum panel, start by start, method by method, as drawn
/// in theme `th` (its style of a method's line, applied to the rod as the drawing's is).
std::vector<pendulum_glyph> pendulum_glyphs(const panel_spec& p, const plot::theme& th);

/// The pendulum drawing's description (kind_descriptions.cpp): what is drawn, each
/// pendulum's rod and bob, where they start.
std::string describe_pendulum_drawing(const panel_spec& spec, bool animated, const plot::theme& th);
/// Each orbit of a phase plot: its shape and how far it reaches on both axes.
std::string describe_phase_orbits(const described_curves& d);

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

/// Adds the rods, bobs, trails and pivot of a pendulum panel at time w0 t, each bob with its
/// motion streak over the `frame_step` before (none for 0).
void add_pendulum_state(plot::panel& panel, const panel_spec& p, double w0_t, double frame_step, double history = 0);

/// A bob's radius in units of the theme's marker radius.
inline constexpr double bob_marker_scale = 3.0;
/// The distance, in rod lengths, between neighbouring bobs of a motion streak, on average
/// along the way since the previous frame: a small fraction of any built-in theme's bob
/// diameter (0.14 rod lengths and more), so that the streak reads as one continuous smear
/// however far the bob went.
inline constexpr double streak_spacing = 0.02;
/// The most bobs in one streak (a jump of 1.28 rod lengths per frame at streak_spacing).
inline constexpr int max_streak_bobs = 64;
/// The opacity of the streak's newest bob; older ones fade linearly towards 0.04.
inline constexpr double streak_alpha = 0.4;

/// One faint bob of a motion streak.
struct streak_bob {
    double angle;  ///< the rod's angle, radians
    double alpha;  ///< opacity
};

/// No strobing: the places the bob passed through between the previous frame (w0 t minus
/// `frame_step`, or the release at 0) and now, oldest first, the first at the previous
/// frame's place, evenly in time and streak_spacing rod lengths apart on average along the way,
/// fading into the past;
/// none where the bob did not move or for a still figure (frame_step 0).
std::vector<streak_bob> motion_streak(const std::function<double(double)>& theta, double w0_t, double frame_step);

}  // namespace figures
