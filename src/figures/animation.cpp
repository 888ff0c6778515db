// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/animation.hpp"

#include "figures/spec_build.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/exact.hpp"
#include "plot/output.hpp"
#include "pendulum/seconds.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace figures {

namespace {

/// The animation's unit of time: the exact period of the first amplitude or start of the
/// (overridden) panels (a start on the separatrix, which has none: T0).
double reference_period(const std::vector<panel_spec>& panels) {
    for (const auto& p : panels) {
        if (!p.theta0.empty()) return 4 * pendulum::exact_solution(p.theta0.front().value).quarter_period();
        if (!p.starts.empty()) {
            const auto& m = p.starts.front().motion;
            return m.has_period() ? m.period() : 2 * std::numbers::pi;
        }
    }
    throw bad_input("an animation needs a panel with theta0 or a start (a pendulum, trajectory or phase panel)");
}

std::string clock_text(const animation_plan& plan, double w0_t) {
    char buf[64];
    if (plan.physical) {
        std::snprintf(buf, sizeof buf, "<i>t</i> = %.2f s", w0_t * plan.seconds_per_unit);
    } else {
        std::snprintf(buf, sizeof buf, "<i>t</i> = %.2f <i>T</i>", w0_t / plan.reference_period);
    }
    return buf;
}

}  // namespace

animation_plan plan_animation(const entry& e, const build_options& options) {
    if (!e.spec.animation) throw std::logic_error("figure '" + e.id + "' is not an animation");
    const animation_spec& a = *e.spec.animation;
    animation_plan plan;
    plan.fps = a.fps;
    plan.physical = e.spec.pendulum.has_value();
    const double length = plan.physical ? e.spec.pendulum->length_m : 1.0;
    const double g = plan.physical ? e.spec.pendulum->g : 9.80665;
    plan.seconds_per_unit = pendulum::seconds_per_radian(length, g);
    plan.reference_period = reference_period(panels_of(e, options));
    const double span = a.duration_s ? *a.duration_s / plan.seconds_per_unit : a.periods.value_or(1.0) * plan.reference_period;
    // Playback: `speed` seconds of the pendulum's time per second shown.
    const double shown_s = span * plan.seconds_per_unit / a.speed;
    const double frames = std::floor(shown_s * a.fps + 1e-9) + 1;
    if (frames > max_frames) {
        throw bad_input("animation '" + e.id + "' would have " + pendulum::format_double(frames) +
                                    " frames; at most " + std::to_string(max_frames) +
                                    " (lower fps, periods or duration_s, or raise speed)");
    }
    plan.frames = static_cast<int>(frames);
    plan.step = a.speed / a.fps / plan.seconds_per_unit;
    return plan;
}

plot::figure animation_frame(const entry& e, const build_options& options, const animation_plan& plan,
                             const plot::figure& base, double w0_t) {
    plot::figure f = base;
    const auto panels = panels_of(e, options);
    add_frame_state(f, e.spec, panels, w0_t, plan.step);
    if (e.spec.animation && e.spec.animation->clock && !f.panels.empty()) {
        // The clock goes on the first drawing (the pendulum), or on the first panel.
        std::size_t at = 0;
        for (std::size_t i = 0; i < panels.size(); ++i) {
            if (panels[i].plot->drawing) {
                at = i;
                break;
            }
        }
        // Above what the panel shows there already (a pendulum panel's period timer).
        plot::label& shown = f.panels[at].overlay_label;
        shown = plot::label(clock_text(plan, w0_t) + (shown.empty() ? "" : "     " + shown.markup));
    }
    return f;
}

void write_animation(const entry& e, const build_options& options, const plot::theme& theme,
                     const plot::format_row& format, const std::filesystem::path& dir,
                     const plot::output_options& output, int first, int last) {
    if (!format.animate) throw std::logic_error("format " + std::string(format.name) + " holds no animation");
    const animation_plan plan = plan_animation(e, options);
    if (first < 0 || last >= plan.frames || first > last) {
        throw bad_input("frames " + std::to_string(first + 1) + ".." + std::to_string(last + 1) +
                        " are outside animation '" + e.id + "', which has frames 1.." + std::to_string(plan.frames));
    }
    build_options still = sized_by(options, theme);
    still.animated = true;
    const plot::figure base = build(e, still);
    const auto frame = [&](int i) { return animation_frame(e, still, plan, base, plan.time(i)); };
    format.animate(plot::animation_frames{first, last, plan.frames, plan.fps, frame}, theme, dir, e.id, output);
}

}  // namespace figures
