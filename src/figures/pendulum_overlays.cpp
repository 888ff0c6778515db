// SPDX-License-Identifier: GPL-3.0-or-later
// The teaching overlays of a pendulum panel: energy bars, velocity and acceleration arrows
// and a period timer, from the exact motion.
#include "figures/pendulum_overlays.hpp"

#include "figures/panel_support.hpp"
#include "pendulum/seconds.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace figures {

using plot::line_style;
using plot::marker_style;
using std::numbers::pi;

bob_energies energies_at(const pendulum::motion& m, double w0_t) {
    const double w = m.velocity(w0_t);
    const double s = std::sin(m.theta(w0_t) / 2);
    return {w * w / 2, 2 * s * s, m.energy()};
}

bob_vectors vectors_at(const pendulum::motion& m, double w0_t) {
    const double a = m.theta(w0_t);
    const double w = m.velocity(w0_t);
    // Along the rod outwards (sin a, -cos a); along the path forwards (cos a, sin a).
    const double tangential = -std::sin(a);
    const double centripetal = w * w;
    return {w * std::cos(a), w * std::sin(a), tangential * std::cos(a) - centripetal * std::sin(a),
            tangential * std::sin(a) + centripetal * std::cos(a)};
}

double largest_speed(const pendulum::motion& m) { return std::sqrt(2 * m.energy()); }

double largest_acceleration(const pendulum::motion& m) {
    // |a|^2 = sin^2 a + theta'^4, theta'^2 = 2 (E - 1 + cos a), over the angles the bob reaches.
    const double e = m.energy();
    double most = 0;
    constexpr int steps = 4000;
    for (int k = 0; k <= steps; ++k) {
        const double a = pi * k / steps;
        const double w2 = 2 * (e - 1 + std::cos(a));
        if (w2 < 0) break;
        most = std::max(most, std::hypot(std::sin(a), w2));
    }
    return most;
}

namespace {

/// The first time after `from` at which f changes from negative to non-negative, found by
/// steps of `step` up to `until` and refined by bisection; none if it does not.
template <class F>
std::optional<double> first_rise(const F& f, double from, double until, double step) {
    double a = from;
    double fa = f(a);
    for (double b = from + step; b <= until + step; b += step) {
        const double fb = f(b);
        if (fa < 0 && fb >= 0) {
            double lo = a;
            double hi = b;
            for (int k = 0; k < 80 && hi - lo > 1e-15 * hi; ++k) {
                const double mid = (lo + hi) / 2;
                (f(mid) < 0 ? lo : hi) = mid;
            }
            return hi;
        }
        a = b;
        fa = fb;
    }
    return std::nullopt;
}

}  // namespace

std::optional<double> measured_period(const pendulum::motion& m) {
    if (!m.has_period()) return std::nullopt;
    // The known period only sets the stopwatch's step and how long it waits.
    const double step = m.period() / 64;
    if (m.kind() == pendulum::regime::rotation) {
        const double start = m.theta(0);
        const double sign = m.velocity(0) >= 0 ? 1.0 : -1.0;
        return first_rise([&](double t) { return sign * (m.theta(t) - start) - 2 * pi; }, 0.0, 2 * m.period(), step);
    }
    const double center = m.libration_center();
    const auto below = [&](double t) { return m.theta(t) - center; };
    const auto first = first_rise(below, 0.0, 2 * m.period(), step);
    if (!first) return std::nullopt;
    const auto second = first_rise(below, *first + step / 2, *first + 2 * m.period(), step);
    if (!second) return std::nullopt;
    return *second - *first;
}

