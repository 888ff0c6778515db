// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the builders of the plot kinds share: grids, series styles, axes, labels.

#include "figures/spec.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"
#include "plot/figure.hpp"

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace figures {

/// The amplitude's symbol, theta with subscript 0, as markup.
inline constexpr const char* theta0_markup = "<i>\u03d1</i><sub>0</sub>";

/// n + 1 evenly spaced values over [a, b], the last exactly b.
std::vector<double> grid(double a, double b, int n);

/// How a method's series looks: the theme's defaults unless the spec overrides them.
struct series_style {
    plot::label label;                             ///< legend entry
    plot::line_style line;                         ///< line
    plot::marker_style marker;                     ///< marker
    int color;                                     ///< palette index
    std::string style_key;                         ///< the theme's style of this name, if any
    std::optional<plot::rgb> rgb_color = std::nullopt;  ///< a colour of its own
    std::string id{};                              ///< the series' id (plot::series::id)
};

/// How method m looks as the index-th series of a panel.
series_style style_of(const method_spec& m, int index);

/// An empty series in the style.
plot::series series_of(const series_style& st);

/// A series in the style with y = f(x) at every x.
plot::series make_series(const series_style& st, std::vector<double> x, const std::function<double(double)>& f);

/// The series id of start i (from 0) of a panel's n starts: `id` itself for one start, else
/// "id:N" (N = i + 1), so that each start's parts have ids of their own.
std::string start_id(const std::string& id, std::size_t i, std::size_t n);

/// A dot that moves with a method in an animation, in its style, with no legend entry; its
/// id "dot:" and start_id's of start i of n.
plot::series moving_dot(const series_style& st, std::size_t i = 0, std::size_t n = 1);

/// True for the exact solution.
bool is_exact(const method_spec& m);

/// The amplitude axis over [lo, hi], in multiples of pi or in degrees.
plot::axis amplitude_axis(const panel_spec& p, double lo, double hi);

/// An angle in the panel's unit (radians or degrees).
double to_axis_angle(const panel_spec& p, double theta);

/// The curve (theta0, f(theta0)) for amplitudes from lo to hi (radians), on the panel's
/// amplitude axis (radians or degrees).
std::shared_ptr<const plot::curve> amplitude_curve(const panel_spec& p, double lo, double hi,
                                                   std::function<double(double)> f);

/// Amplitudes where the exact values are marked: multiples of pi/24 inside [lo, hi].
std::vector<double> circle_amplitudes(double lo, double hi);

/// The fine grid of amplitudes for curves inside [lo, hi].
std::vector<double> curve_amplitudes(double lo, double hi);

/// Seconds per unit of w0 t, for a spec with a [pendulum].
double seconds_per_radian(const figure_spec& spec);

/// The x value of a trajectory panel at t = s T, its unit per exact period, and its label.
std::pair<double, std::string> time_unit_of(const figure_spec& spec, const panel_spec& p,
                                            const pendulum::exact_solution& exact);

/// The style of the i-th series of series that differ by amplitude.
series_style amplitude_style(std::size_t i, const plot::label& label);

/// The angle and the velocity d(theta)/d(w0 t) of method m at time w0 t, for amplitude theta0.
std::pair<double, double> state_at(const method_spec& m, const pendulum::exact_solution& exact, double w0_t);

/// An angle expression as written, typeset as Pango markup: "95pi/100" -> 95π/100 (italic
/// π), "170deg" -> 170°, "pi-1e-6" -> π − 10⁻⁶.
std::string typeset_angle(std::string_view text);

/// The legend label of a method where the spec gives none: "lowest order", "order 6", ...
plot::label method_label(const pendulum::method_choice& m);

/// Throws bad_input naming a user's formula (method m) that is finite at none of `xs`
/// (value(x) is what the panel draws at x); nothing for other methods.
void check_formula_finite(const pendulum::method_choice& m, const std::vector<double>& xs,
                          const std::function<double(double)>& value);

/// The line style of a method where neither the spec nor the theme gives one: none (circles)
/// for the exact solution, solid for laws of motion, dashed for period formulas.
plot::line_style method_line(const pendulum::method_choice& m);

/// Pango markup (a legend entry) as plain text, for CSV and messages.
std::string plain_text(const std::string& markup);

}  // namespace figures
