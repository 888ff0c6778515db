// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "figures/catalog.hpp"
#include "plot/figure.hpp"
#include "plot/output.hpp"
#include "plot/theme.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace figures {

/// When the frames of an animation fall, in the pendulum's time w0 t, and how its end
/// meets its start.
struct animation_plan {
    int frames = 1;                 ///< how many, the seam's blended or held frames too
    int motion_frames = 1;          ///< frames 0.. of the motion itself, one step apart
    double fps = 25;                ///< frames per second of playback
    double step = 0;                ///< w0 t from one frame to the next
    double reference_period = 0;    ///< exact period of the first amplitude, in units of 1/w0
    double seconds_per_unit = 1;    ///< physical seconds per unit of w0 t
    bool physical = false;          ///< the spec gives a [pendulum]: clocks in seconds
    loop_mode loop = loop_mode::periods;  ///< what happens at the seam
    bool seamless = false;          ///< every drawn motion's end runs on into its start within a frame
    double history = 0;             ///< w0 t before 0 that is the motion's past (a whole loop), so that trails cross the seam
    std::string note;               ///< why the loop ends as it does where the spec did not say; empty otherwise

    /// The time w0 t of frame i: the motion's, running on under a cross-fade, held under a hold.
    double time(int i) const { return (loop == loop_mode::hold && i >= motion_frames ? motion_frames - 1 : i) * step; }
    /// How much of the first frame is blended into frame i (0 outside a cross-fade), 0 to 1.
    double fade_in(int i) const;
};

/// The periods w0 T of every motion the panels draw (each method of each start in a drawing
/// or a phase portrait, deduplicated; a plot against time starts its cursor again at the
/// seam), or, where one has none, an empty list and why in `why` (the separatrix, a formula).
std::vector<double> drawn_periods(const std::vector<panel_spec>& panels, std::string& why);

/// The smallest number of frames n, 1 to `most`, after which every period in `periods` has
/// run a whole number of times within one frame: n step - k T lies in [0, step] for each T
/// (the last frame falls within a step before the common end, and the first follows it).
/// nullopt if there is none.
std::optional<int> common_loop_frames(const std::vector<double>& periods, double step, int most);

/// True if n frames of `step` end every period in `periods` within a frame (as common_loop_frames).
bool loop_fits(const std::vector<double>& periods, double step, int n);

/// The frames of an animation spec (with the command line's amplitudes). Without a
/// [pendulum] the time is that of a 1 m pendulum. Throws figures::bad_input naming the
/// key and the limit for more than max_frames frames.
/// With `playback_rate`, the frames are timed at the rate it gives for the spec's (a GIF's
/// rate of whole hundredths of a second).
animation_plan plan_animation(const entry& e, const build_options& options, double (*playback_rate)(double) = nullptr);

/// The animation's figure at time w0 t, with its clock if the spec asks for one; `base` is
/// build(e, options) with options.animated set.
plot::figure animation_frame(const entry& e, const build_options& options, const animation_plan& plan,
                             const plot::figure& base, double w0_t);

/// Frame i of the animation: the motion at plan.time(i), blended with the first frame where
/// the plan cross-fades; `base` as for animation_frame.
plot::figure planned_frame(const entry& e, const build_options& options, const animation_plan& plan,
                           const plot::figure& base, int i);

/// Mixes the moving parts of two frames of one animation: `b`'s at opacity w over `a`'s at 1 - w
/// (legend entries from `a` only; the clock of the one more shown).
plot::figure blend_frames(plot::figure a, const plot::figure& b, double w);

/// Writes frames first..last (inclusive, from 0) of the animation in a format whose row
/// holds an animation writer (format.animate), e.g. DIR/ID.gif. Throws figures::bad_input
/// for a frame range outside the animation.
void write_animation(const entry& e, const build_options& options, const plot::theme& theme,
                     const plot::format_row& format, const std::filesystem::path& dir,
                     const plot::output_options& output, int first, int last);

}  // namespace figures
