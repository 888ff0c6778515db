// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A figure's numbers as the next tool reads them: CSV in rows (long) or in columns (wide)
// and JSON, each series named by a stable id beside its display label.

#include "figures/catalog.hpp"
#include "figures/spec.hpp"
#include "plot/figure.hpp"
#include "plot/render.hpp"
#include "plot/theme.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace figures {

/// True for the characters a series id may hold: [A-Za-z0-9_:.-].
bool series_id_character(char c);

/// Gives every series of the panel an id unique in it: its own (characters outside
/// series_id_character made '_'), else "line:N" for a series that leaves the limits alone
/// and "series:N" for any other (N from 1 in the panel); a repeated id gets ".2", ".3", ...
void give_series_ids(plot::panel& p);

/// How `data` lays out its CSV.
enum class data_layout {
    long_rows,  ///< panel,series,x,y,id: one row per point
    wide,       ///< one x and one y column per panel and series, padded with nan
};

/// One series' numbers as a figure draws them.
struct series_numbers {
    std::string id;                    ///< plot::series::id
    std::string label;                 ///< its legend text, plain
    std::vector<double> x;             ///< abscissae: a curve's samples, or the series' points
    std::vector<double> y;             ///< ordinates
    std::vector<double> x_err_lower;   ///< x uncertainties to the left, one per point; empty: none
    std::vector<double> x_err_upper;   ///< x uncertainties to the right
    std::vector<double> y_err_lower;   ///< y uncertainties below
    std::vector<double> y_err_upper;   ///< y uncertainties above
    bool sampled = false;              ///< x and y are a curve's samples (plot::drawn_data)
    bool reference_line = false;       ///< a reference line: its two ends within the panel
    std::string method;                ///< the method's name ("order:6"), where the series is one
    std::optional<amplitude> theta0;   ///< its amplitude, where it has one
    std::optional<double> period;      ///< T/T0 of the method at theta0, where both are known
    int y_digits = 0;                  ///< significant digits y is printed with (0: every digit of a double)
    /// Where each y is a difference a - b (a residual panel's (T_meas - T_ref)/T0): the size
    /// max(|a|, |b|) of its terms, one per point, for difference_digits(); empty: none.
    std::vector<double> y_terms;
};

/// One axis of a panel, in words.
struct axis_numbers {
    std::string label;  ///< plain text
    std::string unit;   ///< the label's unit in parentheses at its end ("s", "%"), else empty
    std::string scale;  ///< linear or log
    double lo = 0;      ///< the limit at the left or bottom edge
    double hi = 1;      ///< the limit at the right or top edge
};

/// One panel's numbers.
struct panel_numbers {
    std::string name;                    ///< a, b, c, ... as in the captions
    std::string title;                   ///< the panel's label, plain
    axis_numbers x;                      ///< horizontal axis
    axis_numbers y;                      ///< vertical axis
    std::vector<series_numbers> series;  ///< in drawing order
};

/// A figure's numbers, the panels' specs kept for their amplitudes.
struct figure_numbers {
    std::string id;                    ///< the figure's id
    std::vector<panel_spec> specs;     ///< its panels as specified
    std::vector<panel_numbers> panels; ///< its panels' numbers
    /// The figure's legends did not fit at the PNG's size (plot::layout_error): its curves
    /// were sampled on axes laid out without them.
    bool without_legends = false;
};

/// The numbers of figure e as a raster at `dpi` with `theme` draws it: a curve's adaptive
/// samples within 0.05 pt, reference lines as their two ends within the panel, every other
/// series' points. Throws what building and laying out the figure throw.
figure_numbers numbers_of(const entry& e, const build_options& options, const plot::theme& theme, double dpi);

/// The numbers of a built figure without laying it out: every series' own points (a
/// curve's markers, not its samples), for figures made in code.
figure_numbers numbers_of(const plot::figure& f);

/// How closely a value on an error axis is known: relative, as period_error's drawing
/// precision promises (the period panels' relative error and |T_m/T - 1|, the convergence
/// plot's |T_N/T - 1|).
inline constexpr double error_axis_relative = 1e-12;

/// The significant digits a value printed from panel spec p's y axis deserves: on an error
/// axis those its relative error error_axis_relative leaves (12), elsewhere 0, every digit
/// of a double (the shortest round trip). One rule for every error axis and every format.
int printed_digits(const panel_spec& p);

/// The significant digits a difference a - b computed in doubles deserves, from its size
/// and the size of its terms, max(|a|, |b|): floor(log10(|a - b| / (2^-52 max(|a|, |b|)))),
/// clamped to 1 .. 17 (17 where the terms are 0 or not finite, and where nothing cancels:
/// |a - b| >= max(|a|, |b|), terms of opposite signs or one of them 0). One rule for every residual
/// and difference column, in long CSV, wide CSV and JSON.
int difference_digits(double difference, double terms);

/// The digits y[i] of series s is printed with: difference_digits() where s has its terms,
/// s.y_digits otherwise.
int y_digits_at(const series_numbers& s, std::size_t i);

/// v with `digits` significant digits, written shortest ("0.0123", not "0.012300000000");
/// every digit of a double (format_double) where digits is 0.
std::string format_digits(double v, int digits);

/// The numbers as CSV in the layout.
std::string numbers_csv(const figure_numbers& n, data_layout layout);

/// The wide layout's column of a panel's series and axis ('x' or 'y'): "a_order_6_x" (the
/// id's ':', '.' and '-' made '_', which numpy.genfromtxt would drop).
std::string wide_column(const std::string& panel, const std::string& id, char axis);

/// The numbers as JSON: panels with their axes and series (id, label, method, theta0,
/// period, x, y, errors); numbers shortest round-trip, non-finite ones null.
std::string numbers_json(const figure_numbers& n);

/// Text as a JSON string, quotes included: ", \ and control characters escaped (\u00XX).
std::string json_string(std::string_view text);

/// A text field of CSV: quoted as RFC 4180 asks, and one that a spreadsheet would take for
/// a formula (=, +, -, @, tab or carriage return first) with a single quote before it.
std::string csv_field(const std::string& text);

/// A number as JSON: shortest round trip, null when not finite.
std::string json_number(double v);

}  // namespace figures
