// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/eval_columns.hpp"

#include "cli/errors.hpp"
#include "cli/options.hpp"
#include "pendulum/period_error.hpp"

#include <array>
#include <limits>

namespace pendulum::cli {

eval_point::eval_point(const amplitude& t, unsigned needs) : theta0(t.radians()), from_pi(t.from_pi()) {
    if (needs & need_exact) exact.emplace(t);
    // The same rounding of the same AGM as the solution's.
    if (needs & need_exact_period) exact_period = exact ? exact->period_ratio() : pendulum::period_ratio(t);
    if (needs & need_lowest) lowest.emplace(lowest_order(t));
    if (needs & need_first) first.emplace(first_order(t));
    if (needs & need_second) second.emplace(second_order(t));
    if (needs & need_polynomial) polynomial.emplace(pendulum::polynomial(t));
}

namespace {

constexpr std::array<eval_column, 18> columns = {{
    {"theta0", "the amplitude in radians", 0, [](const eval_point& p) { return p.theta0; }},
    {"period_exact", "T/T0, exact", need_exact_period, [](const eval_point& p) { return *p.exact_period; }},
    {"period_lowest", "T/T0, lowest order", need_lowest, [](const eval_point& p) { return p.lowest->period_ratio(); }},
    {"period_first", "T/T0, first order", need_first, [](const eval_point& p) { return p.first->period_ratio(); }},
    {"period_second", "T/T0, second order", need_second, [](const eval_point& p) { return p.second->period_ratio(); }},
    {"c1_exact", "c1, exact", need_exact, [](const eval_point& p) { return p.exact->coefficient(0); }},
    {"c3_exact", "c3, exact", need_exact, [](const eval_point& p) { return p.exact->coefficient(1); }},
    {"c5_exact", "c5, exact", need_exact, [](const eval_point& p) { return p.exact->coefficient(2); }},
    {"c1_lowest", "c1, lowest order (= theta0)", need_lowest, [](const eval_point& p) { return p.lowest->coefficients[0]; }},
    {"c1_first", "c1', first order", need_first, [](const eval_point& p) { return p.first->coefficients[0]; }},
    {"c3_first", "c3', first order", need_first, [](const eval_point& p) { return p.first->coefficients[1]; }},
    {"c1_second", "c1'', second order", need_second, [](const eval_point& p) { return p.second->coefficients[0]; }},
    {"c3_second", "c3'', second order", need_second, [](const eval_point& p) { return p.second->coefficients[1]; }},
    {"c5_second", "c5'', second order", need_second, [](const eval_point& p) { return p.second->coefficients[2]; }},
    {"c1_poly", "c1, polynomial", need_polynomial, [](const eval_point& p) { return p.polynomial->coefficients[0]; }},
    {"c3_poly", "c3, polynomial", need_polynomial, [](const eval_point& p) { return p.polynomial->coefficients[1]; }},
    {"c5_poly", "c5, polynomial", need_polynomial, [](const eval_point& p) { return p.polynomial->coefficients[2]; }},
    // Close to pi every theta0 prints as 3.141592653589793; its distance from pi keeps the
    // amplitude. Only with --columns, so that the default table stays as it was.
    {"pi_minus_theta0", "pi - theta0, exact close to pi where theta0 prints as 3.141592653589793; only with --columns", 0,
     [](const eval_point& p) { return p.from_pi; }, false},
}};

}  // namespace

std::span<const eval_column> eval_columns() { return columns; }

std::optional<method_choice> error_column_method(std::string_view name) {
    if (!name.starts_with(error_column_prefix)) return std::nullopt;
    try {
        return parse_method(name.substr(error_column_prefix.size()));
    } catch (const domain_error& e) {
        throw usage_error("--columns '" + shown_text(std::string(name)) + "': " + e.what());
    }
}

std::variant<std::string, double> period_error_field(const period_error& e) {
    switch (e.what) {
        case period_error::kind::value: return e.value;
        case period_error::kind::below_limit: return std::string("below_limit");
        case period_error::kind::not_computed: return std::string("not_computed");
        case period_error::kind::no_period: break;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

std::string eval_columns_help() {
    std::string out;
    for (const auto& c : columns) {
        out += (out.empty() ? "" : ", ") + std::string(c.name) + " (" + std::string(c.description) + ")";
    }
    return out;
}

}  // namespace pendulum::cli
