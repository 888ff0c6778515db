// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/period_error.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

namespace pendulum::cli {

/// The solutions a column of eval reads, as flags: only those asked for are computed.
enum eval_need : unsigned {
    need_exact = 1,        ///< the exact solution
    need_lowest = 2,       ///< lowest order
    need_first = 4,        ///< first order
    need_second = 8,       ///< second order
    need_polynomial = 16,  ///< polynomial approximant
    need_exact_period = 32,  ///< the exact period alone (one AGM; the solution needs two)
};

/// Everything eval computes once per amplitude: the solutions `needs` names (eval_need flags).
struct eval_point {
    /// Solves the methods of `needs` at theta0.
    eval_point(const amplitude& theta0, unsigned needs);
    double theta0;                               ///< the amplitude
    double from_pi;                              ///< its distance pi - theta0, exact close to pi
    std::optional<exact_solution> exact;         ///< the exact solution
    std::optional<double> exact_period;          ///< T/T0, exact
    std::optional<fourier_solution> lowest;      ///< lowest order
    std::optional<fourier_solution> first;       ///< first order
    std::optional<fourier_solution> second;      ///< second order
    std::optional<fourier_solution> polynomial;  ///< polynomial approximant
};

/// One fixed column of eval's table.
struct eval_column {
    std::string_view name;                  ///< CSV header and JSON key
    std::string_view description;           ///< for --help
    unsigned needs;                         ///< the solutions it reads (eval_need flags)
    double (*value)(const eval_point& p);   ///< the value at an amplitude
    bool by_default = true;                 ///< written without --columns
};

/// The fixed columns, in order; --order and --method add columns after them. Without
/// --columns eval writes those that are by_default.
std::span<const eval_column> eval_columns();

/// The prefix of an error column: err:lowest is the relative period error T_m/T - 1 of
/// lowest order, err:order:6 that of the iteration to order 6, for any method of 'list'.
inline constexpr std::string_view error_column_prefix = "err:";

/// The method of an error column's name (err:METHOD), or nullopt for a name without the
/// prefix; an unknown method is a usage_error naming it.
std::optional<method_choice> error_column_method(std::string_view name);

/// A period error as eval writes it in an err:METHOD column: the number T_m/T - 1, "below_limit" under 1e-300,
/// "not_computed" where no precision resolved it, NaN (an empty field) where there is no period.
std::variant<std::string, double> period_error_field(const period_error& e);

/// The column list for --help: "theta0 (the amplitude), period_exact (T/T0 exact), ...".
std::string eval_columns_help();

}  // namespace pendulum::cli
