// SPDX-License-Identifier: GPL-3.0-or-later
// The spectrum plot: the magnitudes of the Fourier coefficients.
#include "figures/plot_builders.hpp"

#include "figures/panel_support.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"
#include "plot/tex_markup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace figures {

using plot::line_style;
using plot::marker_style;
using std::numbers::pi;

plot::panel spectrum_panel(const panel_context&, const panel_spec& p) {
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
            plot::label label = std::string(theta0_markup) + " = " + typeset_angle(a.text);
            if (p.methods.size() > 1) {
                label = plot::join(plot::label(label.markup + ", "),
                                   m.label.empty() ? method_label(m.method) : plot::tex_label(m.label));
            }
            series_style st = amplitude_style(index++, label);
            st.marker = marker_style::open_circle;
            if (m.style) st.line = *m.style;
            plot::series s = series_of(st);
            const std::vector<double> c = is_exact(m)
                                              ? pendulum::fourier_coefficients(a.theta0(), p.harmonics)
                                              : pendulum::method_solution(m.method, a.theta0()).coefficients;
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

}  // namespace figures
