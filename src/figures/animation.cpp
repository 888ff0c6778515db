// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/animation.hpp"

#include "figures/spec_build.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/exact.hpp"
#include "plot/gif.hpp"
#include "plot/output.hpp"
#include "plot/render.hpp"
#include "pendulum/seconds.hpp"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <iostream>
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

/// True for a method whose period is known without solving it: the exact motion and the
/// closed-form approximants (an iteration's period is its solution, which the render's cost
/// check weighs before any is solved; a formula's motion has none known in advance).
bool period_known(const method_spec& m) {
    return m.method.is_exact() || (!m.method.user && m.method.row->role == pendulum::method_role::approximant);
}

/// The period w0 T of method m from a start, or NaN where it has none (or none known).
double period_of(const method_spec& m, const pendulum::motion& motion) {
    if (m.method.is_exact()) return motion.has_period() ? motion.period() : std::nan("");
    if (!period_known(m) || motion.kind() != pendulum::regime::libration) return std::nan("");
    return 2 * std::numbers::pi * pendulum::method_period(m.method, motion.amplitude());
}

/// Every start of a panel as a motion: its amplitudes released at rest, then its other starts.
std::vector<pendulum::motion> motions_of(const panel_spec& p) {
    std::vector<pendulum::motion> out;
    for (const auto& a : p.theta0) out.push_back(pendulum::motion::from_amplitude(a.theta0()));
    for (const auto& s : p.starts) out.push_back(s.motion);
    return out;
}

/// Why a method's motion from a start has no period, for a note.
std::string no_period(const method_spec& m, const pendulum::motion& motion) {
    if (!period_known(m)) return "the motion of " + m.method.text() + " has no period known before it is solved";
    if (motion.kind() == pendulum::regime::separatrix) return "the separatrix (E = 2 m g L) has no period";
    return "the " + m.method.text() + " motion has no period here";
}

/// The frames added at the seam: half a second of cross-fade, a second of hold, none for periods.
int seam_frames(loop_mode loop, double fps) {
    if (loop == loop_mode::crossfade) return std::max(2, static_cast<int>(std::lround(fps / 2)));
    if (loop == loop_mode::hold) return std::max(1, static_cast<int>(std::lround(fps)));
    return 0;
}

std::string_view loop_name(loop_mode m) {
    for (const auto& row : loop_rows) {
        if (row.mode == m) return row.name;
    }
    throw std::logic_error("a loop mode without a row");
}

/// The frames of the motion: those of the spec's length, or of the smallest common loop of
/// every drawn period; and whether that loop is seamless, with a note where the spec's
/// default cannot be.
void plan_length(animation_plan& plan, const animation_spec& a, const std::vector<panel_spec>& panels,
                 const std::string& id) {
    std::string why;
    const auto periods = drawn_periods(panels, why);
    const bool explicit_length = a.periods || a.duration_s;
    const double span = a.duration_s ? *a.duration_s / plan.seconds_per_unit : a.periods.value_or(1.0) * plan.reference_period;
    const auto frames_of = [&](double w0_t) { return std::max(1.0, std::ceil(w0_t / plan.step - 1e-9)); };
    std::optional<int> common;
    if (!explicit_length && !periods.empty()) common = common_loop_frames(periods, plan.step, max_frames);
    const double n = common ? *common : frames_of(span);
    if (n > max_frames) {
        throw bad_input("animation '" + id + "' would have " + pendulum::format_double(n) + " frames; at most " +
                        std::to_string(max_frames) + " (lower fps, periods or duration_s, or raise speed)");
    }
    plan.motion_frames = static_cast<int>(n);
    plan.seamless = !periods.empty() && loop_fits(periods, plan.step, plan.motion_frames);
    if (periods.empty() && why.empty()) {
        // Nothing but plots against time: their cursors start again, whatever the length.
        plan.loop = a.loop.value_or(loop_mode::periods);
        return;
    }
    if (why.empty() && !plan.seamless) {
        why = explicit_length ? "its length is not a whole number of periods of every drawn motion"
                                : "the drawn motions' periods meet within a frame in no loop of up to " +
                                      std::to_string(max_frames) + " frames";
    }
    plan.loop = a.loop.value_or(plan.seamless ? loop_mode::periods : loop_mode::crossfade);
    if (!plan.seamless && (!a.loop || *a.loop == loop_mode::periods)) {
        plan.note = "animation '" + id + "' cannot loop without a jump: " + why + "; " +
                    (a.loop ? "it jumps back to its start (loop = \"crossfade\" or \"hold\" softens the seam)"
                            : "it ends on a cross-fade (loop = \"crossfade\"; or choose loop = \"hold\")");
    }
    if (plan.seamless && plan.loop == loop_mode::periods) plan.history = plan.motion_frames * plan.step;
}

