// SPDX-License-Identifier: GPL-3.0-or-later
// The phase plot: orbits in the phase plane, one per amplitude.
#include "figures/plot_builders.hpp"

#include "figures/data_series.hpp"
#include "figures/panel_support.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/motion.hpp"
#include "pendulum/phase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace figures {

using plot::line_style;
using plot::marker_style;
using std::numbers::pi;

namespace {

/// Orbits are lines: five dash patterns, then the same a little wider.
plot::series orbit_series(std::size_t i, const plot::label& label) {
    static const line_style lines[] = {line_style::solid, line_style::dashed, line_style::dotted, line_style::dash_dot,
                                       line_style::dash_dot_dot};
    series_style st = amplitude_style(i, label);
    st.line = lines[i % 5];
    st.marker = marker_style::none;
    plot::series s = series_of(st);
    if (i >= 5) s.width_scale = 1.8;
    return s;
}

/// Samples of the series' curve that set the limits and place the legend.
void sample_curve(plot::series& s, double lo, double hi) {
    for (double t : grid(lo, hi, 400)) {
        const auto [x, y] = s.curve->at(t);
        s.x.push_back(x);
        s.y.push_back(y);
    }
}

/// theta reduced to [-pi, pi]: the phase plane of the starts is one turn wide.
double wrapped(double theta) { return std::remainder(theta, 2 * pi); }

/// The orbits of energies and states: a libration's closed orbit (its approximants' too),
/// and above the separatrix theta'/w0 = +-sqrt(4 cos^2(theta/2) - 2 (2 - E)) as a function of
/// theta over [-pi, pi], so that a rotating orbit leaves at one edge and comes back at the
/// other with no line across. An energy draws both directions, a state its own.
/// The series of a start's orbit by one method: in the start's style where the panel has
/// one method of no style of its own, else in the method's (its legend entry once).
plot::series start_series(const panel_spec& p, std::size_t i, std::size_t j) {
    const auto& start = p.starts[i];
    const std::string regime(pendulum::row_of(start.motion.kind()).name);
    const auto& method = p.methods[j];
    const bool by_start = p.methods.size() == 1 && !method.style && !method.marker && method.label.empty();
    plot::series s = by_start ? orbit_series(i, start.label + ", " + regime)
                              : series_of(style_of(method, static_cast<int>(p.methods.size() == 1 ? i : j)));
    if (!by_start && i > 0) s.label = plot::label{};
    return s;
}

/// A libration's closed orbit by a method.
void add_libration_orbit(plot::panel& panel, plot::series s, const pendulum::motion& m, const method_spec& method,
                         double angle) {
    if (is_exact(method)) {
        s.curve = plot::parametric_curve(0, 1, [e = m.libration(), angle](double t) {
            return std::pair{angle * e.theta_at_fraction(t), pendulum::velocity_at_fraction(e, t)};
        }, 8);
    } else {
        s.curve = plot::parametric_curve(
            0, 1, [sol = pendulum::method_solution(method.method, m.amplitude()), period = m.period(), angle](double t) {
                return std::pair{angle * sol.theta(t * period), pendulum::velocity(sol, t * period)};
            }, 8);
    }
    sample_curve(s, 0, 1);
    panel.data.push_back(std::move(s));
}

/// The open orbits of a rotation or the separatrix: both branches of an energy's level set,
/// or the branch a state moves along.
void add_open_orbits(plot::panel& panel, const plot::series& s, const motion_start& start, double angle) {
    const auto& m = start.motion;
    const double gap = m.energy_gap();
    const auto branch = [gap, angle](double sign) {
        return plot::function_curve(-pi * angle, pi * angle, [gap, angle, sign](double x) {
            const double c = std::cos(0.5 * x / angle);
            return sign * std::sqrt(std::max(0.0, 4 * c * c - 2 * gap));
        });
    };
    const double direction = m.start().omega < 0 ? -1.0 : 1.0;
    for (double sign : start.energy ? std::vector<double>{1.0, -1.0} : std::vector<double>{direction}) {
        plot::series b = s;
        if (sign < 0 && start.energy) b.label = plot::label{};
        b.curve = branch(sign);
        sample_curve(b, -pi * angle, pi * angle);
        panel.data.push_back(std::move(b));
    }
}

void add_start_orbits(plot::panel& panel, const panel_spec& p, double angle) {
    for (std::size_t i = 0; i < p.starts.size(); ++i) {
        const auto& start = p.starts[i];
        for (std::size_t j = 0; j < p.methods.size(); ++j) {
            plot::series s = start_series(p, i, j);
            if (start.motion.kind() == pendulum::regime::libration) {
                add_libration_orbit(panel, std::move(s), start.motion, p.methods[j], angle);
            } else {
                add_open_orbits(panel, s, start, angle);
            }
        }
    }
}

}  // namespace

