// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/spec_build.hpp"

#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/phase.hpp"
#include "plot/tex_markup.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace figures {

using plot::line_style;
using plot::marker_style;
using std::numbers::pi;

namespace {

const char* const theta0_markup = "<i>\u03d1</i><sub>0</sub>";

/// n + 1 evenly spaced values over [a, b], the last exactly b.
std::vector<double> grid(double a, double b, int n) {
    std::vector<double> v;
    v.reserve(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) v.push_back(i == n ? b : a + (b - a) * i / n);
    return v;
}

std::string panel_letter(std::size_t i) { return "(" + panel_name(i) + ")"; }

/// How a method's series looks: the theme's defaults unless the spec overrides them.
struct series_style {
    std::string label;
    line_style line;
    marker_style marker;
    int color;
    std::string style_key;
    std::optional<plot::rgb> rgb_color = std::nullopt;
};

series_style style_of(const method_spec& m, int index) {
    series_style s{m.label.empty() ? method_label(m.method) : plot::tex_to_markup(m.label), method_line(m.method),
                   m.method.row->name == "exact" ? marker_style::open_circle : marker_style::none, index, ""};
    // The theme styles a method by name unless the spec says how it looks.
    if (!m.style && !m.marker) s.style_key = std::string(m.method.row->name);
    if (m.style) s.line = *m.style;
    if (m.marker) s.marker = *m.marker;
    s.rgb_color = m.color;
    return s;
}

/// An empty series in the style.
plot::series series_of(const series_style& st) {
    plot::series s;
    s.label = st.label;
    s.line = st.line;
    s.marker = st.marker;
    s.color = st.color;
    s.style_key = st.style_key;
    s.rgb_color = st.rgb_color;
    return s;
}

plot::series make_series(const series_style& st, std::vector<double> x, const std::function<double(double)>& f) {
    plot::series s = series_of(st);
    s.y.reserve(x.size());
    for (double v : x) s.y.push_back(f(v));
    s.x = std::move(x);
    return s;
}

bool is_exact(const method_spec& m) { return m.method.row->name == "exact"; }

/// The amplitude axis over [lo, hi], in multiples of pi or in degrees.
plot::axis amplitude_axis(const panel_spec& p, double lo, double hi) {
    plot::axis a;
    a.label = theta0_markup;
    a.min = lo;
    a.max = hi;
    a.ticks = plot::tick_kind::multiples_of_pi;
    a.max_ticks = 5;
    if (p.degrees) {
        a.ticks = plot::tick_kind::degrees;
        a.min = lo * 180 / pi;
        a.max = hi * 180 / pi;
    }
    return a;
}

double to_axis_angle(const panel_spec& p, double theta) { return p.degrees ? theta * 180 / pi : theta; }

/// Amplitudes where the exact values are marked (multiples of pi/24) and the fine grid for
/// curves, inside the panel's range; the approximants are defined on (0, pi).
std::vector<double> circle_amplitudes(double lo, double hi) {
    std::vector<double> a;
    for (int k = 1; k <= 23; ++k) {
        const double t = k * pi / 24;
        if (t >= lo && t <= hi) a.push_back(t);
    }
    return a;
}

std::vector<double> curve_amplitudes(double lo, double hi) {
    return grid(std::max(lo, 1e-3), std::min(hi, pi - 1e-3), 400);
}

struct context {
    const figure_spec& spec;
    double width_cm;
    bool animated;  // the moving parts are added frame by frame
};

/// Seconds per unit of w0 t, for a spec with a [pendulum].
double seconds_per_radian(const figure_spec& spec) { return std::sqrt(spec.pendulum->length_m / spec.pendulum->g); }

/// The x value of a trajectory panel at t = s T, its unit per exact period, and its label.
std::pair<double, std::string> time_unit_of(const figure_spec& spec, const panel_spec& p,
                                            const pendulum::exact_solution& exact) {
    if (p.time == time_unit::small_period) return {exact.period_ratio(), "<i>t</i>/<i>T</i><sub>0</sub>"};
    if (p.time == time_unit::seconds) return {4 * exact.quarter_period() * seconds_per_radian(spec), "<i>t</i> (s)"};
    return {1.0, "<i>t</i>/<i>T</i>"};
}

plot::panel trajectory_panel(const context& c, const panel_spec& p) {
    const amplitude& a = p.theta0.front();
    const pendulum::exact_solution exact(a.value);
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
    const int circles = std::max(2, static_cast<int>(std::lround(24 * span)));
    const int points = std::max(300, static_cast<int>(std::lround(300 * span)));
    plot::panel panel;
    panel.label = std::string(theta0_markup) + " = " + typeset_angle(a.text);
    panel.x.label = x_label;
    panel.x.min = lo * unit;
    panel.x.max = hi * unit;
    panel.x.max_ticks = c.width_cm < 5 ? 3 : 5;
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
    for (std::size_t i = 0; i < p.methods.size(); ++i) {
        const auto& m = p.methods[i];
        const series_style st = style_of(m, static_cast<int>(i));
        if (is_exact(m)) {
            panel.data.push_back(make_series(st, grid(lo, hi, circles),
                                             [&](double s) { return angle * exact.theta_at_fraction(s); }));
        } else {
            const auto solution = pendulum::method_solution(m.method, a.value);
            panel.data.push_back(make_series(st, grid(lo, hi, points),
                                             [&](double s) { return angle * solution.theta(s * period); }));
        }
        panel.data.back().x = scaled(std::move(panel.data.back().x));
    }
    // The exact motion sets the angle axis; an approximation that overshoots it near the
    // separatrix is clipped rather than stretching the axis.
    if (std::any_of(p.methods.begin(), p.methods.end(), [](const auto& m) { return is_exact(m); })) {
        for (std::size_t i = 0; i < p.methods.size(); ++i) panel.data[i].sets_limits = is_exact(p.methods[i]);
    }
    return panel;
}

plot::panel coefficient_panel(const context& c, const panel_spec& p) {
    const int n = (p.harmonic - 1) / 2;
    const double lo = p.range ? (*p.range)[0] : 0.0;
    const double hi = p.range ? (*p.range)[1] : pi;
    plot::panel panel;
    panel.x = amplitude_axis(p, lo, hi);
    if (c.width_cm < 5) panel.x.max_ticks = 3;
    panel.y.label = "<i>c</i><sub>" + std::to_string(p.harmonic) + "</sub>";
    for (std::size_t i = 0; i < p.methods.size(); ++i) {
        const auto& m = p.methods[i];
        const series_style st = style_of(m, static_cast<int>(i));
        std::vector<double> x;
        plot::series s;
        if (is_exact(m)) {
            // The exact values from the closed form through the nome. The paper's Eq. (Lamb.12.1),
            // by quadrature in doubles, is right only to about 1e-16 theta0 in absolute terms:
            // c5 at pi/24 (1.9e-9) would be off by 8e-9 of itself.
            s = make_series(st, circle_amplitudes(lo, hi),
                            [n](double t) { return pendulum::exact_solution(t).coefficient(n); });
        } else {
            s = make_series(st, curve_amplitudes(lo, hi), [&](double t) {
                const auto sol = pendulum::method_solution(m.method, t);
                return n < static_cast<int>(sol.coefficients.size()) ? sol.coefficients[static_cast<std::size_t>(n)]
                                                                      : 0.0;
            });
        }
        for (double& v : s.x) v = to_axis_angle(p, v);
        panel.data.push_back(std::move(s));
    }
    return panel;
}

plot::panel period_panel(const context& c, const panel_spec& p) {
    const double lo = p.range ? (*p.range)[0] : 0.0;
    const double hi = p.range ? (*p.range)[1] : pi;
    plot::panel panel;
    panel.x = amplitude_axis(p, lo, hi);
    if (c.width_cm < 5) panel.x.max_ticks = 3;
    const double seconds = c.spec.pendulum ? 2 * pi * seconds_per_radian(c.spec) : 1.0;
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
    }
    // Each period is computed once per amplitude: the exact one for the errors.
    const auto curve = curve_amplitudes(lo, hi);
    std::vector<double> exact;
    if (p.y != period_axis::value) {
        for (double t : curve) exact.push_back(pendulum::period_ratio(t));
    }
    for (std::size_t i = 0; i < p.methods.size(); ++i) {
        const auto& m = p.methods[i];
        const series_style st = style_of(m, static_cast<int>(i));
        if (p.y == period_axis::value) {
            auto s = make_series(st, is_exact(m) ? circle_amplitudes(lo, hi) : curve,
                                 [&](double t) { return seconds * pendulum::method_period(m.method, t); });
            for (double& v : s.x) v = to_axis_angle(p, v);
            panel.data.push_back(std::move(s));
            continue;
        }
        if (is_exact(m)) continue;  // its error is zero
        plot::series s = series_of(st);
        for (std::size_t k = 0; k < curve.size(); ++k) {
            const double err = pendulum::method_period(m.method, curve[k]) / exact[k] - 1;
            s.x.push_back(to_axis_angle(p, curve[k]));
            if (p.y == period_axis::error_percent) {
                s.y.push_back(100 * err);
            } else {
                // Below the rounding of T itself an error means nothing on a log axis.
                s.y.push_back(std::fabs(err) > 1e-16 ? std::fabs(err) : std::nan(""));
            }
        }
        panel.data.push_back(std::move(s));
    }
    return panel;
}

