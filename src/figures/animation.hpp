// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "figures/catalog.hpp"
#include "plot/figure.hpp"
#include "plot/output.hpp"
#include "plot/theme.hpp"

#include <filesystem>
#include <string>

namespace figures {

/// When the frames of an animation fall, in the pendulum's time w0 t.
struct animation_plan {
    int frames = 1;                 ///< how many
    double fps = 30;                ///< frames per second of playback
    double step = 0;                ///< w0 t from one frame to the next
    double reference_period = 0;    ///< exact period of the first amplitude, in units of 1/w0
    double seconds_per_unit = 1;    ///< physical seconds per unit of w0 t
    bool physical = false;          ///< the spec gives a [pendulum]: clocks in seconds

    /// The time w0 t of frame i.
    double time(int i) const { return i * step; }
};

/// The frames of an animation spec (with the command line's amplitudes). Without a
/// [pendulum] the time is that of a 1 m pendulum. Throws figures::bad_input naming the
/// key and the limit for more than max_frames frames.
animation_plan plan_animation(const entry& e, const build_options& options);

/// The animation's figure at time w0 t, with its clock if the spec asks for one; `base` is
/// build(e, options) with options.animated set.
plot::figure animation_frame(const entry& e, const build_options& options, const animation_plan& plan,
                             const plot::figure& base, double w0_t);

/// Writes frames first..last (inclusive, from 0) of the animation in a format whose row
/// holds an animation writer (format.animate), e.g. DIR/ID.gif. Throws figures::bad_input
/// for a frame range outside the animation.
void write_animation(const entry& e, const build_options& options, const plot::theme& theme,
                     const plot::format_row& format, const std::filesystem::path& dir,
                     const plot::output_options& output, int first, int last);

}  // namespace figures
