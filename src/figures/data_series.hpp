// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Measured data in a panel ([[panel.data]]): read from a CSV or TSV file or given inline,
// checked, and placed on the panel's axes in their units.

#include "plot/figure.hpp"

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace figures {

struct panel_spec;
struct figure_spec;

/// The largest data file, in bytes (a spec file's limit too).
inline constexpr std::size_t max_data_file_bytes = std::size_t{1} << 20;
/// The most rows of a data file, or values of an inline list, in one data series.
inline constexpr std::size_t max_data_rows = 100000;
/// The most data series ([[panel.data]] tables) of one panel.
inline constexpr std::size_t max_data_series_per_panel = 8;
/// The most problems reported from one data file: the first few tell what is wrong.
inline constexpr std::size_t max_data_problems = 20;

/// The unit a data series' column is in, as x_unit and y_unit name it.
enum class data_unit {
    rad,           ///< "rad": an angle in radians
    deg,           ///< "deg": an angle in degrees
    seconds,       ///< "s": a period or a time in seconds (needs [pendulum])
    period_ratio,  ///< "T/T0": a period in units of the small-swing period
    small_period,  ///< "t/T0": a time in small-swing periods
    period,        ///< "t/T": a time in exact periods of the panel's motion
    number,        ///< "1": a pure number (a coefficient, theta'/w0, an energy, a log error)
    percent,       ///< "%": a relative error in per cent
};

/// What a panel's axis measures, which fixes the units data on it may be given in.
enum class quantity { angle, period, time, number, percent };

/// One measured series of a panel, as read: values and error bars in the units given.
struct data_series {
    std::string label;             ///< legend label, TeX; empty: the file's name, or "data"
    std::string file;              ///< the data file's path (for the dependency file); empty when inline
    std::string shown_file;        ///< the file as the spec names it, for messages and the default label
    data_unit x_unit = data_unit::number;  ///< unit of x and its errors
    data_unit y_unit = data_unit::number;  ///< unit of y and its errors
    std::vector<double> x;         ///< abscissae
    std::vector<double> y;         ///< ordinates
    plot::error_bars errors;       ///< lower and upper errors (>= 0), in the units of their axis
    std::array<int, 2> where{0, 0};  ///< line and column of its [[panel.data]] table in the spec
};

/// The name of a unit as specs write it.
std::string_view unit_name(data_unit u);

/// The quantities of a panel's x and y axes, or nothing for a panel that takes no data.
std::optional<std::array<quantity, 2>> data_axes(const panel_spec& p);

/// How data reach a panel's axes: the factor from a unit to the axis' unit, and an offset
/// added to y at each axis x (residuals subtract their reference there; null for none).
struct data_placement {
    std::function<double(data_unit)> x_factor;  ///< axis value per unit of x
    std::function<double(data_unit)> y_factor;  ///< axis value per unit of y
    std::function<double(double)> y_offset{};   ///< added to y at the axis' x
};

/// The factor from `from` to `to`, two units of one quantity: t0_seconds is the small-swing
/// period T0 in seconds (0 without [pendulum]), period_ratio the panel's T/T0 (times in t/T).
double unit_factor(data_unit from, data_unit to, double t0_seconds, double period_ratio);

/// Adds the panel's data series to `panel`, placed on its axes, as markers with error bars
/// in the theme's data styles, each with its legend entry and the id "data:1", "data:2", ...
void add_data_series(plot::panel& panel, const panel_spec& p, const data_placement& at);

/// Adds the data of a panel whose x axis is an angle (in the panel's angle unit) and whose y
/// axis is a pure number: phase and coefficient panels.
void add_angle_number_data(plot::panel& panel, const panel_spec& p);

/// The angle unit of a panel's amplitude axis (deg or rad).
data_unit angle_axis_unit(const panel_spec& p);

/// The small-swing period T0 in seconds, 0 without [pendulum].
double small_period_seconds_of(const figure_spec& f);

}  // namespace figures