/// Line styles for series that differ by amplitude, in order.
series_style amplitude_style(std::size_t i, const std::string& label) {
    static const line_style cycle[] = {line_style::solid, line_style::dashed, line_style::dotted, line_style::dash_dot};
    return {label, cycle[i % 4], i == 4 ? marker_style::open_circle : marker_style::none, static_cast<int>(i), ""};
}

plot::panel convergence_panel(const context&, const panel_spec& p) {
    plot::panel panel;
    panel.x.label = "order <i>N</i> of the iteration";
    panel.x.min = p.orders[0];
    panel.x.max = p.orders[1];
    panel.y.label = "|<i>T</i><sub><i>N</i></sub>/<i>T</i> \u2212 1|";
    panel.y.kind = plot::scale::log;
    panel.y.min = 1e-16;
    panel.y.max = 1.0;
    panel.y.max_ticks = 9;
    for (std::size_t i = 0; i < p.theta0.size(); ++i) {
        const amplitude& a = p.theta0[i];
        const double exact = pendulum::period_ratio(a.value);
        const auto levels = pendulum::iterated_periods(a.value, p.orders[1]);
        const series_style st = amplitude_style(i, std::string(theta0_markup) + " = " + typeset_angle(a.text));
        plot::series s = series_of(st);
        for (int n = p.orders[0]; n <= p.orders[1]; ++n) {
            const auto& level = levels[static_cast<std::size_t>(n)];
            const double err = std::fabs(level.value / exact - 1);
            // A point is drawn only where it is right to 10 %: its error, the level's rounding
            // and that of T and of the ratio (1 ulp each), is below a tenth of it. Levels
            // without a period (close to pi) are gaps too.
            const double uncertainty = level.rounding / exact + 2 * std::numeric_limits<double>::epsilon();
            s.x.push_back(n);
            s.y.push_back(err >= 10 * uncertainty ? err : std::nan(""));
        }
        panel.data.push_back(std::move(s));
    }
    return panel;
}

