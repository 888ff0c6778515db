// SPDX-License-Identifier: GPL-3.0-or-later
// The coefficient plot: one Fourier coefficient against the amplitude.
#include "figures/plot_builders.hpp"

#include "figures/data_series.hpp"
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

plot::panel coefficient_panel(const panel_context& c, const panel_spec& p) {
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
            const std::function<double(double)> c = [n](double t) {
                return pendulum::exact_solution(t).coefficient(n);
            };
            s = make_series(st, circle_amplitudes(lo, hi), c);
            const auto line = curve_amplitudes(lo, hi);
            s.curve = amplitude_curve(p, line.front(), line.back(), c);
        } else {
            const std::function<double(double)> c = [method = m.method, n](double t) {
                const auto sol = pendulum::method_solution(method, t);
                return n < static_cast<int>(sol.coefficients.size()) ? sol.coefficients[static_cast<std::size_t>(n)]
                                                                      : 0.0;
            };
            s = make_series(st, curve_amplitudes(lo, hi), c);
            s.curve = amplitude_curve(p, s.x.front(), s.x.back(), c);
        }
        for (double& v : s.x) v = to_axis_angle(p, v);
        panel.data.push_back(std::move(s));
    }
    add_angle_number_data(panel, p);
    return panel;
}

}  // namespace figures