namespace {

/// An amplitude's orbit style by one method: one method, each orbit its own line and colour,
/// its amplitude in the legend; several, a style per method, one legend entry each.
plot::series amplitude_series(const panel_spec& p, std::size_t i, std::size_t j) {
    const amplitude& a = p.theta0[i];
    const auto& m = p.methods[j];
    const bool by_amplitude = p.methods.size() == 1 && !m.style && !m.marker && m.label.empty();
    series_style st = by_amplitude ? amplitude_style(i, std::string(theta0_markup) + " = " + typeset_angle(a.text))
                                   : style_of(m, static_cast<int>(p.methods.size() == 1 ? i : j));
    if (!by_amplitude && i > 0) st.label.clear();  // one legend entry per method
    if (by_amplitude) {
        // Orbits are lines: five dash patterns, then the same a little wider.
        static const line_style lines[] = {line_style::solid, line_style::dashed, line_style::dotted,
                                           line_style::dash_dot, line_style::dash_dot_dot};
        st.line = lines[i % 5];
        st.marker = marker_style::none;
    }
    plot::series s = series_of(st);
    if (by_amplitude && i >= 5) s.width_scale = 1.8;
    if (is_exact(m) && !m.style && !m.marker && !by_amplitude) {
        // An orbit reads best as a line, whatever the theme's circles for exact.
        s.line = line_style::solid;
        s.marker = marker_style::none;
        s.style_key.clear();
    }
    return s;
}

/// The orbit of each amplitude by each method, sampled for the limits and the legend.
void add_amplitude_orbits(plot::panel& panel, const panel_spec& p, double angle) {
    const auto s_grid = grid(0, 1, 400);
    for (std::size_t i = 0; i < p.theta0.size(); ++i) {
        const amplitude& a = p.theta0[i];
        const pendulum::exact_solution exact(a.theta0());
        const double period = 4 * exact.quarter_period();
        for (std::size_t j = 0; j < p.methods.size(); ++j) {
            const auto& m = p.methods[j];
            plot::series s = amplitude_series(p, i, j);
            if (is_exact(m)) {
                s.curve = plot::parametric_curve(0, 1, [exact, angle](double t) {
                    return std::pair{angle * exact.theta_at_fraction(t), pendulum::velocity_at_fraction(exact, t)};
                }, 8);
            } else {
                s.curve = plot::parametric_curve(
                    0, 1, [sol = pendulum::method_solution(m.method, a.theta0()), period, angle](double t) {
                        return std::pair{angle * sol.theta(t * period), pendulum::velocity(sol, t * period)};
                    }, 8);
            }
            // The orbit is drawn from its curve; these samples set the limits and place the legend.
            for (double t : s_grid) {
                const auto [x, y] = s.curve->at(t);
                s.x.push_back(x);
                s.y.push_back(y);
            }
            panel.data.push_back(std::move(s));
        }
    }
}

/// The separatrix: a thin mid-grey line over the orbits, thinner than any of them. Its grey
/// (relative luminance 0.21) stands 3:1 or more against a white page (3.98:1) and against
/// the dark slides' background (4.1:1), and apart from the paper's black orbits in greyscale.
const plot::rgb separatrix_grey{0.5, 0.5, 0.5};

void add_separatrix(plot::panel& panel, double angle) {
    const auto theta = grid(-pi, pi, 400);
    for (double sign : {1.0, -1.0}) {
        plot::series s;
        if (sign > 0) s.label = "separatrix";
        s.line = line_style::solid;
        s.rgb_color = separatrix_grey;
        s.width_scale = 0.6;
        s.curve = plot::function_curve(-pi * angle, pi * angle, [sign, angle](double x) {
            return sign * pendulum::separatrix_velocity(x / angle);
        });
        for (double t : theta) {
            s.x.push_back(angle * t);
            s.y.push_back(s.curve->at(angle * t).second);
        }
        panel.data.push_back(std::move(s));
    }
}

}  // namespace

plot::panel phase_panel(const panel_context&, const panel_spec& p) {
    plot::panel panel;
    const double angle = p.degrees ? 180 / pi : 1.0;
    panel.x.label = "<i>\u03d1</i>";
    panel.x.ticks = p.degrees ? plot::tick_kind::degrees : plot::tick_kind::multiples_of_pi;
    panel.x.max_ticks = 5;
    panel.y.label = "d<i>\u03d1</i>/d(<i>\u03c9</i><sub>0</sub><i>t</i>)";
    if (!p.starts.empty()) {
        // One turn, -pi to pi: rotating orbits leave at one edge and come back at the other.
        panel.x.min = -pi * angle;
        panel.x.max = pi * angle;
        add_start_orbits(panel, p, angle);
    }
    add_amplitude_orbits(panel, p, angle);
    if (p.separatrix) add_separatrix(panel, angle);
    add_angle_number_data(panel, p);
    return panel;
}

void add_phase_frame(plot::panel& panel, const panel_context&, const panel_spec& p, double w0_t) {
    const double angle = p.degrees ? 180 / pi : 1.0;
    const std::size_t starts = p.starts.size() + p.theta0.size();
    for (std::size_t i = 0; i < p.starts.size(); ++i) {
        const auto& m = p.starts[i].motion;
        for (std::size_t j = 0; j < p.methods.size(); ++j) {
            plot::series dot = moving_dot(style_of(p.methods[j], static_cast<int>(p.methods.size() == 1 ? i : j)), i, starts);
            if (is_exact(p.methods[j])) {
                dot.x = {angle * wrapped(m.theta(w0_t))};
                dot.y = {m.velocity(w0_t)};
            } else {
                const auto sol = pendulum::method_solution(p.methods[j].method, m.amplitude());
                dot.x = {angle * sol.theta(m.libration_clock(w0_t))};
                dot.y = {pendulum::velocity(sol, m.libration_clock(w0_t))};
            }
            panel.data.push_back(std::move(dot));
        }
    }
    for (std::size_t i = 0; i < p.theta0.size(); ++i) {
        const pendulum::exact_solution exact(p.theta0[i].theta0());
        for (std::size_t j = 0; j < p.methods.size(); ++j) {
            // One method: each orbit its own colour, as the orbits are drawn.
            const int index = static_cast<int>(p.methods.size() == 1 ? i : j);
            plot::series dot = moving_dot(style_of(p.methods[j], index), p.starts.size() + i, starts);
            const auto [theta, velocity] = state_at(p.methods[j], exact, w0_t);
            dot.x = {angle * theta};
            dot.y = {velocity};
            panel.data.push_back(std::move(dot));
        }
    }
}

}  // namespace figures