plot::panel phase_panel(const context&, const panel_spec& p) {
    plot::panel panel;
    const double angle = p.degrees ? 180 / pi : 1.0;
    panel.x.label = "<i>\u03d1</i>";
    panel.x.ticks = p.degrees ? plot::tick_kind::degrees : plot::tick_kind::multiples_of_pi;
    panel.x.max_ticks = 5;
    panel.y.label = "d<i>\u03d1</i>/d(<i>\u03c9</i><sub>0</sub><i>t</i>)";
    const auto s_grid = grid(0, 1, 400);
    for (std::size_t i = 0; i < p.theta0.size(); ++i) {
        const amplitude& a = p.theta0[i];
        const pendulum::exact_solution exact(a.value);
        const double period = 4 * exact.quarter_period();
        for (std::size_t j = 0; j < p.methods.size(); ++j) {
            const auto& m = p.methods[j];
            // One method: each orbit its own colour; several: a colour per method.
            series_style st = style_of(m, static_cast<int>(p.methods.size() == 1 ? i : j));
            if (i > 0) st.label.clear();  // one legend entry per method
            plot::series s = series_of(st);
            if (is_exact(m)) {
                if (!m.style && !m.marker) {
                    // An orbit reads best as a line, whatever the theme's circles for exact.
                    s.line = line_style::solid;
                    s.marker = marker_style::none;
                    s.style_key.clear();
                }
                for (double t : s_grid) {
                    s.x.push_back(angle * exact.theta_at_fraction(t));
                    s.y.push_back(pendulum::velocity_at_fraction(exact, t));
                }
            } else {
                const auto sol = pendulum::method_solution(m.method, a.value);
                for (double t : s_grid) {
                    s.x.push_back(angle * sol.theta(t * period));
                    s.y.push_back(pendulum::velocity(sol, t * period));
                }
            }
            panel.data.push_back(std::move(s));
        }
    }
    if (p.separatrix) {
        const auto theta = grid(-pi, pi, 400);
        for (double sign : {1.0, -1.0}) {
            plot::series s{sign > 0 ? "separatrix" : "", {}, {}, line_style::dashed, marker_style::none, 0};
            for (double t : theta) {
                s.x.push_back(angle * t);
                s.y.push_back(sign * pendulum::separatrix_velocity(t));
            }
            panel.data.push_back(std::move(s));
        }
    }
    return panel;
}

