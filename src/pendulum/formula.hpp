// SPDX-License-Identifier: GPL-3.0-or-later
// A user's formula: a period T/T0 = f(theta0) or a law of motion theta(t) = f(t, theta0),
// parsed once into a tree and evaluated many times (doubles for drawing, MPFR for errors).
#pragma once

#include "pendulum/amplitude.hpp"
#include "pendulum/period_error.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace pendulum {

/// The bounds of a formula's text and tree.
inline constexpr std::size_t max_formula_bytes = 1000;  ///< the text's length in bytes
inline constexpr int max_formula_depth = 64;            ///< nesting of parentheses, calls, signs and powers
inline constexpr std::size_t max_formula_nodes = 500;   ///< numbers, variables, operations and calls
inline constexpr int max_bessel_order = 1000;           ///< |n| of besselj(n, x)

/// The functions a formula may call, as one line for messages and help.
std::string formula_functions();

/// One node of a formula's tree (internal to the evaluators; public for the tree's layout).
struct formula_node {
    /// What the node is.
    enum class op {
        number, pi, theta0, t,                  // leaves
        add, sub, mul, div, pow, neg,           // arithmetic
        sqrt, exp, log, sin, cos, tan, asin, acos, atan, sinh, cosh, tanh, abs,  // one argument
        ellipk, ellipe,                         // complete elliptic integrals K(m), E(m)
        agm,                                    // agm(a, b)
        besselj,                                // J_n(x): n is `order`, the argument is `a`
    };
    op what = op::number;  ///< the operation
    int a = -1;            ///< first operand (index into the tree), or -1
    int b = -1;            ///< second operand, or -1
    int order = 0;         ///< besselj's n
    double value = 0;      ///< a number, rounded to a double
    std::string digits;    ///< a number as written, for MPFR at any precision
};

/// A parsed formula. Throws domain_error on bad text with "formula:1:COLUMN: what; ...".
class formula {
public:
    /// Parses `text` (at most max_formula_bytes, depth and nodes bounded).
    explicit formula(std::string_view text);

    /// The text as given.
    const std::string& text() const { return text_; }
    /// True where the formula uses t: a law of motion theta(t); false for a period T/T0.
    bool uses_t() const { return uses_t_; }
    /// The value in doubles at theta0 (and t): may be NaN or infinite.
    double value(double theta0, double t = 0) const;
    /// The tree, root last.
    const std::vector<formula_node>& nodes() const { return nodes_; }

private:
    std::string text_;
    std::vector<formula_node> nodes_;
    bool uses_t_ = false;
};

/// The formula as TeX math (without the dollars), for its default label: sqrt as \sqrt,
/// theta0 as \theta_0, pi as \pi, / as \frac, * as a thin space (\cdot before a number),
/// functions by their TeX names (log is \ln), written from the tree, so parentheses stand
/// only where precedence needs them.
std::string formula_tex(const formula& f);

/// T/T0 of a period formula at theta0: in doubles where the amplitude is its double, in
/// MPFR from the exact amplitude otherwise (close to pi, from an expression). NaN where
/// the formula is not finite.
double formula_period(const formula& f, const amplitude& theta0);

/// T_f/T - 1 of a period formula, right to 1e-13 relative (MPFR, precision raised until two
/// agree); below_limit under 1e-300; no_period where the formula is not finite;
/// not_computed where no precision up to 2304 bits resolves it.
period_error formula_period_error(const formula& f, const amplitude& theta0);

/// The most seconds one formula_period_error of f is estimated to take (its work is
/// counted and bounded: where it runs out the error is not_computed), for a render's cost.
double formula_error_seconds(const formula& f);

}  // namespace pendulum