namespace {

/// The bars' left edge and width of a start's group (rod lengths).
constexpr double bars_left = 1.35;
constexpr double bars_width = 0.9;

/// What one energy bar shows.
enum class bar_kind { kinetic, potential, total };

/// A bar's name in ids, its palette colour and the opacity of its fill (0: an outline only).
struct bar_look {
    const char* name;
    int color;
    double fill;
    const char* label;
};

constexpr bar_look bar_looks[] = {
    // A legend entry each, in the bar's colour, in their order from the left.
    {"kinetic", 2, 0.55, "kinetic <i>E</i><sub>kin</sub>"},
    {"potential", 1, 0.25, "potential <i>E</i><sub>pot</sub>"},
    {"total", 0, 0.0, "total <i>E</i> (unit <i>m g L</i>)"},
};

/// Adds bar `kind` of start i (of n) with height `value` of `largest`: an outline, filled by
/// vertical strokes; the first start's outline carries the legend entry.
void add_bar(plot::panel& panel, bar_kind kind, std::size_t i, std::size_t n, double value, double largest) {
    const bar_look& look = bar_looks[static_cast<int>(kind)];
    const double group = bars_width / static_cast<double>(n);
    const double slot = group / 3;
    const double x0 = bars_left + group * static_cast<double>(i) + slot * static_cast<int>(kind) + 0.15 * slot;
    const double x1 = x0 + 0.7 * slot;
    const double y0 = energy_bars_base;
    const double y1 = y0 + energy_bars_height * value / largest;
    const std::string id = std::string(look.name) + ":" + std::to_string(i + 1);
    if (look.fill > 0) {
        plot::series fill;
        fill.id = "energy-fill:" + id;
        fill.color = look.color;
        fill.alpha = look.fill;
        fill.width_scale = 1.0;
        constexpr int strokes = 24;
        for (int k = 0; k <= strokes; ++k) {
            const double x = x0 + (x1 - x0) * k / strokes;
            fill.x.insert(fill.x.end(), {x, x, std::nan("")});
            fill.y.insert(fill.y.end(), {y0, y1, std::nan("")});
        }
        panel.data.push_back(std::move(fill));
    }
    plot::series outline;
    outline.id = "energy:" + id;
    outline.color = look.color;
    outline.x = {x0, x1, x1, x0, x0};
    outline.y = {y0, y0, y1, y1, y0};
    if (i == 0 && *look.label != '\0') outline.label = plot::label(look.label);
    panel.data.push_back(std::move(outline));
}

/// The largest total energy of the panel's starts: the full height of the bars.
double largest_energy(const std::vector<overlay_start>& starts) {
    double most = 0;
    for (const auto& s : starts) most = std::max(most, s.motion.energy());
    return most;
}

/// An arrow from (x, y) along (dx, dy): its shaft and, unless it has no length, its head.
void add_arrow(plot::panel& panel, const std::string& id, int color, line_style line, double x, double y, double dx,
               double dy, const std::string& label) {
    plot::series shaft;
    shaft.id = "arrow:" + id;
    shaft.color = color;
    shaft.line = line;
    shaft.width_scale = 1.3;
    shaft.x = {x, x + dx};
    shaft.y = {y, y + dy};
    if (!label.empty()) shaft.label = plot::label(label);
    panel.data.push_back(std::move(shaft));
    const double length = std::hypot(dx, dy);
    if (!(length > 0)) return;
    const double head = std::min(0.08, 0.45 * length);
    const double ux = dx / length;
    const double uy = dy / length;
    plot::series tip;
    tip.id = "arrowhead:" + id;
    tip.color = color;
    tip.width_scale = 1.3;
    const double bx = x + dx - head * ux;
    const double by = y + dy - head * uy;
    tip.x = {bx - 0.5 * head * uy, x + dx, bx + 0.5 * head * uy};
    tip.y = {by + 0.5 * head * ux, y + dy, by - 0.5 * head * ux};
    panel.data.push_back(std::move(tip));
}

/// A number with three significant digits for the legend.
std::string short_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

/// The arrows' legend entries: what the longest arrow of the panel stands for.
std::string arrow_label(const figure_spec& spec, bool velocity, double most) {
    const std::string what = velocity ? "velocity <i>v</i>" : "acceleration <i>a</i>";
    if (spec.pendulum) {
        const double l = spec.pendulum->length_m;
        const double g = spec.pendulum->g;
        return what + " (longest " +
               (velocity ? short_number(most * std::sqrt(g * l)) + " m/s)" : short_number(most * g) + " m/s<sup>2</sup>)");
    }
    return what + " (longest " + short_number(most) + (velocity ? " <i>ω</i><sub>0</sub><i>L</i>)" : " <i>g</i>)");
}

/// Each start's velocity and acceleration arrows on its exact bob, scaled once for the
/// panel (the whole motion of every start) so that the longest is longest_arrow.
void add_arrows(plot::panel& panel, const panel_context& c, const panel_spec& p,
                const std::vector<overlay_start>& starts, double w0_t) {
    double most_v = 0;
    double most_a = 0;
    for (const auto& s : starts) {
        most_v = std::max(most_v, largest_speed(s.motion));
        most_a = std::max(most_a, largest_acceleration(s.motion));
    }
    for (std::size_t i = 0; i < starts.size(); ++i) {
        const auto& m = starts[i].motion;
        const double a = m.theta(w0_t);
        const double x = std::sin(a);
        const double y = -std::cos(a);
        const bob_vectors v = vectors_at(m, w0_t);
        const std::string n = std::to_string(i + 1);
        if (p.velocity_arrows && most_v > 0) {
            const double k = longest_arrow / most_v;
            add_arrow(panel, "velocity:" + n, 3, line_style::solid, x, y, k * v.vx, k * v.vy,
                      i == 0 ? arrow_label(c.spec, true, most_v) : "");
        }
        if (p.acceleration_arrows && most_a > 0) {
            const double k = longest_arrow / most_a;
            add_arrow(panel, "acceleration:" + n, 5, line_style::dashed, x, y, k * v.ax, k * v.ay,
                      i == 0 ? arrow_label(c.spec, false, most_a) : "");
        }
    }
}

/// A time w0 t in the timer's unit: seconds with a [pendulum] table, else T0.
std::string timer_time(const figure_spec& spec, double w0_t) {
    char buf[64];
    if (spec.pendulum) {
        std::snprintf(buf, sizeof buf, "%.3f s", w0_t * pendulum::seconds_per_radian(spec.pendulum->length_m, spec.pendulum->g));
    } else {
        std::snprintf(buf, sizeof buf, "%.4f <i>T</i><sub>0</sub>", w0_t / (2 * pi));
    }
    return buf;
}

}  // namespace