plot::panel spectrum_panel(const context&, const panel_spec& p) {
    plot::panel panel;
    panel.x.label = "2<i>k</i> + 1";
    panel.x.min = 0;
    panel.x.max = 2 * p.harmonics;
    panel.y.label = "|<i>c</i><sub>2<i>k</i>+1</sub>|";
    panel.y.kind = plot::scale::log;
    panel.y.max_ticks = 8;
    std::size_t index = 0;
    for (std::size_t i = 0; i < p.theta0.size(); ++i) {
        const amplitude& a = p.theta0[i];
        for (const auto& m : p.methods) {
            std::string label = std::string(theta0_markup) + " = " + typeset_angle(a.text);
            if (p.methods.size() > 1) label += ", " + (m.label.empty() ? method_label(m.method) : plot::tex_to_markup(m.label));
            series_style st = amplitude_style(index++, label);
            st.marker = marker_style::open_circle;
            if (m.style) st.line = *m.style;
            plot::series s = series_of(st);
            const std::vector<double> c = is_exact(m)
                                              ? pendulum::fourier_coefficients(a.value, p.harmonics)
                                              : pendulum::method_solution(m.method, a.value).coefficients;
            for (std::size_t k = 0; k < c.size() && static_cast<int>(k) < p.harmonics; ++k) {
                s.x.push_back(static_cast<double>(2 * k + 1));
                // Coefficients below the smallest normal double are noise or underflow.
                s.y.push_back(std::fabs(c[k]) > 1e-300 ? std::fabs(c[k]) : std::nan(""));
            }
            panel.data.push_back(std::move(s));
        }
    }
    return panel;
}

