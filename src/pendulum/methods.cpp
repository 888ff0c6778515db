// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/methods.hpp"

#include "pendulum/amplitude.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/formula_methods.hpp"
#include "pendulum/formula.hpp"
#include "pendulum/period_formulas.hpp"

#include <array>
#include <charconv>

namespace pendulum {

namespace {

/// The Fourier solution of a motion method, as a table entry.
template <fourier_solution (*f)(const amplitude&)>
fourier_solution solution_of(const amplitude& theta0, int) {
    return f(theta0);
}

/// The period of a motion method, from its Fourier solution.
template <fourier_solution (*f)(const amplitude&)>
double period_of(const amplitude& theta0, int) {
    return f(theta0).period_ratio();
}

/// The period of a formula without N, as a table entry.
template <double (*f)(const amplitude&)>
double closed_form(const amplitude& theta0, int) {
    return f(theta0);
}

/// A legend label that does not depend on N.
template <const char* text>
std::string fixed(int) {
    return text;
}

constexpr char exact_label[] = "exact";
constexpr char harmonic_label[] = "harmonic";
constexpr char lowest_label[] = "lowest order";
constexpr char first_label[] = "first order";
constexpr char second_label[] = "second order";
constexpr char polynomial_label[] = "polynomial";
constexpr char kidd_fogg_label[] = "Kidd\u2013Fogg";
constexpr char lima_arun_label[] = "Lima\u2013Arun";
constexpr char ganley_label[] = "Ganley";
constexpr char denman_label[] = "Denman";
constexpr char log_asymptote_label[] = "log asymptote";
constexpr char molina_label[] = "Molina";

std::string order_label(int n) { return "order " + std::to_string(n); }
std::string agm_label(int n) { return "AGM, " + std::to_string(n) + (n == 1 ? " step" : " steps"); }
std::string series_label(int n) { return "series to $\\vartheta_0^{" + std::to_string(2 * n) + "}$"; }

constexpr std::array<method_row, 15> rows = {{
    {"exact", method_role::exact, fixed<exact_label>, -1, 0, "the exact solution (Jacobi elliptic functions)", closed_form<period_ratio>,
     nullptr, exact_period_error},
    {"harmonic", method_role::approximant, fixed<harmonic_label>, -1, 0, "small-amplitude motion theta0 cos(w0 t)", period_of<harmonic>,
     solution_of<harmonic>, harmonic_period_error},
    {"lowest", method_role::approximant, fixed<lowest_label>, -1, 0, "the paper's lowest order: c1 = theta0, besinc frequency",
     period_of<lowest_order>, solution_of<lowest_order>, lowest_period_error},
    {"first", method_role::approximant, fixed<first_label>, -1, 0, "the paper's first order: c1', c3'", period_of<first_order>,
     solution_of<first_order>, first_period_error},
    {"second", method_role::approximant, fixed<second_label>, -1, 0, "the paper's second order (appendix): c1'', c3'', c5''",
     period_of<second_order>, solution_of<second_order>, second_period_error},
    {"polynomial", method_role::approximant, fixed<polynomial_label>, -1, 0, "Taylor polynomials through theta0^5 (Fulcher and Davis)",
     period_of<polynomial>, solution_of<polynomial>, polynomial_period_error},
    {"order", method_role::iterated, order_label, 0, max_order, "the paper's iteration to order N (N + 1 harmonics)",
     [](const amplitude& t, int n) { return iterated(t, n).period_ratio(); },
     [](const amplitude& t, int n) { return iterated(t, n); }, iterated_period_error},
    {"kidd-fogg", method_role::period_only, fixed<kidd_fogg_label>, -1, 0, "period 1/sqrt(k') (Kidd and Fogg 2002)",
     closed_form<period_kidd_fogg>, nullptr, kidd_fogg_period_error},
    {"lima-arun", method_role::period_only, fixed<lima_arun_label>, -1, 0, "period -ln(k')/(1 - k') (Lima and Arun 2006)",
     closed_form<period_lima_arun>, nullptr, lima_arun_period_error},
    {"ganley", method_role::period_only, fixed<ganley_label>, -1, 0, "period sqrt(F theta0/sin(F theta0)), F = sqrt(3)/2 (Ganley 1985)",
     closed_form<period_ganley>, nullptr, ganley_period_error},
    {"agm", method_role::period_only, agm_label, 1, max_agm_steps, "period after N AGM steps (Carvalhaes and Suppes 2008)",
     period_agm, nullptr, agm_period_error},
    {"denman", method_role::period_only, fixed<denman_label>, -1, 0, "period 1/(1 - theta0^2/16) (Denman 1959)", closed_form<period_denman>,
     nullptr, denman_period_error},
    {"series", method_role::period_only, series_label, 1, max_series_terms, "Taylor series of the period through theta0^(2N)",
     period_series, nullptr, series_period_error},
    {"log-asymptote", method_role::period_only, fixed<log_asymptote_label>, -1, 0, "large-amplitude asymptote (2/pi) ln(4/k')",
     closed_form<period_log_asymptote>, nullptr, log_asymptote_period_error},
    {"molina", method_role::period_only, fixed<molina_label>, -1, 0, "period (sin(theta0)/theta0)^(-3/8) (Molina 1997)",
     closed_form_period<formulas::molina>, nullptr, closed_form_period_error<formulas::molina>},
}};

/// The rows of a user's formula (not in the table: the formula rides in method_choice::user).
[[noreturn]] void no_formula() { throw domain_error("a formula method is evaluated through its formula"); }
double formula_row_period(const amplitude&, int) { no_formula(); }
period_error formula_row_error(const amplitude&, int, precision) { no_formula(); }
std::string formula_row_label(int n) { return "formula " + std::to_string(n); }

constexpr method_row period_formula_row = {"formula", method_role::period_only, formula_row_label, 1, 0,
                                           "a user's formula for T/T0 in theta0", formula_row_period, nullptr,
                                           formula_row_error};
constexpr method_row motion_formula_row = {"formula", method_role::approximant, formula_row_label, 1, 0,
                                           "a user's formula for theta(t) in t and theta0", formula_row_period,
                                           nullptr, formula_row_error};

constexpr std::string_view formula_prefix = "formula:";

}  // namespace

std::span<const method_row> method_table() { return rows; }

std::string method_choice::text() const {
    return n < 0 ? std::string(row->name) : std::string(row->name) + ":" + std::to_string(n);
}

std::string method_choice::label() const { return user ? user->text() : row->label(n); }

std::string method_names() {
    std::string out;
    for (const auto& r : rows) out += (out.empty() ? "" : ", ") + std::string(r.name) + (r.min_n < 0 ? "" : ":N");
    return out + ", formula:EXPR";
}

method_choice parse_method(std::string_view text) {
    if (text.starts_with(formula_prefix)) {
        auto f = std::make_shared<const formula>(text.substr(formula_prefix.size()));
        return {f->uses_t() ? &motion_formula_row : &period_formula_row, 1, std::move(f)};
    }
    const auto colon = text.find(':');
    const std::string_view name = text.substr(0, colon);
    for (const auto& r : rows) {
        if (r.name != name) continue;
        if (r.min_n < 0) {
            if (colon != std::string_view::npos) {
                throw domain_error("method '" + std::string(text) + "': " + std::string(name) + " takes no :N");
            }
            return {&r, -1, nullptr};
        }
        const std::string range = std::to_string(r.min_n) + ".." + std::to_string(r.max_n);
        if (colon == std::string_view::npos) {
            throw domain_error("method '" + std::string(text) + "' needs N, as in " + std::string(name) + ":" +
                               std::to_string(r.min_n + 1) + " (N in " + range + ")");
        }
        const std::string_view digits = text.substr(colon + 1);
        int n = -1;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
        if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() || n < r.min_n ||
            n > r.max_n) {
            throw domain_error("method '" + std::string(text) + "': N must be a whole number in " + range);
        }
        return {&r, n, nullptr};
    }
    throw domain_error("unknown method '" + std::string(text) + "'; methods: " + method_names());
}

double method_period(const method_choice& m, const amplitude& theta0) {
    if (m.user) {
        if (m.user->uses_t()) throw domain_error("method " + m.text() + " is a law of motion theta(t); its period is not defined");
        return formula_period(*m.user, theta0);
    }
    return m.row->period(theta0, m.n);
}

period_error method_period_error(const method_choice& m, const amplitude& theta0, precision p) {
    if (m.user) {
        if (m.user->uses_t()) throw domain_error("method " + m.text() + " is a law of motion theta(t); its period error is not defined");
        return formula_period_error(*m.user, theta0);
    }
    return m.row->error(theta0, m.n, p);
}

fourier_solution method_solution(const method_choice& m, const amplitude& theta0) {
    if (!m.row->solution) {
        throw domain_error("method " + m.text() + " gives " +
                           (m.has_motion() ? std::string("the exact motion, not a Fourier approximant")
                                           : std::string("a period only, not a law of motion")));
    }
    return m.row->solution(theta0, m.n);
}

}  // namespace pendulum
