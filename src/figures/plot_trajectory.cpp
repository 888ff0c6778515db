// SPDX-License-Identifier: GPL-3.0-or-later
// The trajectory plot: theta(t) of each method at one amplitude.
#include "figures/plot_builders.hpp"

#include "figures/data_series.hpp"
#include "figures/errors.hpp"
#include "figures/panel_support.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/formula.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/motion.hpp"
#include "pendulum/phase.hpp"
#include "pendulum/time_reduction.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>

namespace figures {

using plot::line_style;
using plot::marker_style;
using std::numbers::pi;

namespace {

/// The panel's measured data: times in the time axis' unit (`period_ratio` is the motion's
/// T/T0, for times in t/T), angles in the angle axis'.
void add_trajectory_data(plot::panel& panel, const panel_context& c, const panel_spec& p, double period_ratio) {
    if (p.data.empty()) return;
    const double t0 = small_period_seconds_of(c.spec);
    const data_unit axis = p.time == time_unit::seconds        ? data_unit::seconds
                           : p.time == time_unit::small_period ? data_unit::small_period
                                                               : data_unit::period;
    for (const auto& d : p.data) {
        if (d.x_unit == data_unit::period && !std::isfinite(period_ratio)) {
            throw bad_input("data in x_unit = \"t/T\": this panel's motion has no period T; give the times in "
                            "\"t/T0\" or \"s\"");
        }
    }
    data_placement at;
    at.x_factor = [=](data_unit u) { return unit_factor(u, axis, t0, period_ratio); };
    at.y_factor = [&p, t0](data_unit u) { return unit_factor(u, angle_axis_unit(p), t0, 1.0); };
    add_data_series(panel, p, at);
}


/// w0 t per unit of a start's time axis, and the axis label: the motion's own period T (a
/// rotation's revolution), T0, or seconds.
std::pair<double, std::string> start_time_unit(const figure_spec& spec, const panel_spec& p, const pendulum::motion& m) {
    if (p.time == time_unit::small_period) return {2 * pi, "<i>t</i>/<i>T</i><sub>0</sub>"};
    if (p.time == time_unit::seconds) return {1 / seconds_per_radian(spec), "<i>t</i> (s)"};
    return {m.period(), m.kind() == pendulum::regime::rotation ? "<i>t</i>/<i>T</i><sub>rev</sub>" : "<i>t</i>/<i>T</i>"};
}

/// The time cursor of an animated trajectory: a faint vertical line at x, with its start's id.
plot::series time_cursor(double x, const std::string& id) {
    plot::series cursor;
    cursor.id = id;
    cursor.x = {x, x};
    cursor.y = {-1e5, 1e5};
    cursor.autoscale = false;
    cursor.alpha = 0.5;
    cursor.width_scale = 0.6;
    return cursor;
}

/// theta(w0 t) of a method for a start: the exact motion, unwrapped, or an approximant of a
/// libration on the libration's own clock.
std::function<double(double)> start_theta(const method_spec& m, const pendulum::motion& motion) {
    if (is_exact(m)) return [motion](double w0_t) { return motion.theta(w0_t); };
    return [motion, solution = pendulum::method_solution(m.method, motion.amplitude())](double w0_t) {
        return motion.libration_center() + solution.theta(motion.libration_clock(w0_t));
    };
}

/// theta(s), s = t/T, of an approximant at amplitude a for times up to `largest` in size: its
/// phase (w/w0) w0 t reduced exactly with its own w/w0 from the exact amplitude (time_reducer
/// with the solution's exact source), so that the figure's numbers are the trajectory
/// command's at any time.
std::function<double(double)> approximant_theta(const pendulum::method_choice& method, const pendulum::amplitude& a,
                                                double largest, double period, double angle) {
    auto solution = std::make_shared<const pendulum::fourier_solution>(pendulum::method_solution(method, a));
    if (!solution->exists()) {
        return [solution, period, angle](double s) { return angle * solution->theta(s * period); };
    }
    auto reduce = std::make_shared<const pendulum::time_reducer>(a, pendulum::time_scale{}, largest, *solution);
    return [solution, reduce, angle](double s) { return angle * solution->theta_at_phase(reduce->phase(s)); };
}

/// The unit of a start panel's time axis as time_reducer takes it.
pendulum::time_scale start_time_scale(const figure_spec& spec, const panel_spec& p) {
    if (p.time == time_unit::small_period) return {pendulum::time_scale::unit::small_periods};
    if (p.time == time_unit::seconds) {
        return {pendulum::time_scale::unit::seconds, spec.pendulum->length_m, spec.pendulum->g};
    }
    return {};
}

/// theta(x) of a start's exact motion at x in the axis' unit (w0 t = x unit), as the
/// trajectory command computes it: x reduced modulo the motion's period exactly (time_reducer,
/// for times up to `largest`) and a rotation's whole revolutions added back exactly. The
/// separatrix has no period.
std::function<double(double)> exact_start_theta(const pendulum::motion& motion, const pendulum::time_scale& ts,
                                                double unit, double largest) {
    if (!motion.has_period()) return [motion, unit](double x) { return motion.theta(x * unit); };
    // A reducer keeps the last reduction's whole periods: one caller at a time.
    struct clock {
        clock(const pendulum::motion& m, const pendulum::time_scale& ts, double largest) : reduce(m, ts, largest) {}
        pendulum::time_reducer reduce;
        std::mutex lock;
    };
    auto c = std::make_shared<clock>(motion, ts, largest);
    return [motion, c](double x) {
        const std::lock_guard<std::mutex> hold(c->lock);
        return pendulum::point_at(motion, c->reduce, x).theta;
    };
}

/// A trajectory of one start (energy or state): theta(t) unwrapped, a rotation's angle rising.
plot::panel start_trajectory_panel(const panel_context& c, const panel_spec& p) {
    const motion_start& start = p.starts.front();
    const auto [unit, x_label] = start_time_unit(c.spec, p, start.motion);
    // Default: one period of the motion (T0 on the separatrix), in the axis' unit.
    const double one = (start.motion.has_period() ? start.motion.period() : 2 * pi) / unit;
    const double lo = p.range ? (*p.range)[0] : 0.0;
    const double hi = p.range ? (*p.range)[1] : one;
    const double cycles = (hi - lo) * unit / (start.motion.has_period() ? start.motion.period() : 2 * pi);
    plot::panel panel;
    panel.label = start.label + ", " + std::string(pendulum::row_of(start.motion.kind()).name);
    panel.x.label = x_label;
    panel.x.min = lo;
    panel.x.max = hi;
    panel.x.max_ticks = c.width_cm < 5 ? 3 : 6;
    panel.y.label = "<i>\u03d1</i>";
    panel.y.ticks = p.degrees ? plot::tick_kind::degrees : plot::tick_kind::multiples_of_pi;
    panel.y.max_ticks = 7;
    panel.y.round_limits = true;
    panel.y.margin = 0.002;
    const double angle = p.degrees ? 180 / pi : 1.0;
    const int pieces = std::clamp(static_cast<int>(std::lround(8 * cycles)), 8, 4000);
    const int circles = std::clamp(static_cast<int>(std::lround(24 * cycles)), 2, 2400);
    for (std::size_t i = 0; i < p.methods.size(); ++i) {
        const auto& m = p.methods[i];
        const std::function<double(double)> f =
            is_exact(m) ? exact_start_theta(start.motion, start_time_scale(c.spec, p), unit,
                                            std::max(std::fabs(lo), std::fabs(hi)))
                        : [g = start_theta(m, start.motion), unit = unit](double x) { return g(x * unit); };
        const auto theta = [f, angle](double x) { return angle * f(x); };
        panel.data.push_back(make_series(style_of(m, static_cast<int>(i)), grid(lo, hi, is_exact(m) ? circles : 300), theta));
        panel.data.back().curve =
            plot::parametric_curve(lo, hi, [theta](double x) { return std::pair{x, theta(x)}; }, pieces);
        panel.data.back().sets_limits = is_exact(m);
    }
    add_trajectory_data(panel, c, p,
                        start.motion.has_period() ? start.motion.period_ratio() : std::numeric_limits<double>::quiet_NaN());
    return panel;
}

}  // namespace

plot::panel trajectory_panel(const panel_context& c, const panel_spec& p) {
    if (!p.starts.empty()) return start_trajectory_panel(c, p);
    // parse_spec refuses an empty list; a panel without a start is a bug, never a crash.
    if (p.theta0.empty()) throw std::logic_error("a trajectory panel without a start or an amplitude");
    const amplitude& a = p.theta0.front();
    const pendulum::exact_solution exact(a.theta0());
    const double period = 4 * exact.quarter_period();  // T in units of 1/w0
    // x = s * unit with s = t/T.
    const auto [unit, x_label] = time_unit_of(c.spec, p, exact);
    const double lo = p.range ? (*p.range)[0] / unit : 0.0;
    const double hi = p.range ? (*p.range)[1] / unit : 1.0;
    const auto scaled = [unit = unit](std::vector<double> s) {
        if (unit != 1.0) {
            for (double& v : s) v *= unit;
        }
        return s;
    };
    const double span = hi - lo;
    // 300 points and 24 circles a period (the spec reader bounds the periods).
    const int circles = std::max(2, static_cast<int>(std::lround(24 * span)));
    const int points = std::max(300, static_cast<int>(std::lround(300 * span)));
    plot::panel panel;
    panel.label = std::string(theta0_markup) + " = " + typeset_angle(a.text);
    panel.x.label = x_label;
    panel.x.min = lo * unit;
    panel.x.max = hi * unit;
    panel.x.max_ticks = c.width_cm < 5 ? 3 : 6;
    panel.y.label = "<i>\u03d1</i>";
    if (p.degrees) {
        panel.y.ticks = plot::tick_kind::degrees;
        panel.y.max_ticks = 7;
    } else {
        panel.y.ticks = plot::tick_kind::multiples_of_pi;
        panel.y.max_ticks = 7;
    }
    panel.y.round_limits = true;
    panel.y.margin = 0.002;  // just enough to keep the curve off the frame at a tick
    const double angle = p.degrees ? 180 / pi : 1.0;
    // The lines are drawn from theta(s), first cut into eight pieces a period.
    const int pieces = std::max(8, static_cast<int>(std::lround(8 * span)));
    for (std::size_t i = 0; i < p.methods.size(); ++i) {
        const auto& m = p.methods[i];
        const series_style st = style_of(m, static_cast<int>(i));
        std::function<double(double)> theta;  // of s = t/T
        if (is_exact(m)) {
            theta = [exact, angle](double s) { return angle * exact.theta_at_fraction(s); };
        } else if (m.method.user) {
            // A user's theta(t) = f(t, theta0), t = w0 t.
            theta = [f = m.method.user, t0 = a.theta0().radians(), period, angle](double s) {
                return angle * f->value(t0, s * period);
            };
            check_formula_finite(m.method, grid(lo, hi, points), [&theta](double s) { return theta(s); });
        } else {
            theta = approximant_theta(m.method, a.theta0(), std::max(std::fabs(lo), std::fabs(hi)), period, angle);
        }
        panel.data.push_back(make_series(st, grid(lo, hi, is_exact(m) ? circles : points), theta));
        panel.data.back().x = scaled(std::move(panel.data.back().x));
        panel.data.back().curve = plot::parametric_curve(
            lo, hi, [theta, unit = unit](double s) { return std::pair{s * unit, theta(s)}; }, pieces);
    }
    // The exact motion sets the angle axis; an approximation that overshoots it near the
    // separatrix is clipped rather than stretching the axis.
    if (std::any_of(p.methods.begin(), p.methods.end(), [](const auto& m) { return is_exact(m); })) {
        for (std::size_t i = 0; i < p.methods.size(); ++i) panel.data[i].sets_limits = is_exact(p.methods[i]);
    }
    add_trajectory_data(panel, c, p, exact.period_ratio());
    return panel;
}

void add_trajectory_frame(plot::panel& panel, const panel_context& c, const panel_spec& p, double w0_t) {
    const double angle = p.degrees ? 180 / pi : 1.0;
    const std::size_t starts = p.starts.size() + p.theta0.size();
    std::size_t i = 0;
    for (const auto& start : p.starts) {
        const double x_now = w0_t / start_time_unit(c.spec, p, start.motion).first;
        panel.data.push_back(time_cursor(x_now, start_id("cursor", i, starts)));
        for (std::size_t j = 0; j < p.methods.size(); ++j) {
            plot::series dot = moving_dot(style_of(p.methods[j], static_cast<int>(j)), i, starts);
            dot.x = {x_now};
            dot.y = {angle * start_theta(p.methods[j], start.motion)(w0_t)};
            panel.data.push_back(std::move(dot));
        }
        ++i;
    }
    for (const auto& a : p.theta0) {
        const pendulum::exact_solution exact(a.theta0());
        const double period = 4 * exact.quarter_period();
        // The time cursor.
        const double x_now = w0_t / period * time_unit_of(c.spec, p, exact).first;
        panel.data.push_back(time_cursor(x_now, start_id("cursor", i, starts)));
        for (std::size_t j = 0; j < p.methods.size(); ++j) {
            plot::series dot = moving_dot(style_of(p.methods[j], static_cast<int>(j)), i, starts);
            dot.x = {x_now};
            dot.y = {angle * state_at(p.methods[j], exact, w0_t).first};
            panel.data.push_back(std::move(dot));
        }
        ++i;
    }
}

}  // namespace figures
