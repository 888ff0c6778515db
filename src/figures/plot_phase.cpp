// SPDX-License-Identifier: GPL-3.0-or-later
// The phase plot: orbits in the phase plane, one per amplitude.
#include "figures/plot_builders.hpp"

#include "figures/panel_support.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/phase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace figures {

using plot::line_style;
using plot::marker_style;
using std::numbers::pi;

plot::panel phase_panel(const panel_context&, const panel_spec& p) {
    plot::panel panel;
    const double angle = p.degrees ? 180 / pi : 1.0;
    panel.x.label = "<i>\u03d1</i>";
    panel.x.ticks = p.degrees ? plot::tick_kind::degrees : plot::tick_kind::multiples_of_pi;
    panel.x.max_ticks = 5;
    panel.y.label = "d<i>\u03d1</i>/d(<i>\u03c9</i><sub>0</sub><i>t</i>)";
    const auto s_grid = grid(0, 1, 400);
    for (std::size_t i = 0; i < p.theta0.size(); ++i) {
        const amplitude& a = p.theta0[i];
        const pendulum::exact_solution exact(a.theta0());
        const double period = 4 * exact.quarter_period();
        for (std::size_t j = 0; j < p.methods.size(); ++j) {
            const auto& m = p.methods[j];
            // One method: each orbit its own line and colour, its amplitude in the legend;
            // several: a style per method, one legend entry each.
            const bool by_amplitude = p.methods.size() == 1 && !m.style && !m.marker && m.label.empty();
            series_style st = by_amplitude
                                  ? amplitude_style(i, std::string(theta0_markup) + " = " + typeset_angle(a.text))
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
            if (is_exact(m)) {
                if (!m.style && !m.marker && !by_amplitude) {
                    // An orbit reads best as a line, whatever the theme's circles for exact.
                    s.line = line_style::solid;
                    s.marker = marker_style::none;
                    s.style_key.clear();
                }
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
    if (p.separatrix) {
        // A wide grey band under the orbits: seen even where an orbit runs along it.
        const auto theta = grid(-pi, pi, 400);
        for (double sign : {1.0, -1.0}) {
            plot::series s;
            if (sign > 0) s.label = "separatrix";
            s.line = line_style::solid;
            s.rgb_color = plot::rgb{0.62, 0.62, 0.62};
            s.width_scale = 3.5;
            s.curve = plot::function_curve(-pi * angle, pi * angle, [sign, angle](double x) {
                return sign * pendulum::separatrix_velocity(x / angle);
            });
            for (double t : theta) {
                s.x.push_back(angle * t);
                s.y.push_back(s.curve->at(angle * t).second);
            }
            panel.data.insert(panel.data.begin() + (sign > 0 ? 0 : 1), std::move(s));
        }
    }
    return panel;
}

void add_phase_frame(plot::panel& panel, const panel_context&, const panel_spec& p, double w0_t) {
    const double angle = p.degrees ? 180 / pi : 1.0;
    for (std::size_t i = 0; i < p.theta0.size(); ++i) {
        const pendulum::exact_solution exact(p.theta0[i].theta0());
        for (std::size_t j = 0; j < p.methods.size(); ++j) {
            // One method: each orbit its own colour, as the orbits are drawn.
            const int index = static_cast<int>(p.methods.size() == 1 ? i : j);
            plot::series dot = moving_dot(style_of(p.methods[j], index));
            const auto [theta, velocity] = state_at(p.methods[j], exact, w0_t);
            dot.x = {angle * theta};
            dot.y = {velocity};
            panel.data.push_back(std::move(dot));
        }
    }
}

}  // namespace figures