/// One legend for the animation (plot::one_legend, as every figure has): a drawing's dotted
/// rays to its turning points get an entry of their own, the first of them.
void one_legend(plot::figure& f) {
    bool turn_named = false;
    std::vector<plot::panel*> panels;
    for (auto& panel : f.panels) {
        panels.push_back(&panel);
        for (auto& s : panel.data) {
            if (turn_named || !s.id.starts_with("turn:")) continue;
            s.label = plot::label("turning points");
            turn_named = true;
        }
    }
    plot::one_legend(panels);
}

}  // namespace

double animation_plan::fade_in(int i) const {
    if (loop != loop_mode::crossfade || i < motion_frames) return 0;
    return static_cast<double>(i - motion_frames + 1) / (frames - motion_frames + 1);
}

std::vector<double> drawn_periods(const std::vector<panel_spec>& panels, std::string& why) {
    std::vector<double> out;
    for (const auto& p : panels) {
        // A plot against time moves its cursor along its range and starts it again at the seam.
        if (!p.plot->add_frame || p.plot->range == range_kind::times) continue;
        for (const auto& motion : motions_of(p)) {
            for (const auto& m : p.methods) {
                if (!m.method.has_motion()) continue;
                const double t = period_of(m, motion);
                if (!std::isfinite(t) || t <= 0) {
                    why = no_period(m, motion);
                    return {};
                }
                const bool known = std::any_of(out.begin(), out.end(), [t](double u) { return std::fabs(u - t) <= 1e-12 * t; });
                if (!known) out.push_back(t);
            }
        }
    }
    return out;
}

bool loop_fits(const std::vector<double>& periods, double step, int n) {
    const double end = n * step;
    return std::all_of(periods.begin(), periods.end(), [&](double t) {
        const double k = std::floor(end / t + 1e-9);
        const double late = end - k * t;
        return k >= 1 && late >= -1e-9 * step && late <= step * (1 + 1e-9);
    });
}

std::optional<int> common_loop_frames(const std::vector<double>& periods, double step, int most) {
    if (periods.empty() || !(step > 0)) return std::nullopt;
    for (int n = 1; n <= most; ++n) {
        if (loop_fits(periods, step, n)) return n;
    }
    return std::nullopt;
}

animation_plan plan_animation(const entry& e, const build_options& options, double (*playback_rate)(double)) {
    if (!e.spec.animation) throw std::logic_error("figure '" + e.id + "' is not an animation");
    const animation_spec& a = *e.spec.animation;
    animation_plan plan;
    plan.fps = playback_rate ? playback_rate(a.fps) : a.fps;
    plan.physical = e.spec.pendulum.has_value();
    const double length = plan.physical ? e.spec.pendulum->length_m : 1.0;
    const double g = plan.physical ? e.spec.pendulum->g : 9.80665;
    plan.seconds_per_unit = pendulum::seconds_per_radian(length, g);
    const auto panels = panels_of(e, options);
    plan.reference_period = reference_period(panels);
    // Playback: `speed` seconds of the pendulum's time per second shown.
    plan.step = a.speed / plan.fps / plan.seconds_per_unit;
    plan_length(plan, a, panels, e.id);
    const double frames = static_cast<double>(plan.motion_frames) + seam_frames(plan.loop, plan.fps);
    if (frames > max_frames) {
        throw bad_input("animation '" + e.id + "' would have " + pendulum::format_double(frames) +
                        " frames with its loop = \"" + std::string(loop_name(plan.loop)) + "\"; at most " +
                        std::to_string(max_frames) + " (lower fps, periods or duration_s, or raise speed)");
    }
    plan.frames = static_cast<int>(frames);
    return plan;
}

