// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"

#include <span>
#include <string>
#include <string_view>

namespace pendulum::cli {

/// Everything eval computes once per amplitude.
struct eval_point {
    /// Solves every method at theta0.
    explicit eval_point(const amplitude& theta0);
    double theta0;                ///< the amplitude
    exact_solution exact;         ///< the exact solution
    fourier_solution lowest;      ///< lowest order
    fourier_solution first;       ///< first order
    fourier_solution second;      ///< second order
    fourier_solution polynomial;  ///< polynomial approximant
};

/// One fixed column of eval's table.
struct eval_column {
    std::string_view name;                  ///< CSV header and JSON key
    std::string_view description;           ///< for --help
    double (*value)(const eval_point& p);   ///< the value at an amplitude
};

/// The fixed columns, in order; --order and --method add columns after them.
std::span<const eval_column> eval_columns();

/// The column list for --help: "theta0 (the amplitude), period_exact (T/T0 exact), ...".
std::string eval_columns_help();

}  // namespace pendulum::cli