plot::panel pendulum_panel(const context& c, const panel_spec& p) {
    // The drawing: x to the right, y up, the pivot at the origin and a rod of length 1.
    plot::panel panel;
    panel.frameless = true;
    panel.equal_aspect = true;
    panel.x.min = -1.2;
    panel.x.max = 1.2;
    panel.y.min = -1.2;
    panel.y.max = 1.2;
    const double theta0 = p.theta0.front().value;
    // The bob's path, faint, and the amplitude it is released from.
    plot::series path;
    for (double a : grid(0, 2 * pi, 200)) {
        path.x.push_back(std::sin(a));
        path.y.push_back(-std::cos(a));
    }
    path.alpha = 0.2;
    path.width_scale = 0.6;
    panel.data.push_back(std::move(path));
    for (double side : {1.0, -1.0}) {
        plot::series mark;
        mark.x = {0, side * std::sin(theta0)};
        mark.y = {0, -std::cos(theta0)};
        mark.line = line_style::dotted;
        mark.alpha = 0.5;
        mark.width_scale = 0.6;
        panel.data.push_back(std::move(mark));
    }
    if (!c.animated) add_pendulum_state(panel, p, 0.0);
    return panel;
}

plot::panel build_panel(const context& c, const panel_spec& p) {
    switch (p.plot) {
        case plot_kind::pendulum: return pendulum_panel(c, p);
        case plot_kind::trajectory: return trajectory_panel(c, p);
        case plot_kind::coefficient: return coefficient_panel(c, p);
        case plot_kind::period: return period_panel(c, p);
        case plot_kind::convergence: return convergence_panel(c, p);
        case plot_kind::phase: return phase_panel(c, p);
        case plot_kind::spectrum: return spectrum_panel(c, p);
    }
    throw std::logic_error("plot kind without a builder");
}

}  // namespace

std::vector<panel_spec> panels_with(const figure_spec& spec, const build_options& o) {
    if (o.amplitudes.empty()) return spec.panels;
    std::vector<panel_spec> out;
    const auto first_trajectory = std::find_if(spec.panels.begin(), spec.panels.end(),
                                               [](const panel_spec& p) { return p.plot == plot_kind::trajectory; });
    std::vector<const panel_spec*> trajectories;
    for (const auto& p : spec.panels) {
        if (p.plot == plot_kind::trajectory) trajectories.push_back(&p);
    }
    for (const auto& p : spec.panels) {
        if (p.plot == plot_kind::trajectory) {
            if (&p != &*first_trajectory) continue;
            for (std::size_t i = 0; i < o.amplitudes.size(); ++i) {
                panel_spec q = i < trajectories.size() ? *trajectories[i] : p;
                if (i >= trajectories.size()) q.paper_file.clear();
                q.theta0 = {o.amplitudes[i]};
                q.title.reset();
                out.push_back(std::move(q));
            }
            continue;
        }
        panel_spec q = p;
        if (p.plot == plot_kind::phase || p.plot == plot_kind::convergence || p.plot == plot_kind::spectrum) {
            q.theta0 = o.amplitudes;
        } else if (p.plot == plot_kind::pendulum) {
            q.theta0 = {o.amplitudes.front()};
        }
        out.push_back(std::move(q));
    }
    return out;
}

