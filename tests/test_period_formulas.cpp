// SPDX-License-Identifier: GPL-3.0-or-later
// The period formulas of the literature against 50-digit references
// (tests/data/make_period_formulas.py).
#include "pendulum/amplitude.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/period_formulas.hpp"
#include "reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace {

using namespace pendulum;

struct formula_column {
    std::string name;
    std::function<double(double)> period;
};

/// The columns of period_formulas.csv, in order after theta0.
std::vector<formula_column> columns() {
    std::vector<formula_column> c = {{"kidd-fogg", period_kidd_fogg},
                                     {"lima-arun", period_lima_arun},
                                     {"ganley", period_ganley},
                                     {"denman", period_denman},
                                     {"log-asymptote", period_log_asymptote}};
    for (int n : {0, 1, 2, 3, 5}) c.push_back({"agm:" + std::to_string(n), [n](double t) { return period_agm(t, n); }});
    for (int n : {0, 1, 2, 3, 6, 10, 20}) {
        c.push_back({"series:" + std::to_string(n), [n](double t) { return period_series(t, n); }});
    }
    return c;
}

TEST(PeriodFormulas, MatchTheReferenceToRounding) {
    const auto rows = test_support::read_reference("period_formulas.csv");
    const auto cols = columns();
    for (const auto& row : rows) {
        ASSERT_EQ(row.size(), cols.size() + 1);
        const double theta0 = row[0];
        for (std::size_t i = 0; i < cols.size(); ++i) {
            const double want = row[i + 1];
            const double got = cols[i].period(theta0);
            // The series sums up to 21 positive terms: a few more roundings than the closed forms.
            const double tolerance = cols[i].name.starts_with("series") ? 1e-15 : 5e-16;
            EXPECT_LE(std::fabs(got / want - 1), tolerance)
                << cols[i].name << " at theta0 = " << format_double(theta0) << ": got " << format_double(got)
                << ", want " << format_double(want);
        }
    }
}

TEST(PeriodFormulas, SpecialCasesOfTheFamilies) {
    for (double t : {0.1, 1.0, 2.5, 3.1}) {
        const double kp = std::cos(t / 2);
        EXPECT_EQ(period_agm(t, 0), 1.0);
        EXPECT_DOUBLE_EQ(period_agm(t, 1), 2.0 / (1.0 + kp));
        EXPECT_DOUBLE_EQ(period_agm(t, 2), 4.0 / ((1.0 + std::sqrt(kp)) * (1.0 + std::sqrt(kp))));
        EXPECT_EQ(period_series(t, 0), 1.0);
        // Through theta0^4 the series is the polynomial approximant's period.
        EXPECT_DOUBLE_EQ(period_series(t, 2), polynomial(t).period_ratio());
    }
}

TEST(PeriodFormulas, RejectBadArguments) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (double t : {0.0, -1.0, std::numbers::pi, 4.0, nan}) {
        EXPECT_THROW(period_kidd_fogg(t), domain_error);
        EXPECT_THROW(period_lima_arun(t), domain_error);
        EXPECT_THROW(period_ganley(t), domain_error);
        EXPECT_THROW(period_denman(t), domain_error);
        EXPECT_THROW(period_log_asymptote(t), domain_error);
        EXPECT_THROW(period_agm(t, 1), domain_error);
        EXPECT_THROW(period_series(t, 2), domain_error);
    }
    EXPECT_THROW(period_agm(1.0, -1), domain_error);
    EXPECT_THROW(period_agm(1.0, max_agm_steps + 1), domain_error);
    EXPECT_THROW(period_series(1.0, -1), domain_error);
    EXPECT_THROW(period_series(1.0, max_series_terms + 1), domain_error);
}

}  // namespace
