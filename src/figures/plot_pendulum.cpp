// SPDX-License-Identifier: GPL-3.0-or-later
// The pendulum drawing: rod and bob of each method, for animations.
#include "figures/plot_builders.hpp"

#include "figures/panel_support.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace figures {

using plot::line_style;
using plot::marker_style;
using std::numbers::pi;

plot::panel pendulum_panel(const panel_context& c, const panel_spec& p) {
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
    path.curve = plot::parametric_curve(0, 2 * pi, [](double a) { return std::pair{std::sin(a), -std::cos(a)}; }, 8);
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
                const double t0 = w0_t - span * (8 - k) / 8;
                const double t1 = w0_t - span * (7 - k) / 8;
                // Drawn after this function returns: holds its own copies.
                const auto bob_at = [exact, solution, period, exact_m = is_exact(m)](double t) {
                    const double a = exact_m ? exact.theta_at_fraction(t / period) : solution.theta(t);
                    return std::pair{std::sin(a), -std::cos(a)};
                };
                for (double t : {t0, t1}) {
                    trail.x.push_back(bob_at(t).first);
                    trail.y.push_back(bob_at(t).second);
                }
                trail.curve = plot::parametric_curve(t0, t1, bob_at, 1);
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

void add_pendulum_frame(plot::panel& panel, const panel_context&, const panel_spec& p, double w0_t) {
    add_pendulum_state(panel, p, w0_t);
}

}  // namespace figures