void add_pendulum_state(plot::panel& panel, const panel_spec& p, double w0_t) {
    const double theta0 = p.theta0.front().value;
    const pendulum::exact_solution exact(theta0);
    const double period = 4 * exact.quarter_period();
    for (std::size_t i = 0; i < p.methods.size(); ++i) {
        const auto& m = p.methods[i];
        const auto solution = is_exact(m) ? pendulum::fourier_solution{} : pendulum::method_solution(m.method, theta0);
        const auto theta = [&](double t) {
            return is_exact(m) ? exact.theta_at_fraction(t / period) : solution.theta(t);
        };
        series_style st = style_of(m, static_cast<int>(i));
        st.style_key.clear();
        if (p.trail > 0) {
            // The bob's recent path, fading into the past in eight steps.
            const double span = std::min(p.trail * period, w0_t);
            for (int k = 0; k < 8 && span > 0; ++k) {
                plot::series trail = series_of(st);
                trail.label.clear();
                trail.line = line_style::solid;
                trail.marker = marker_style::none;
                trail.alpha = 0.08 + 0.06 * k;
                for (double t : grid(w0_t - span * (8 - k) / 8, w0_t - span * (7 - k) / 8, 12)) {
                    const double a = theta(t);
                    trail.x.push_back(std::sin(a));
                    trail.y.push_back(-std::cos(a));
                }
                panel.data.push_back(std::move(trail));
            }
        }
        const double a = theta(w0_t);
        plot::series rod = series_of(st);
        rod.line = m.style.value_or(line_style::solid);
        if (rod.line == line_style::none) rod.line = line_style::solid;
        rod.marker = marker_style::none;
        rod.width_scale = 1.2;
        rod.x = {0, std::sin(a)};
        rod.y = {0, -std::cos(a)};
        plot::series bob = series_of(st);
        bob.label.clear();
        bob.line = line_style::none;
        // The exact pendulum's bob is solid; the approximations' are outlines.
        bob.marker = m.marker.value_or(is_exact(m) ? marker_style::filled_circle : marker_style::open_circle);
        bob.marker_scale = 3.0;
        bob.width_scale = 1.5;
        bob.x = {std::sin(a)};
        bob.y = {-std::cos(a)};
        panel.data.push_back(std::move(rod));
        panel.data.push_back(std::move(bob));
    }
    plot::series pivot;
    pivot.line = line_style::none;
    pivot.marker = marker_style::filled_circle;
    pivot.marker_scale = 1.2;
    pivot.x = {0};
    pivot.y = {0};
    panel.data.push_back(std::move(pivot));
}

void add_frame_state(plot::figure& f, const figure_spec& spec, const std::vector<panel_spec>& panels, double w0_t) {
    for (std::size_t i = 0; i < panels.size() && i < f.panels.size(); ++i) {
        const panel_spec& p = panels[i];
        plot::panel& panel = f.panels[i];
        const std::size_t still = panel.data.size();
        // Everything added here moves: the overlay pass of a frame draws it.
        struct mark_overlay {
            plot::panel& panel;
            std::size_t from;
            ~mark_overlay() {
                for (std::size_t k = from; k < panel.data.size(); ++k) panel.data[k].overlay = true;
            }
        } mark{panel, still};
        if (p.plot == plot_kind::pendulum) {
            add_pendulum_state(panel, p, w0_t);
            continue;
        }
        if (p.plot != plot_kind::trajectory && p.plot != plot_kind::phase) continue;
        const double angle = p.degrees ? 180 / pi : 1.0;
        for (const auto& a : p.theta0) {
            const pendulum::exact_solution exact(a.value);
            const double period = 4 * exact.quarter_period();
            double x_now = 0;
            if (p.plot == plot_kind::trajectory) {
                // The time cursor.
                x_now = w0_t / period * time_unit_of(spec, p, exact).first;
                plot::series cursor;
                cursor.x = {x_now, x_now};
                cursor.y = {-1e3, 1e3};
                cursor.autoscale = false;
                cursor.alpha = 0.5;
                cursor.width_scale = 0.6;
                panel.data.push_back(std::move(cursor));
            }
            for (std::size_t j = 0; j < p.methods.size(); ++j) {
                const auto& m = p.methods[j];
                const std::size_t amplitude_index = static_cast<std::size_t>(&a - p.theta0.data());
                const bool by_orbit = p.plot == plot_kind::phase && p.methods.size() == 1;
                series_style st = style_of(m, static_cast<int>(by_orbit ? amplitude_index : j));
                plot::series dot = series_of(st);
                dot.label.clear();
                dot.style_key.clear();
                dot.line = line_style::none;
                dot.marker = marker_style::filled_circle;
                dot.marker_scale = 1.8;
                dot.autoscale = false;
                double theta = 0;
                double velocity = 0;
                if (is_exact(m)) {
                    theta = exact.theta_at_fraction(w0_t / period);
                    velocity = pendulum::velocity_at_fraction(exact, w0_t / period);
                } else {
                    const auto sol = pendulum::method_solution(m.method, a.value);
                    theta = sol.theta(w0_t);
                    velocity = pendulum::velocity(sol, w0_t);
                }
                dot.x = {p.plot == plot_kind::trajectory ? x_now : angle * theta};
                dot.y = {p.plot == plot_kind::trajectory ? angle * theta : velocity};
                panel.data.push_back(std::move(dot));
            }
        }
    }
}