plot::figure animation_frame(const entry& e, const build_options& options, const animation_plan& plan,
                             const plot::figure& base, double w0_t) {
    plot::figure f = base;
    const auto panels = panels_of(e, options);
    // In a seamless loop the round before the seam is the motion's past: a trail at the first
    // frames reaches back across the seam, and every frame shows its own time exactly.
    add_frame_state(f, e.spec, panels, w0_t, plan.step, plan.history);
    one_legend(f);
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

plot::figure blend_frames(plot::figure a, const plot::figure& b, double w) {
    for (std::size_t k = 0; k < a.panels.size() && k < b.panels.size(); ++k) {
        auto& panel = a.panels[k];
        // The legend does not fade: each entry moves to a copy of its series at full
        // opacity, shrunk to its first point and drawn before what moves (a rod: under the
        // pivot), where the legend's order keeps it.
        std::vector<plot::series> entries;
        for (auto& s : panel.data) {
            if (!s.overlay) continue;
            if (!s.label.empty() && !s.x.empty()) {
                plot::series entry = s;
                entry.x = {s.x.front(), s.x.front()};
                entry.y = {s.y.front(), s.y.front()};
                entry.curve = {};
                entry.id += ":legend";
                entries.push_back(std::move(entry));
                s.label = {};
            }
            s.alpha *= 1 - w;
        }
        const auto moving = std::find_if(panel.data.begin(), panel.data.end(), [](const plot::series& s) { return s.overlay; });
        panel.data.insert(moving, entries.begin(), entries.end());
        for (const auto& s : b.panels[k].data) {
            if (!s.overlay) continue;
            panel.data.push_back(s);
            panel.data.back().alpha *= w;
            panel.data.back().label = {};
            panel.data.back().id += ":fade-in";
        }
        if (w >= 0.5) panel.overlay_label = b.panels[k].overlay_label;
    }
    return a;
}

plot::figure planned_frame(const entry& e, const build_options& options, const animation_plan& plan,
                           const plot::figure& base, int i) {
    plot::figure f = animation_frame(e, options, plan, base, plan.time(i));
    const double w = plan.fade_in(i);
    if (w <= 0) return f;
    return blend_frames(std::move(f), animation_frame(e, options, plan, base, plan.time(0)), w);
}

void write_animation(const entry& e, const build_options& options, const plot::theme& theme,
                     const plot::format_row& format, const std::filesystem::path& dir,
                     const plot::output_options& output, int first, int last) {
    if (!format.animate) throw std::logic_error("format " + std::string(format.name) + " holds no animation");
    const animation_plan plan = plan_animation(e, options, format.playback_rate);
    if (!plan.note.empty()) std::cerr << "pendulum-figures: note: " << e.id << "." << format.name << ": " << plan.note << '\n';
    if (format.playback_rate && plan.fps != e.spec.animation->fps) {
        std::cerr << "pendulum-figures: note: " << e.id << "." << format.name << ": "
                  << pendulum::format_double(e.spec.animation->fps)
                  << " frames per second would play unevenly (its frames' delays are whole hundredths of a second); "
                     "it plays at "
                  << plot::rate_text(plan.fps) << '\n';
    }
    if (first < 0 || last >= plan.frames || first > last) {
        throw bad_input("frames " + std::to_string(first + 1) + ".." + std::to_string(last + 1) +
                        " are outside animation '" + e.id + "', which has frames 1.." + std::to_string(plan.frames));
    }
    build_options still = sized_by(options, theme);
    still.animated = true;
    const plot::figure base = build(e, still);
    const auto frame = [&](int i) { return planned_frame(e, still, plan, base, i); };
    format.animate(plot::animation_frames{first, last, plan.frames, plan.fps, frame}, theme, dir, e.id, output);
}

}  // namespace figures
