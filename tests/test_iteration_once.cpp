// SPDX-License-Identifier: GPL-3.0-or-later
// The order-N iteration, written once over the number type (src/pendulum/iteration.hpp): the
// levels the tool prints on both sides of every threshold that picks extended precision or
// MPFR, against 40-digit references (tests/data/make_iteration_grid.py).
#include "pendulum/amplitude.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/gsl_support.hpp"
#include "pendulum/iteration.hpp"
#include "pendulum/mp_iteration.hpp"
#include "reference.hpp"
#include "reference_rows.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <numbers>
#include <string>
#include <vector>

namespace {

using namespace pendulum;

using test_support::rows::amplitude_of;
using test_support::rows::number;
using test_support::rows::split_at;
using test_support::rows::ulp;

/// The rows of iteration_grid.csv by amplitude.
std::map<std::string, std::vector<std::vector<std::string>>> grid_rows() {
    std::map<std::string, std::vector<std::vector<std::string>>> out;
    const auto rows = test_support::read_reference_text("iteration_grid.csv");
    for (std::size_t i = 1; i < rows.size(); ++i) out[rows[i].at(0)].push_back(rows[i]);
    return out;
}

/// The worst errors of one amplitude's levels, in ulps (periods) and ulps of c1 (coefficients).
struct worst_errors {
    double period = 0;
    double coefficient = 0;
};

/// Compares every level with its reference row: T_N/T0 and the coefficients given.
worst_errors check_levels(const std::string& which, const std::vector<fourier_solution>& levels,
                          const std::vector<std::vector<std::string>>& rows, double allowed) {
    worst_errors worst;
    EXPECT_EQ(levels.size(), rows.size()) << which;
    for (std::size_t n = 0; n < std::min(levels.size(), rows.size()); ++n) {
        const auto& f = rows[n];
        if (f.size() < 3 || f.at(2).empty()) {
            EXPECT_FALSE(levels[n].exists()) << which << " order " << n;
            continue;
        }
        const double want = number(f.at(2));
        const double u = std::fabs(levels[n].period_ratio() - want) / ulp(want);
        EXPECT_LE(u, allowed) << which << " order " << n << ": T/T0 " << format_double(levels[n].period_ratio())
                              << ", want " << f.at(2);
        worst.period = std::max(worst.period, u);
        if (f.size() < 4 || f.at(3).empty()) continue;
        const auto c = split_at(f.at(3), ';');
        EXPECT_EQ(c.size(), levels[n].coefficients.size()) << which << " order " << n;
        for (std::size_t k = 0; k < std::min(c.size(), levels[n].coefficients.size()); ++k) {
            const double uc = std::fabs(levels[n].coefficients[k] - number(c[k])) / ulp(levels[n].coefficients[0]);
            EXPECT_LE(uc, allowed) << which << " order " << n << " c" << 2 * k + 1;
            worst.coefficient = std::max(worst.coefficient, uc);
        }
    }
    return worst;
}

TEST(IterationOnce, EveryLevelWithinFourUlpsOnBothSidesOfTheSwitch) {
    // pi - 0.0201 (extended precision, to order 200), pi - 0.0199 (MPFR) and 0.99pi: in
    // doubles eval --theta0 pi-0.0201 --order 37 gave 3.811200505147771 [3.81120050514781661].
    ASSERT_EQ(detail::iteration_mp_below, 0.02);
    const auto rows = grid_rows();
    ASSERT_EQ(rows.size(), 3u);
    for (const auto& [which, levels_rows] : rows) {
        const int order = static_cast<int>(levels_rows.size()) - 1;
        const auto worst = check_levels(which, iterated_sequence(amplitude_of(which), order), levels_rows, 4);
        std::cout << which << " to order " << order << ": worst T_N/T0 " << worst.period << " ulps, worst c_k "
                  << worst.coefficient << " ulps of c1\n";
    }
}

TEST(IterationOnce, BothSidesOfTheSmallAmplitudeBranchAgreeWithTheMpfrTemplate) {
    // The extended levels take sin(theta0 u)/theta0 from its Taylor polynomial below
    // small_amplitude (1e-8): on both sides every coefficient is within 4 ulps of c1 of the
    // same template run in MPFR with 256 bits (which iteration_grid.csv checks against mpmath).
    ASSERT_EQ(small_amplitude, 1e-8);
    for (const double theta0 : {1e-8, std::nextafter(1e-8, 0.0), 1e-300}) {
        const auto levels = iterated_sequence(amplitude(theta0), 12);
        const auto x = mp::exact_amplitude(amplitude(theta0), 256);
        std::vector<std::vector<mp::real>> u;
        const auto lambdas = detail::mp_lambdas(x, 12, 256, {}, &u);
        for (std::size_t n = 0; n < levels.size(); ++n) {
            ASSERT_TRUE(lambdas[n].has_value());
            EXPECT_EQ(levels[n].frequency_ratio, mp::sqrt(*lambdas[n]).to_double()) << theta0 << " order " << n;
            for (std::size_t k = 0; k < u[n].size(); ++k) {
                const double want = (u[n][k] * x.theta).to_double();
                EXPECT_LE(std::fabs(levels[n].coefficients[k] - want), 4 * ulp(levels[n].coefficients[0]))
                    << theta0 << " order " << n << " c" << 2 * k + 1;
            }
        }
    }
}

}  // namespace
