// SPDX-License-Identifier: GPL-3.0-or-later
// The convergence plot: the period error of the iteration against its order.
#include "figures/plot_builders.hpp"

#include "figures/panel_support.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

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

}  // namespace figures