std::string panel_name(std::size_t i) {
    std::string letters;
    for (std::size_t n = i + 1; n > 0; n = (n - 1) / 26) letters.insert(letters.begin(), static_cast<char>('a' + (n - 1) % 26));
    return letters;
}

std::string method_label(const pendulum::method_choice& m) {
    const std::string_view name = m.row->name;
    if (name == "lowest" || name == "first" || name == "second") return std::string(name) + " order";
    if (name == "order") return "order " + std::to_string(m.n);
    if (name == "kidd-fogg") return "Kidd\u2013Fogg";
    if (name == "lima-arun") return "Lima\u2013Arun";
    if (name == "ganley") return "Ganley";
    if (name == "denman") return "Denman";
    if (name == "agm") return "AGM, " + std::to_string(m.n) + (m.n == 1 ? " step" : " steps");
    if (name == "series") return "series to " + std::string(theta0_markup) + "<sup>" + std::to_string(2 * m.n) + "</sup>";
    if (name == "log-asymptote") return "log asymptote";
    return std::string(name);
}

line_style method_line(const pendulum::method_choice& m) {
    const std::string_view name = m.row->name;
    if (name == "exact") return line_style::none;
    if (m.has_motion()) return line_style::solid;
    return line_style::dashed;
}

std::string typeset_angle(std::string_view text) {
    std::string out;
    std::size_t i = 0;
    auto digits_at = [&](std::size_t k) { return k < text.size() && std::isdigit(static_cast<unsigned char>(text[k])); };
    while (i < text.size()) {
        const char c = text[i];
        if (text.substr(i, 2) == "pi") {
            out += "<i>\u03c0</i>";
            i += 2;
        } else if (text.substr(i, 2) == std::string_view("\u03c0")) {
            out += "<i>\u03c0</i>";
            i += 2;
        } else if (text.substr(i, 3) == "deg") {
            out += "\u00b0";
            i += 3;
        } else if (text.substr(i, 3) == "rad") {
            i += 3;
        } else if (c == '-' || c == '+') {
            // A sign at the start or after an operator or "(" is unary; otherwise an operator.
            const bool unary = out.empty() || out.back() == '(' || out.ends_with("\u00d7") || out.ends_with(" ");
            out += unary ? (c == '-' ? "\u2212" : "+") : (c == '-' ? " \u2212 " : " + ");
            ++i;
        } else if (c == '*') {
            // "9*pi/10" reads as 9π/10; between two numbers it is a product sign.
            const bool before_number = digits_at(i + 1) || (i + 1 < text.size() && text[i + 1] == '.');
            out += before_number ? "\u00d7" : "";
            ++i;
        } else if (c == ' ') {
            ++i;
        } else if (digits_at(i) || c == '.') {
            // A number; an exponent is set as a power of ten: 1e-6 -> 10^-6, 2.5e3 -> 2.5x10^3.
            std::size_t j = i;
            while (digits_at(j) || (j < text.size() && text[j] == '.')) ++j;
            std::string mantissa(text.substr(i, j - i));
            if (j < text.size() && (text[j] == 'e' || text[j] == 'E')) {
                std::size_t k = j + 1;
                std::string sign;
                if (k < text.size() && (text[k] == '-' || text[k] == '+')) {
                    if (text[k] == '-') sign = "\u2212";
                    ++k;
                }
                std::size_t e = k;
                while (digits_at(e)) ++e;
                std::string exponent(text.substr(k, e - k));
                exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
                out += (mantissa == "1" ? std::string() : mantissa + "\u00d7") + "10<sup>" + sign + exponent + "</sup>";
                i = e;
            } else {
                out += mantissa;
                i = j;
            }
        } else {
            out += plot::escape_markup(std::string(1, c));
            ++i;
        }
    }
    return out;
}

