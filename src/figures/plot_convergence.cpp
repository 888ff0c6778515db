// SPDX-License-Identifier: GPL-3.0-or-later
// The convergence plot: the period error of the iteration against its order.
#include "figures/plot_builders.hpp"

#include "figures/panel_support.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "plot/workers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace figures {

using plot::line_style;
using plot::marker_style;
using std::numbers::pi;

plot::panel convergence_panel(const panel_context&, const panel_spec& p) {
    plot::panel panel;
    panel.x.label = "order <i>N</i> of the iteration";
    panel.x.min = p.orders[0];
    panel.x.max = p.orders[1];
    panel.y.label = "|<i>T</i><sub><i>N</i></sub>/<i>T</i> \u2212 1|";
    panel.y.kind = plot::scale::log;
    // The limits follow the data: the errors are right far below the doubles' rounding.
    panel.y.round_limits = true;
    panel.y.max_ticks = 9;
    // Every level with MPFR: each drawn error is right to 1e-12 relative; levels without a
    // period (close to pi) and errors below the axis are gaps. The amplitudes are
    // independent: each on a free core (--jobs), the same numbers on any.
    std::vector<std::vector<pendulum::period_error>> errors(p.theta0.size());
    plot::parallel_for(errors.size(), [&](std::size_t i) {
        errors[i] = pendulum::iterated_period_errors(p.theta0[i].theta0(), p.orders[1], 1e-300);
    });
    for (std::size_t i = 0; i < p.theta0.size(); ++i) {
        const amplitude& a = p.theta0[i];
        const auto& levels = errors[i];
        const series_style st = amplitude_style(i, std::string(theta0_markup) + " = " + typeset_angle(a.text));
        plot::series s = series_of(st);
        for (int n = p.orders[0]; n <= p.orders[1]; ++n) {
            const auto& level = levels[static_cast<std::size_t>(n)];
            const bool known = level.what == pendulum::period_error::kind::value && level.value != 0;
            s.x.push_back(n);
            s.y.push_back(known ? std::fabs(level.value) : std::nan(""));
        }
        panel.data.push_back(std::move(s));
    }
    return panel;
}

}  // namespace figures
