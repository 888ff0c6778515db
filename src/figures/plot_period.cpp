// SPDX-License-Identifier: GPL-3.0-or-later
// The period plot: T/T0 of each method against the amplitude, or its error.
#include "figures/plot_builders.hpp"

#include "figures/data_series.hpp"
#include "figures/panel_support.hpp"
#include "pendulum/formula.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/motion.hpp"

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

/// The exact period against the energy E (per m g L) launched from the bottom: T/T0 of the
/// libration below the separatrix, the revolution's T/T0 above it, each curve stopping short
/// of E = 2, where both diverge, and a vertical line marking the separatrix.
/// One side of the separatrix against the energy, from `from` to `to`, its own curve (the
/// i-th: libration solid, rotation dashed), sampled up to `top`.
plot::series energy_piece(const series_style& st, std::size_t i, double from, double to, const char* label,
                          const std::function<double(double)>& period, double top) {
    plot::series s = series_of(st);
    s.label = plot::label(label);
    s.line = i == 0 ? line_style::solid : line_style::dashed;
    s.marker = marker_style::none;
    s.style_key.clear();
    s.color = static_cast<int>(i);
    // Just short of E = 2: the curve leaves the axis long before (T = 4 T0 at 2 - 4.5e-4).
    const double a = from == 2.0 ? std::nextafter(2.0, 3.0) : from;
    const double b = to == 2.0 ? std::nextafter(2.0, 1.0) : to;
    for (double e : grid(a, b, 200)) {
        const double v = period(e);
        if (!(v <= top)) continue;
        s.x.push_back(e);
        s.y.push_back(v);
    }
    s.curve = plot::function_curve(a, b, period);
    return s;
}

/// The dotted vertical line of the separatrix at E = 2.
plot::series energy_separatrix(const panel_spec& p, double top) {
    plot::series line;
    line.label = "separatrix, <i>E</i> = 2";
    line.line = line_style::dotted;
    line.rgb_color = plot::rgb{0.5, 0.5, 0.5};
    line.autoscale = false;
    line.x = {2, 2};
    line.y = {p.y_range ? (*p.y_range)[0] : 0.0, top};
    return line;
}

plot::panel energy_period_panel(const panel_context& c, const panel_spec& p) {
    const double lo = p.range ? (*p.range)[0] : 0.0;
    const double hi = p.range ? (*p.range)[1] : 4.0;
    plot::panel panel;
    panel.x.label = "<i>E</i>/(<i>m g L</i>)";
    panel.x.min = lo;
    panel.x.max = hi;
    if (c.width_cm < 5) panel.x.max_ticks = 3;
    const double seconds = c.spec.pendulum ? 2 * pi * seconds_per_radian(c.spec) : 1.0;
    panel.y.label = c.spec.pendulum ? "<i>T</i> (s)" : "<i>T</i>/<i>T</i><sub>0</sub>";
    // The divergence is logarithmic: the axis stops at 4 T0 (2 - E = 4.5e-4 below the separatrix).
    panel.y.min = 0;
    panel.y.max = 4 * seconds;
    const double top = p.y_range ? (*p.y_range)[1] : *panel.y.max;
    const std::function<double(double)> period = [seconds](double e) {
        if (e == 0) return seconds;  // the limit of small swings
        if (e == 2) return std::nan("");
        return seconds * pendulum::motion::from_energy(e).period_ratio();
    };
    struct piece {
        double from, to;
        const char* label;
    };
    // Each side of the separatrix its own curve, none drawn through it.
    const piece pieces[] = {{lo, std::min(hi, 2.0), "libration, period <i>T</i>"},
                            {std::max(lo, 2.0), hi, "rotation, one revolution"}};
    const series_style st = style_of(p.methods.front(), 0);
    for (std::size_t i = 0; i < 2; ++i) {
        const auto& [from, to, label] = pieces[i];
        if (from < to) panel.data.push_back(energy_piece(st, i, from, to, label, period, top));
    }
    if (lo < 2 && 2 < hi) panel.data.push_back(energy_separatrix(p, top));
    return panel;
}