plot::figure figure_grid(const figure_spec& spec, const build_options& options) {
    const int n = static_cast<int>(panels_with(spec, options).size());
    if (n == 0) throw bad_input("figure '" + spec.id + "' has no panels");
    plot::figure f;
    f.cols = std::min(spec.columns.value_or(3), n);
    f.rows = (n + f.cols - 1) / f.cols;
    f.panel_width_cm = spec.panel_width_cm.value_or(options.panel_width_cm);
    f.panel_aspect = spec.panel_aspect.value_or(options.panel_aspect);
    f.shared_legend = spec.legend == legend_mode::first;
    return f;
}

plot::figure build_figure(const figure_spec& spec, const build_options& options) {
    const auto panels = panels_with(spec, options);
    plot::figure f = figure_grid(spec, options);
    const context c{spec, f.panel_width_cm, options.animated};
    for (std::size_t i = 0; i < panels.size(); ++i) {
        const auto& p = panels[i];
        plot::panel panel = build_panel(c, p);
        if (p.y_range) {
            panel.y.min = (*p.y_range)[0];
            panel.y.max = (*p.y_range)[1];
        }
        if (p.x_label) panel.x.label = plot::tex_to_markup(*p.x_label);
        if (p.y_label) panel.y.label = plot::tex_to_markup(*p.y_label);
        const std::string letter = panels.size() > 1 ? panel_letter(i) : "";
        if (p.title) {
            panel.label = plot::tex_to_markup(*p.title);
        } else if (p.plot == plot_kind::trajectory) {
            panel.label = letter.empty() ? panel.label : letter + " " + panel.label;
        } else {
            panel.label = letter;
        }
        if (spec.legend == legend_mode::none) panel.legend = plot::legend_place::none;
        for (const auto& line : p.lines) {
            // A reference line crosses the whole panel, from limit to limit of the other axis
            // (its data range when the axis has no limits), and leaves the limits alone.
            plot::series s{line.label.empty() ? "" : plot::tex_to_markup(line.label), {}, {}, line.style,
                           marker_style::none, 0};
            s.autoscale = false;
            const auto extent = [&](const plot::axis& a, bool horizontal) {
                double lo = a.min.value_or(std::numeric_limits<double>::infinity());
                double hi = a.max.value_or(-std::numeric_limits<double>::infinity());
                for (const auto& d : panel.data) {
                    for (double v : horizontal ? d.x : d.y) {
                        if (!std::isfinite(v) || !d.autoscale) continue;
                        if (!a.min) lo = std::min(lo, v);
                        if (!a.max) hi = std::max(hi, v);
                    }
                }
                // Past the data by the widest margin an axis adds, so the line meets the frame.
                const double pad = a.kind == plot::scale::log ? 0.0 : (hi - lo);
                return std::array<double, 2>{a.min ? lo : lo - pad, a.max ? hi : hi + pad};
            };
            if (line.y) {
                const auto x = extent(panel.x, true);
                s.x = {x[0], x[1]};
                s.y = {*line.y, *line.y};
            } else {
                const auto y = extent(panel.y, false);
                s.x = {*line.x, *line.x};
                s.y = {y[0], y[1]};
            }
            panel.data.push_back(std::move(s));
        }
        f.panels.push_back(std::move(panel));
    }
    return f;
}

}  // namespace figures