void add_overlays_still(plot::panel& panel, const panel_spec& p, const std::vector<overlay_start>& starts,
                        bool clock) {
    // The line of the timer or of an animation's clock: the plot layer keeps it above the
    // drawing, beside its label, measured in points (never over a bob near the top).
    panel.overlay_line = p.timer || clock;
    if (!p.energy_bars || starts.empty()) return;
    panel.x.max = energy_bars_right;
    const double largest = largest_energy(starts);
    for (std::size_t i = 0; i < starts.size(); ++i) {
        add_bar(panel, bar_kind::total, i, starts.size(), starts[i].motion.energy(), largest);
    }
}

void add_overlays_at(plot::panel& panel, const panel_context& c, const panel_spec& p,
                     const std::vector<overlay_start>& starts, double w0_t) {
    if (p.energy_bars && !starts.empty()) {
        const double largest = largest_energy(starts);
        for (std::size_t i = 0; i < starts.size(); ++i) {
            const bob_energies e = energies_at(starts[i].motion, w0_t);
            add_bar(panel, bar_kind::kinetic, i, starts.size(), e.kinetic, largest);
            add_bar(panel, bar_kind::potential, i, starts.size(), e.potential, largest);
        }
    }
    if (p.velocity_arrows || p.acceleration_arrows) add_arrows(panel, c, p, starts, w0_t);
    // A still figure shows what the timer ends on: each measured period.
    const double shown = c.animated ? w0_t : std::numeric_limits<double>::infinity();
    if (p.timer) panel.overlay_label = plot::label(timer_text(c.spec, starts, shown, c.frame_step));
}

std::string timer_text(const figure_spec& spec, const std::vector<overlay_start>& starts, double w0_t,
                       double frame_step) {
    // One line, the first start's: several starts are told apart by their label.
    std::string out;
    for (const auto& s : starts) {
        if (!out.empty()) break;
        if (starts.size() > 1) out += s.label + ": ";
        const auto period = measured_period(s.motion);
        // The frame nearest the completion shows it: an animation of one period ends there.
        if (period && w0_t + frame_step / 2 >= *period * (1 - 1e-12)) {
            out += "<i>T</i> = " + timer_time(spec, *period);
        } else if (!std::isfinite(w0_t)) {
            out += "no period (the separatrix)";
        } else {
            out += "timer " + timer_time(spec, w0_t) + (period ? "" : " (no period)");
        }
    }
    return out;
}

}  // namespace figures