plot::panel period_curves_panel(const panel_context& c, const panel_spec& p);

/// The period axis' unit: seconds with [pendulum], else T/T0.
data_unit period_unit(const panel_context& c) {
    return c.spec.pendulum ? data_unit::seconds : data_unit::period_ratio;
}

/// The reference of a residual panel: residual_of, or the exact period.
pendulum::method_choice residual_reference(const panel_spec& p) {
    return p.residual_of ? *p.residual_of : pendulum::parse_method("exact");
}

/// The label of the residual axis, (T_meas - T_ref)/T0: measured minus reference, in T0.
std::string residual_label(const panel_spec& p) {
    const auto ref = residual_reference(p);
    const std::string sub = ref.is_exact() ? "" : "<sub>" + plot::escape_markup(ref.text()) + "</sub>";
    return "(<i>T</i><sub>meas</sub> \u2212 <i>T</i>" + sub + ")/<i>T</i><sub>0</sub>";
}

/// A residual panel: each method's (T_m - T_ref)/T0 as a curve, the reference itself a zero
/// line with its legend entry, and the data's residuals (added by the caller).
void add_residual_curves(plot::panel& panel, const panel_spec& p, double lo, double hi) {
    const auto ref = residual_reference(p);
    plot::series zero;
    zero.label = method_label(ref);
    zero.x = {to_axis_angle(p, lo), to_axis_angle(p, hi)};
    zero.y = {0, 0};
    zero.line = line_style::solid;
    zero.width_scale = 0.6;
    panel.data.push_back(std::move(zero));
    const auto curve = curve_amplitudes(lo, hi);
    for (std::size_t i = 0; i < p.methods.size(); ++i) {
        const auto& m = p.methods[i];
        if (m.method.text() == ref.text()) continue;
        const std::function<double(double)> residual = [method = m.method, ref](double t) {
            return pendulum::method_period(method, t) - pendulum::method_period(ref, t);
        };
        auto s = make_series(style_of(m, static_cast<int>(i)), curve, residual);
        for (double& v : s.x) v = to_axis_angle(p, v);
        if (s.line == line_style::none) {
            // The exact period's circles become a line here: a residual is a curve.
            s.line = line_style::solid;
            s.marker = marker_style::none;
            s.style_key.clear();
        }
        s.curve = amplitude_curve(p, curve.front(), curve.back(), residual);
        panel.data.push_back(std::move(s));
    }
}

/// The panel's measured data on its axes: amplitudes (or energies) across, periods in the
/// axis' unit, or their residuals from the reference, (T_meas - T_ref)/T0.
void add_period_data(plot::panel& panel, const panel_context& c, const panel_spec& p) {
    if (p.data.empty()) return;
    const double t0 = small_period_seconds_of(c.spec);
    data_placement at;
    at.x_factor = [&p, t0](data_unit u) {
        return p.energy_axis ? 1.0 : unit_factor(u, angle_axis_unit(p), t0, 1.0);
    };
    at.y_factor = [&](data_unit u) {
        if (p.y == period_axis::value) return unit_factor(u, period_unit(c), t0, 1.0);
        if (p.y == period_axis::residual) return unit_factor(u, data_unit::period_ratio, t0, 1.0);
        return 1.0;
    };
    if (p.y == period_axis::residual) {
        at.y_offset = [ref = residual_reference(p), degrees = p.degrees](double x) {
            const double theta = degrees ? x * pi / 180 : x;
            return -pendulum::method_period(ref, theta);
        };
    }
    add_data_series(panel, p, at);
}

}  // namespace

plot::panel period_panel(const panel_context& c, const panel_spec& p) {
    plot::panel panel = period_curves_panel(c, p);
    add_period_data(panel, c, p);
    return panel;
}

