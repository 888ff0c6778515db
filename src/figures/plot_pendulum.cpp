// SPDX-License-Identifier: GPL-3.0-or-later
// The pendulum drawing: rod and bob of each start and method, for animations. A start may
// swing, go over the top (theta unwrapped, drawn modulo 2 pi) or approach the top on the
// separatrix; several starts swing side by side in one drawing, each in its own colour.
#include "figures/plot_builders.hpp"

#include "figures/panel_support.hpp"
#include "figures/pendulum_overlays.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/motion.hpp"
#include "plot/render.hpp"
#include "plot/tex_markup.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

namespace figures {

using plot::line_style;
using plot::marker_style;
using std::numbers::pi;

namespace {

/// One start of a drawing: its exact motion and its legend text.
using bob_start = overlay_start;

/// The panel's starts: its amplitudes (released at rest), then its energies or states.
std::vector<bob_start> starts_of(const panel_spec& p) {
    std::vector<bob_start> out;
    for (const auto& a : p.theta0) {
        out.push_back({pendulum::motion::from_amplitude(a.theta0()), std::string(theta0_markup) + " = " + typeset_angle(a.text)});
    }
    for (const auto& s : p.starts) out.push_back({s.motion, s.label});
    return out;
}

/// The angle of method m at time w0 t from a start: the exact motion in every regime, an
/// approximation of a libration on the libration's own clock about its centre.
std::function<double(double)> angle_of(const method_spec& m, const pendulum::motion& motion) {
    if (is_exact(m)) return [motion](double t) { return motion.theta(t); };
    return [motion, solution = pendulum::method_solution(m.method, motion.amplitude())](double t) {
        return motion.libration_center() + solution.theta(motion.libration_clock(t));
    };
}

/// The bob's place for the angle a: the pivot at the origin, a rod of length 1.
std::pair<double, double> bob_place(double a) { return {std::sin(a), -std::cos(a)}; }

/// How a start's rod and bob look: with one start, the method's style, the theme's included
/// (the glyph the method has in every other panel); with several, the start's colour (the
/// phase portrait's colour of its orbit) and the method's line.
series_style bob_style(const panel_spec& p, const std::vector<bob_start>& starts, std::size_t i, std::size_t j) {
    const auto& m = p.methods[j];
    series_style st = style_of(m, static_cast<int>(j));
    st.id = start_id(st.id, i, starts.size());
    if (starts.size() > 1) {
        // The phase panel's line of the start's orbit, so that one palette colour (the paper
        // theme's black) still tells the starts apart, in the drawing and in its legend.
        static const line_style lines[] = {line_style::solid, line_style::dashed, line_style::dotted,
                                           line_style::dash_dot, line_style::dash_dot_dot};
        if (!m.style) st.line = lines[i % 5];
        st.color = static_cast<int>(i);
        st.label = p.methods.size() == 1 ? plot::label(starts[i].label)
                                         : plot::join(plot::label(starts[i].label + ", "), st.label);
        st.style_key.clear();
    }
    return st;
}

/// The glyph of start i by method j, from its style (bob_style), before a theme's style.
pendulum_glyph glyph_of(const panel_spec& p, const std::vector<bob_start>& starts, std::size_t i, std::size_t j) {
    const series_style st = bob_style(p, starts, i, j);
    const auto& m = p.methods[j];
    return {st.label.markup, st.line == line_style::none ? line_style::solid : st.line,
            m.marker.value_or(is_exact(m) ? marker_style::filled_circle : marker_style::open_circle)};
}

/// The rod of a glyph in its style, not yet placed: the glyph's line, which the theme's
/// style of the method replaces where that is a drawn line (style_line_only).
plot::series rod_of(const series_style& st, const pendulum_glyph& glyph) {
    plot::series rod = series_of(st);
    rod.label.clear();
    rod.style_line_only = true;
    rod.line = glyph.rod;
    rod.marker = marker_style::none;
    rod.width_scale = 1.2;
    rod.id = "rod:" + st.id;
    return rod;
}

/// A moving part of the drawing in the start's style: no legend entry (the panel's key
/// carries it) and no theme style (the part says how it looks).
plot::series drawn_part(const series_style& st) {
    plot::series s = series_of(st);
    s.label.clear();
    s.style_key.clear();
    return s;
}

/// The legend entry of start i by method j: no points, the glyph of the method (one start) or
/// of the start (several) as every panel draws it, themed alike.
plot::series legend_key(const panel_spec& p, const std::vector<bob_start>& starts, std::size_t i, std::size_t j) {
    plot::series key = series_of(bob_style(p, starts, i, j));
    if (starts.size() > 1) key.marker = marker_style::none;  // the rod's line in the start's colour
    key.id = "key:" + key.id;
    return key;
}

/// The trail's legend entry: how far back it reaches, in seconds with a [pendulum] table and
/// one start, else in periods; a faint line in the foreground colour.
plot::series trail_key(const panel_context& c, const panel_spec& p, const std::vector<bob_start>& starts) {
    plot::series key;
    key.id = "key:trail";
    key.alpha = 0.4;
    const auto& m = starts.front().motion;
    if (c.spec.pendulum && starts.size() == 1) {
        const double w0_t = p.trail * (m.has_period() ? m.period() : 2 * pi);
        key.label = plot::label("path of the last " +
                                pendulum::format_double(std::round(w0_t * seconds_per_radian(c.spec) * 100) / 100) + " s");
    } else {
        key.label = plot::label("path" + std::string(starts.size() > 1 ? "s" : "") + " of the last " +
                                pendulum::format_double(p.trail) + " period" + (p.trail == 1 ? "" : "s"));
    }
    return key;
}

}  // namespace

std::vector<pendulum_glyph> pendulum_glyphs(const panel_spec& p, const plot::theme& th) {
    const auto starts = starts_of(p);
    std::vector<pendulum_glyph> out;
    for (std::size_t i = 0; i < starts.size(); ++i) {
        for (std::size_t j = 0; j < p.methods.size(); ++j) {
            pendulum_glyph g = glyph_of(p, starts, i, j);
            // The rod as the theme draws it: the plot layer's styling of the drawing's rod.
            plot::figure one;
            one.panels.emplace_back().data.push_back(rod_of(bob_style(p, starts, i, j), g));
            g.rod = plot::with_theme_styles(one, th).panels.front().data.front().line;
            out.push_back(std::move(g));
        }
    }
    return out;
}

plot::panel pendulum_panel(const panel_context& c, const panel_spec& p) {
    // The drawing: x to the right, y up, the pivot at the origin and a rod of length 1.
    plot::panel panel;
    panel.frameless = true;
    panel.equal_aspect = true;
    panel.x.min = -1.2;
    panel.x.max = 1.2;
    panel.y.min = -1.2;
    panel.y.max = 1.2;
    // The bob's path, faint: the whole circle, which a rotation goes round.
    plot::series path;
    for (double a : grid(0, 2 * pi, 200)) {
        path.x.push_back(std::sin(a));
        path.y.push_back(-std::cos(a));
    }
    path.curve = plot::parametric_curve(0, 2 * pi, [](double a) { return bob_place(a); }, 8);
    path.alpha = 0.2;
    path.width_scale = 0.6;
    path.id = "path";
    panel.data.push_back(std::move(path));
    // A drawing of one start names it, as a trajectory panel does ("(a) theta0 = 10 deg"):
    // drawings side by side (--apart) say which is which.
    const auto starts = starts_of(p);
    if (starts.size() == 1) panel.label = starts.front().label;
    // The turning points of each libration, dotted (a rotation and the separatrix have none).
    for (std::size_t i = 0; i < starts.size(); ++i) {
        const auto& m = starts[i].motion;
        if (m.kind() != pendulum::regime::libration) continue;
        const double amplitude = m.amplitude().radians();
        for (double side : {1.0, -1.0}) {
            plot::series mark;
            mark.x = {0, side * std::sin(amplitude)};
            mark.y = {0, -std::cos(amplitude)};
            mark.line = line_style::dotted;
            mark.alpha = 0.5;
            mark.width_scale = 0.6;
            mark.id = start_id(side > 0 ? "turn:right" : "turn:left", i, starts.size());
            if (starts.size() > 1) mark.color = static_cast<int>(i);
            panel.data.push_back(std::move(mark));
        }
    }
    // The legend: a key per start and method, and the trail's.
    for (std::size_t i = 0; i < starts.size(); ++i) {
        for (std::size_t j = 0; j < p.methods.size(); ++j) panel.data.push_back(legend_key(p, starts, i, j));
    }
    if (p.trail > 0) panel.data.push_back(trail_key(c, p, starts));
    // The teaching overlays' parts that stay (the total energy), then, when still, the rest.
    // An animation's clock goes on its first drawing: every drawing keeps it a line, so that
    // drawings side by side have one size.
    add_overlays_still(panel, p, starts, c.animated && c.spec.animation && c.spec.animation->clock);
    if (!c.animated) {
        add_pendulum_state(panel, p, 0.0, 0.0);
        add_overlays_at(panel, c, p, starts, 0.0);
    }
    return panel;
}

namespace {

/// The bob's recent path over `span` before w0 t, fading into the past in eight steps.
template <class Theta>
void add_trail(plot::panel& panel, const series_style& st, const Theta& theta, double w0_t, double span) {
    for (int k = 0; k < 8 && span > 0; ++k) {
        plot::series trail = drawn_part(st);
        trail.line = line_style::solid;
        trail.marker = marker_style::none;
        trail.alpha = 0.08 + 0.06 * k;
        trail.id = "trail:" + st.id + ":" + std::to_string(k + 1);  // oldest first
        const double t0 = w0_t - span * (8 - k) / 8;
        const double t1 = w0_t - span * (7 - k) / 8;
        // Drawn after this function returns: holds its own copy of the motion.
        const auto bob_at = [theta](double t) { return bob_place(theta(t)); };
        for (double t : {t0, t1}) {
            trail.x.push_back(bob_at(t).first);
            trail.y.push_back(bob_at(t).second);
        }
        trail.curve = plot::parametric_curve(t0, t1, bob_at, 1);
        panel.data.push_back(std::move(trail));
    }
}

/// The way the bob came since the previous frame, as a streak of faint bobs (motion_streak).
template <class Theta>
void add_streak(plot::panel& panel, const series_style& st, const Theta& theta, double w0_t, double frame_step,
                marker_style bob_marker) {
    const auto ghosts = motion_streak(theta, w0_t, frame_step);
    for (std::size_t k = 0; k < ghosts.size(); ++k) {
        const auto& ghost = ghosts[k];
        plot::series s = drawn_part(st);
        s.line = line_style::none;
        // A blur, also behind an outlined bob: filled, fainter for an outline.
        s.marker = marker_style::filled_circle;
        s.marker_scale = bob_marker_scale;
        s.width_scale = 1.5;
        s.id = "streak:" + st.id + ":" + std::to_string(k + 1);  // oldest first
        s.alpha = bob_marker == marker_style::filled_circle ? ghost.alpha : 0.5 * ghost.alpha;
        s.x = {bob_place(ghost.angle).first};
        s.y = {bob_place(ghost.angle).second};
        panel.data.push_back(std::move(s));
    }
}

/// The rod and the bob at angle a, as the glyph shows them.
void add_rod_and_bob(plot::panel& panel, const series_style& st, const pendulum_glyph& glyph, double a) {
    // The glyph's line, themed (a theme's dotted harmonic).
    plot::series rod = rod_of(st, glyph);
    rod.x = {0, std::sin(a)};
    rod.y = {0, -std::cos(a)};
    plot::series bob = drawn_part(st);
    bob.line = line_style::none;
    // The exact pendulum's bob is solid; the approximations' are outlines.
    bob.marker = glyph.bob;
    bob.marker_scale = bob_marker_scale;
    bob.width_scale = 1.5;
    bob.id = "bob:" + st.id;
    bob.x = {std::sin(a)};
    bob.y = {-std::cos(a)};
    panel.data.push_back(std::move(rod));
    panel.data.push_back(std::move(bob));
}

/// The pivot, a dot at the origin.
void add_pivot(plot::panel& panel) {
    plot::series pivot;
    pivot.id = "pivot";
    pivot.line = line_style::none;
    pivot.marker = marker_style::filled_circle;
    pivot.marker_scale = 1.2;
    pivot.x = {0};
    pivot.y = {0};
    panel.data.push_back(std::move(pivot));
}

}  // namespace

void add_pendulum_state(plot::panel& panel, const panel_spec& p, double w0_t, double frame_step, double history) {
    const auto starts = starts_of(p);
    for (std::size_t i = 0; i < starts.size(); ++i) {
        const auto& motion = starts[i].motion;
        // The unit of the trail: the start's period (a rotation's revolution), T0 on the separatrix.
        const double period = motion.has_period() ? motion.period() : 2 * pi;
        for (std::size_t j = 0; j < p.methods.size(); ++j) {
            const auto& m = p.methods[j];
            const auto theta = angle_of(m, motion);
            const series_style st = bob_style(p, starts, i, j);
            if (p.trail > 0) add_trail(panel, st, theta, w0_t, std::min(p.trail * period, w0_t + history));
            const pendulum_glyph glyph = glyph_of(p, starts, i, j);
            add_streak(panel, st, theta, w0_t, frame_step, glyph.bob);
            add_rod_and_bob(panel, st, glyph, theta(w0_t));
        }
    }
    add_pivot(panel);
}

std::vector<streak_bob> motion_streak(const std::function<double(double)>& theta, double w0_t, double frame_step) {
    // Since the previous frame, or since the release at t = 0.
    const double span = std::min(frame_step, w0_t);
    if (!(span > 0)) return {};
    // The length of the bob's way (in rod lengths), from fine steps of the motion.
    constexpr int fine = 64;
    double length = 0;
    auto last = bob_place(theta(w0_t - span));
    for (int k = 1; k <= fine; ++k) {
        const auto next = bob_place(theta(w0_t - span + span * k / fine));
        length += std::hypot(next.first - last.first, next.second - last.second);
        last = next;
    }
    const int n = std::min(max_streak_bobs, static_cast<int>(std::ceil(length / streak_spacing)));
    if (n < 1) return {};
    // Oldest first, the last at the previous frame's place: fading into the past.
    std::vector<streak_bob> out;
    for (int k = n; k >= 1; --k) {
        const double age = static_cast<double>(k) / n;  // (0, 1]: 1 at the previous frame
        out.push_back({theta(w0_t - span * age), streak_alpha * (1.0 - age) + 0.04});
    }
    return out;
}

void add_pendulum_frame(plot::panel& panel, const panel_context& c, const panel_spec& p, double w0_t) {
    add_pendulum_state(panel, p, w0_t, c.frame_step, c.history);
    add_overlays_at(panel, c, p, starts_of(p), w0_t);
}

}  // namespace figures
