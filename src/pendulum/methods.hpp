// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pendulum/amplitude.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/period_error.hpp"

#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace pendulum {

class formula;

/// What a method is: the exact solution, one of the paper's closed-form approximants (or
/// another law of motion), the paper's iteration to order N, or a formula for the period only.
enum class method_role { exact, approximant, iterated, period_only };

/// One row of the method table: everything a user can choose by name, and what it is.
struct method_row {
    std::string_view name;         ///< "exact", "order", "agm", ...; written NAME or NAME:N
    method_role role;              ///< what it is: figures and commands treat each role alike
    std::string (*label)(int n);   ///< legend label for N (-1 without), text with TeX math in $...$
    int min_n;                     ///< smallest N, or -1 when the method takes none
    int max_n;                     ///< largest N
    std::string_view description;  ///< one line for help and lists
    double (*period)(const amplitude& theta0, int n);              ///< T/T0
    fourier_solution (*solution)(const amplitude& theta0, int n);  ///< the Fourier solution, or null
    period_error (*error)(const amplitude& theta0, int n, precision p);  ///< T_m/T - 1 without cancellation

    /// True for methods with a law of motion theta(t), false for period formulas.
    constexpr bool has_motion() const { return role != method_role::period_only; }
};

/// Every method, in the order help and lists show them.
std::span<const method_row> method_table();

/// A method chosen by name, with its N where it takes one.
struct method_choice {
    const method_row* row = nullptr;  ///< the table row
    int n = -1;                       ///< N, or -1; for a user's formula its number K (formula:K)
    std::shared_ptr<const formula> user;  ///< a user's formula ("formula:EXPR"), or null

    /// The name as written: "lowest", "order:6"; a user's formula by its number, "formula:1".
    std::string text() const;
    /// True for methods with a law of motion.
    bool has_motion() const { return row->has_motion(); }
    /// True for the exact solution.
    bool is_exact() const { return row->role == method_role::exact; }
    /// The legend label, text with TeX math in $...$: "lowest order", "order 6", ...
    std::string label() const;
};

/// Parses NAME or NAME:N, or formula:EXPR (a user's formula, numbered 1: callers number
/// several in their order); throws domain_error naming the text and listing the methods.
method_choice parse_method(std::string_view text);

/// The period ratio T/T0 of the method at amplitude theta0.
double method_period(const method_choice& m, const amplitude& theta0);

/// The period error T_m/T - 1 of the method at amplitude theta0, right to 1e-12 relative
/// down to 1e-300 (below that, and where no period exists, it says so), or correctly rounded.
period_error method_period_error(const method_choice& m, const amplitude& theta0, precision p = precision::drawing);

/// The truncated Fourier solution of a motion method other than "exact"; throws
/// domain_error for exact and for period-only methods.
fourier_solution method_solution(const method_choice& m, const amplitude& theta0);

/// The names of the table as one line, "exact, harmonic, ..., order:N, agm:N, ...".
std::string method_names();

}  // namespace pendulum