namespace {

/// The y axis of a period panel against the amplitude: its label, and a log scale for
/// log |error|.
void period_y_axis(plot::panel& panel, const panel_context& c, const panel_spec& p) {
    switch (p.y) {
        case period_axis::value:
            panel.y.label = c.spec.pendulum ? "<i>T</i> (s)" : "<i>T</i>/<i>T</i><sub>0</sub>";
            break;
        case period_axis::error_percent: panel.y.label = "relative error (%)"; break;
        case period_axis::error_log:
            panel.y.label = "|<i>T</i><sub><i>m</i></sub>/<i>T</i> \u2212 1|";
            panel.y.kind = plot::scale::log;
            panel.y.max_ticks = 9;
            break;
        case period_axis::residual: panel.y.label = residual_label(p); break;
    }
}

/// A method's period against the amplitude (in seconds with [pendulum]).
plot::series period_series(const panel_spec& p, const method_spec& m, const series_style& st,
                           const std::vector<double>& curve, double lo, double hi, double seconds) {
    const std::function<double(double)> period = [method = m.method, seconds](double t) {
        return seconds * pendulum::method_period(method, t);
    };
    auto s = make_series(st, is_exact(m) ? circle_amplitudes(lo, hi) : curve, period);
    for (double& v : s.x) v = to_axis_angle(p, v);
    s.curve = amplitude_curve(p, curve.front(), curve.back(), period);
    return s;
}

/// A method's period error against the amplitude, in per cent or as log |error|: without
/// cancellation (MPFR where the periods agree closely), right to 1e-12.
plot::series error_series(const panel_spec& p, const method_spec& m, const series_style& st,
                          const std::vector<double>& curve) {
    const auto error = [method = m.method, percent = p.y == period_axis::error_percent](double t) {
        const auto err = pendulum::method_period_error(method, t);
        using kind = pendulum::period_error::kind;
        if (err.what == kind::no_period || err.what == kind::not_computed) return std::nan("");
        if (percent) return 100 * err.value;  // 0 below 1e-300
        // Below 1e-300 an error has no place on a log axis of doubles.
        return err.what == kind::value && err.value != 0 ? std::fabs(err.value) : std::nan("");
    };
    plot::series s = series_of(st);
    for (const double t : curve) {
        s.x.push_back(to_axis_angle(p, t));
        s.y.push_back(error(t));
    }
    s.curve = amplitude_curve(p, curve.front(), curve.back(), error);
    return s;
}

plot::panel period_curves_panel(const panel_context& c, const panel_spec& p) {
    if (p.energy_axis) return energy_period_panel(c, p);
    const double lo = p.range ? (*p.range)[0] : 0.0;
    const double hi = p.range ? (*p.range)[1] : pi;
    plot::panel panel;
    panel.x = amplitude_axis(p, lo, hi);
    if (c.width_cm < 5) panel.x.max_ticks = 3;
    const double seconds = c.spec.pendulum ? 2 * pi * seconds_per_radian(c.spec) : 1.0;
    period_y_axis(panel, c, p);
    if (p.y == period_axis::residual) {
        add_residual_curves(panel, p, lo, hi);
        return panel;
    }
    const auto curve = curve_amplitudes(lo, hi);
    for (std::size_t i = 0; i < p.methods.size(); ++i) {
        const auto& m = p.methods[i];
        const series_style st = style_of(m, static_cast<int>(i));
        if (m.method.user) check_formula_finite(m.method, curve, [f = m.method.user](double t) { return f->value(t); });
        if (p.y == period_axis::value) {
            panel.data.push_back(period_series(p, m, st, curve, lo, hi, seconds));
        } else if (!is_exact(m)) {  // the exact method's error is zero
            panel.data.push_back(error_series(p, m, st, curve));
        }
    }
    return panel;
}

}  // namespace

}  // namespace figures
