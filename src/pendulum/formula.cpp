// SPDX-License-Identifier: GPL-3.0-or-later
// The formula language as rows of the one expression parser (expression_parser.hpp), and a
// formula's evaluation in doubles.
#include "pendulum/formula.hpp"

#include "pendulum/angle.hpp"
#include "pendulum/expression_parser.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace pendulum {

namespace {

using op = formula_node::op;

/// The functions a formula may call.
constexpr std::array<grammar::function_row, 17> functions = {{
    {"sqrt", op::sqrt, 1, ""},   {"exp", op::exp, 1, ""},       {"log", op::log, 1, ""},       {"sin", op::sin, 1, ""},
    {"cos", op::cos, 1, ""},     {"tan", op::tan, 1, ""},       {"asin", op::asin, 1, ""},     {"acos", op::acos, 1, ""},
    {"atan", op::atan, 1, ""},   {"sinh", op::sinh, 1, ""},     {"cosh", op::cosh, 1, ""},     {"tanh", op::tanh, 1, ""},
    {"abs", op::abs, 1, ""},     {"ellipk", op::ellipk, 1, ""}, {"ellipe", op::ellipe, 1, ""}, {"agm", op::agm, 2, "(a, b)"},
    {"besselj", op::besselj, 2, "(n, x)", true},
}};

/// The variables and constants by name ("θ0" and "π" are their Greek spellings).
constexpr std::array<grammar::name_row, 5> names = {{
    {"theta0", op::theta0}, {"\u03b80", op::theta0}, {"t", op::t}, {"pi", op::pi}, {"\u03c0", op::pi},
}};

/// The operators, loosest first: + and -, * and /, ^ (right-associative, tighter than a sign).
constexpr std::array<grammar::operator_row, 5> operators = {{
    {'+', op::add, 1, false}, {'-', op::sub, 1, false}, {'*', op::mul, 2, false}, {'/', op::div, 2, false},
    {'^', op::pow, 4, true},
}};

/// "formula:1:COLUMN: why": the column counts characters from 1.
std::string formula_message(std::string_view text, std::size_t at, const std::string& why) {
    std::size_t column = 1;
    for (std::size_t i = 0; i < at && i < text.size(); ++i) {
        if ((static_cast<unsigned char>(text[i]) & 0xc0) != 0x80) ++column;
    }
    return "formula:1:" + std::to_string(column) + ": " + why;
}

double node_value(const std::vector<formula_node>& nodes, int i, double theta0, double t);

double constant_value(const std::vector<formula_node>& nodes, int i) { return node_value(nodes, i, 0, 0); }

const grammar::language formula_language{
    .names = names,
    .functions = functions,
    .operators = operators,
    .units = {},
    .max_bytes = max_formula_bytes,
    .max_depth = max_formula_depth,
    .max_nodes = max_formula_nodes,
    .max_order = max_bessel_order,
    .noun = "formula",
    .a_noun = "a formula",
    .nesting = "parentheses, calls, signs and exponents",
    .empty = "empty formula; write T/T0 in theta0, e.g. 1/sqrt(cos(theta0/2))",
    .functions_note = "(ellipk and ellipe take the parameter m = k^2)",
    .message = formula_message,
    .constant = constant_value,
};

// ---- Doubles.

double agm_double(double a, double b) {
    if (std::isnan(a) || std::isnan(b) || a < 0 || b < 0) return std::nan("");
    if (a == 0 || b == 0) return 0;
    if (std::isinf(a) || std::isinf(b)) return std::numeric_limits<double>::infinity();
    for (int i = 0; i < 100 && a != b; ++i) {
        const double next = (a + b) / 2;
        b = std::sqrt(a * b);
        if (next == a) break;
        a = next;
    }
    return a;
}

double ellipk_double(double m) {
    if (m == 1) return std::numeric_limits<double>::infinity();
    if (!(m < 1)) return std::nan("");
    return std::numbers::pi / (2 * agm_double(1, std::sqrt(1 - m)));
}

/// E(m) = K(m) (1 - sum 2^(n-1) c_n^2) along the AGM of 1 and sqrt(1 - m), c_0^2 = m.
double ellipe_double(double m) {
    if (m == 1) return 1;
    if (!(m < 1)) return std::nan("");
    if (std::isinf(m)) return std::numeric_limits<double>::infinity();
    double a = 1;
    double b = std::sqrt(1 - m);
    double sum = m / 2;
    double weight = 0.5;
    for (int i = 0; i < 100; ++i) {
        const double c = (a - b) / 2;
        const double next = (a + b) / 2;
        b = std::sqrt(a * b);
        a = next;
        weight *= 2;
        sum += weight * c * c;
        if (std::fabs(weight * c * c) <= 1e-17 * std::fabs(sum) || c == 0) break;
    }
    return std::numbers::pi / (2 * a) * (1 - sum);
}

double one_argument(op what, double x) {
    switch (what) {
        case op::sqrt: return std::sqrt(x);
        case op::exp: return std::exp(x);
        case op::log: return std::log(x);
        case op::sin: return std::sin(x);
        case op::cos: return std::cos(x);
        case op::tan: return std::tan(x);
        case op::asin: return std::asin(x);
        case op::acos: return std::acos(x);
        case op::atan: return std::atan(x);
        case op::sinh: return std::sinh(x);
        case op::cosh: return std::cosh(x);
        case op::tanh: return std::tanh(x);
        case op::abs: return std::fabs(x);
        case op::ellipk: return ellipk_double(x);
        case op::ellipe: return ellipe_double(x);
        case op::neg: return -x;
        default: return std::nan("");
    }
}

double node_value(const std::vector<formula_node>& nodes, int i, double theta0, double t) {
    const auto& n = nodes[static_cast<std::size_t>(i)];
    const auto arg = [&](int j) { return node_value(nodes, j, theta0, t); };
    switch (n.what) {
        case op::number: return n.value;
        case op::pi: return std::numbers::pi;
        case op::theta0: return theta0;
        case op::t: return t;
        case op::add: return arg(n.a) + arg(n.b);
        case op::sub: return arg(n.a) - arg(n.b);
        case op::mul: return arg(n.a) * arg(n.b);
        case op::div: return arg(n.a) / arg(n.b);
        case op::pow: return std::pow(arg(n.a), arg(n.b));
        case op::agm: return agm_double(arg(n.a), arg(n.b));
        case op::besselj: return jn(n.order, arg(n.a));
        default: return one_argument(n.what, arg(n.a));
    }
}

}  // namespace

std::string formula_functions() { return grammar::functions_of(formula_language); }

formula::formula(std::string_view text) : text_(text) {
    grammar::tree t = grammar::parse(text, formula_language);
    nodes_ = std::move(t.nodes);
    uses_t_ = t.uses_t;
}

double formula::value(double theta0, double t) const {
    return node_value(nodes_, static_cast<int>(nodes_.size()) - 1, theta0, t);
}

}  // namespace pendulum
