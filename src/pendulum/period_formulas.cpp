// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/period_formulas.hpp"

#include "pendulum/amplitude.hpp"
#include "pendulum/formulas.hpp"

#include <string>

namespace pendulum {

namespace {

void check_count(int n, int largest, const char* what) {
    if (n < 0 || n > largest) {
        throw domain_error(std::string(what) + " must be between 0 and " + std::to_string(largest) + ", got " +
                           std::to_string(n));
    }
}

}  // namespace

// Each formula is the template of formulas.hpp, in doubles.

static_assert(formulas::series_coefficients.size() == max_series_terms + 1, "a coefficient for every term");

double period_kidd_fogg(const amplitude& a) { return formulas::kidd_fogg{}(formulas::view_of(a), 0); }

double period_lima_arun(const amplitude& a) { return formulas::lima_arun{}(formulas::view_of(a), 0); }

double period_ganley(const amplitude& a) { return formulas::ganley{}(formulas::view_of(a), 0); }

double period_agm(const amplitude& a, int steps) {
    check_count(steps, max_agm_steps, "the number of AGM steps");
    return formulas::agm{}(formulas::view_of(a), steps);
}

double period_denman(const amplitude& a) { return formulas::denman{}(formulas::view_of(a), 0); }

double period_series(const amplitude& a, int terms) {
    check_count(terms, max_series_terms, "the number of series terms");
    // In extended precision: near pi the sum is up to N times as sensitive to theta0^2 as to
    // its own rounding (6 ulps for N = 20 in doubles).
    return static_cast<double>(formulas::series{}(formulas::view_extended(a), terms));
}

double period_log_asymptote(const amplitude& a) { return formulas::log_asymptote{}(formulas::view_of(a), 0); }

}  // namespace pendulum
