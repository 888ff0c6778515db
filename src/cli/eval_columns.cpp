// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/eval_columns.hpp"

#include <array>

namespace pendulum::cli {

eval_point::eval_point(const amplitude& t)
    : theta0(t.radians()),
      exact(t),
      lowest(lowest_order(t)),
      first(first_order(t)),
      second(second_order(t)),
      polynomial(pendulum::polynomial(t)) {}

namespace {

constexpr std::array<eval_column, 17> columns = {{
    {"theta0", "the amplitude in radians", [](const eval_point& p) { return p.theta0; }},
    {"period_exact", "T/T0, exact", [](const eval_point& p) { return p.exact.period_ratio(); }},
    {"period_lowest", "T/T0, lowest order", [](const eval_point& p) { return p.lowest.period_ratio(); }},
    {"period_first", "T/T0, first order", [](const eval_point& p) { return p.first.period_ratio(); }},
    {"period_second", "T/T0, second order", [](const eval_point& p) { return p.second.period_ratio(); }},
    {"c1_exact", "c1, exact", [](const eval_point& p) { return p.exact.coefficient(0); }},
    {"c3_exact", "c3, exact", [](const eval_point& p) { return p.exact.coefficient(1); }},
    {"c5_exact", "c5, exact", [](const eval_point& p) { return p.exact.coefficient(2); }},
    {"c1_lowest", "c1, lowest order (= theta0)", [](const eval_point& p) { return p.lowest.coefficients[0]; }},
    {"c1_first", "c1', first order", [](const eval_point& p) { return p.first.coefficients[0]; }},
    {"c3_first", "c3', first order", [](const eval_point& p) { return p.first.coefficients[1]; }},
    {"c1_second", "c1'', second order", [](const eval_point& p) { return p.second.coefficients[0]; }},
    {"c3_second", "c3'', second order", [](const eval_point& p) { return p.second.coefficients[1]; }},
    {"c5_second", "c5'', second order", [](const eval_point& p) { return p.second.coefficients[2]; }},
    {"c1_poly", "c1, polynomial", [](const eval_point& p) { return p.polynomial.coefficients[0]; }},
    {"c3_poly", "c3, polynomial", [](const eval_point& p) { return p.polynomial.coefficients[1]; }},
    {"c5_poly", "c5, polynomial", [](const eval_point& p) { return p.polynomial.coefficients[2]; }},
}};

}  // namespace

std::span<const eval_column> eval_columns() { return columns; }

std::string eval_columns_help() {
    std::string out;
    for (const auto& c : columns) {
        out += (out.empty() ? "" : ", ") + std::string(c.name) + " (" + std::string(c.description) + ")";
    }
    return out;
}

}  // namespace pendulum::cli
