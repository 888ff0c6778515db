// SPDX-License-Identifier: GPL-3.0-or-later
// The core library keeps no process-wide state: the host's GSL error handler stays its own
// through every core function (GSL is only called where it cannot fail, checked first), and
// how closely a period error is computed is a parameter of each call, not a mode.
#include <gtest/gtest.h>

#include "pendulum/amplitude.hpp"
#include "pendulum/angle.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/claims.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/gsl_support.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/motion.hpp"
#include "pendulum/period_error.hpp"
#include "reference.hpp"

#include <gsl/gsl_errno.h>

#include <cfloat>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace pendulum;
using std::numbers::pi;

/// How often GSL called the host's handler.
int host_handler_calls = 0;

void host_handler(const char*, const char*, int, int) { ++host_handler_calls; }

/// Installs host_handler for one test and puts the previous handler back afterwards.
class HostHandler : public ::testing::Test {
protected:
    void SetUp() override {
        host_handler_calls = 0;
        previous_ = gsl_set_error_handler(host_handler);
    }
    void TearDown() override { gsl_set_error_handler(previous_); }

    /// True while GSL's handler is still host_handler (read by setting it again).
    static bool still_host_handler() { return gsl_set_error_handler(host_handler) == host_handler; }

private:
    gsl_error_handler_t* previous_ = nullptr;
};

double minus_half(double x, void*) { return x - 0.5; }
double not_finite(double x, void*) { return x < 0.5 ? -1.0 : std::nan(""); }

}  // namespace

TEST_F(HostHandler, StaysThroughEveryCoreFunction) {
    for (const double theta0 : {1e-9, 1e-3, 0.5, pi / 2, 3.1, pi - 1e-9}) {
        const exact_solution exact(theta0);
        (void)exact.coefficient_by_quadrature(1);
        (void)iterated(theta0, 4);
        (void)first_order(theta0);
        (void)motion::from_state({theta0, 0.25}).theta(2.0);
        for (const auto& row : method_table()) {
            const method_choice m{&row, row.min_n < 0 ? -1 : row.min_n, nullptr};
            (void)method_period_error(m, theta0);
            (void)method_period_error(m, theta0, precision::correctly_rounded);
        }
        EXPECT_TRUE(still_host_handler()) << theta0;
    }
    (void)find_amplitude(minus_half, nullptr, 0.0, 1.0);
    (void)max_deviation_over_period("second", 2.5);
    EXPECT_TRUE(still_host_handler());
    EXPECT_EQ(host_handler_calls, 0);
}

TEST_F(HostHandler, ClaimsLeaveItInPlace) {
    EXPECT_FALSE(paper_claims().empty());
    EXPECT_TRUE(still_host_handler());
    EXPECT_EQ(host_handler_calls, 0);
}

// Inputs that GSL refuses through its handler are refused before GSL sees them.
TEST_F(HostHandler, RootWithoutBracketIsRefusedBeforeGsl) {
    try {
        (void)find_amplitude(minus_half, nullptr, 0.6, 1.0);
        FAIL() << "no root in [0.6, 1] was accepted";
    } catch (const domain_error& e) {
        EXPECT_NE(std::string(e.what()).find("same sign at both ends"), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)find_amplitude(minus_half, nullptr, 1.0, 0.0), domain_error);
    EXPECT_THROW((void)find_amplitude(minus_half, nullptr, std::nan(""), 1.0), domain_error);
    // Not finite inside the bracket: GSL's "function value is not finite" never reached.
    EXPECT_THROW((void)find_amplitude(not_finite, nullptr, 0.0, 0.4), domain_error);
    EXPECT_THROW((void)find_amplitude(not_finite, nullptr, 0.0, 1.0), domain_error);
    EXPECT_EQ(host_handler_calls, 0);
    EXPECT_TRUE(still_host_handler());
}

TEST_F(HostHandler, EllipticIntegralOutsideGslDomainIsRefusedBeforeGsl) {
    // x + y = 0: k'^2 s^2 underflows (GSL's DOMAIN_ERROR).
    try {
        (void)elliptic_f(1.0, 0.0, 1e-170);
        FAIL() << "R_F(0, 0, 1) was accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "the elliptic integral R_F failed: input domain error");
    }
    EXPECT_EQ(host_handler_calls, 0);
}

// The limits of each GSL routine's checked range: N accepted, N + 1 refused.
TEST_F(HostHandler, CarlsonRfDomainBoundaries) {
    const double lowest = 5.0 * DBL_MIN;
    EXPECT_GT(carlson_rf(lowest, 0.0, 1.0), 0.0);
    EXPECT_THROW((void)carlson_rf(std::nextafter(lowest, 0.0), 0.0, 1.0), std::runtime_error);
    const double highest = 0.2 * DBL_MAX;
    EXPECT_GT(carlson_rf(1.0, 1.0, std::nextafter(highest, 0.0)), 0.0);
    EXPECT_THROW((void)carlson_rf(1.0, 1.0, highest), std::runtime_error);
    EXPECT_THROW((void)carlson_rf(-0.0 - DBL_MIN, 1.0, 1.0), std::runtime_error);
    EXPECT_THROW((void)carlson_rf(std::nan(""), 1.0, 1.0), std::runtime_error);
    EXPECT_EQ(host_handler_calls, 0);
}

TEST_F(HostHandler, BesselRangeBoundaries) {
    EXPECT_NO_THROW((void)bessel_j(bessel_j_max_order, 4.0));
    EXPECT_NO_THROW((void)bessel_j(bessel_j_max_order, small_amplitude));
    EXPECT_NO_THROW((void)bessel_j(1, -4.0));
    try {
        (void)bessel_j(bessel_j_max_order + 1, 1.0);
        FAIL() << "J4 was accepted";
    } catch (const domain_error& e) {
        EXPECT_NE(std::string(e.what()).find("1 <= n <= 3"), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)bessel_j(0, 1.0), domain_error);
    EXPECT_THROW((void)bessel_j(1, std::nextafter(4.0, 5.0)), domain_error);
    EXPECT_THROW((void)bessel_j(3, std::nextafter(small_amplitude, 0.0)), domain_error);
    EXPECT_THROW((void)bessel_j(1, std::nan("")), domain_error);
    // J_n(x)/x by its series below 1e-8, down to the smallest subnormal.
    EXPECT_NEAR(bessel_j_over_x(3, 4.9e-324), 0.0, 1e-300);
    EXPECT_DOUBLE_EQ(bessel_j_over_x(1, 4.9e-324), 0.5);
    EXPECT_THROW((void)bessel_j_over_x(bessel_j_max_order + 1, 1.0), std::invalid_argument);
    EXPECT_EQ(host_handler_calls, 0);
}

TEST_F(HostHandler, QuadratureConvergesUpToTheSeparatrix) {
    for (const double d : {1e-3, 1e-9}) {
        const exact_solution s(pendulum::amplitude::from_pi(d));
        for (int n = 0; n < 3; ++n) EXPECT_NEAR(s.coefficient_by_quadrature(n), s.coefficient(n), 1e-12) << d << " c" << 2 * n + 1;
    }
    EXPECT_EQ(host_handler_calls, 0);
}

// The claims' errors are correctly rounded because the calls ask for it (mpmath reference,
// tests/data/make_claims_errors.py); the same calls without it, before and after, give the
// drawing's errors, right to 1e-12: no mode outlives a call.
TEST(Precision, IsAParameterOfEachCall) {
    const auto rows = test_support::read_reference_text("claims_errors.csv");
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const std::string& method = rows[i][0];
        const std::string& at = rows[i][1];
        // The doubles the claims use (make_claims_errors.py rounds them as C++ does).
        const std::map<std::string, double> doubles = {
            {"pi/2", pi / 2}, {"9pi/10", 9 * pi / 10}, {"95pi/100", 95 * pi / 100}, {"99pi/100", 99 * pi / 100}};
        const amplitude theta0 = doubles.at(at);
        const double reference = std::stod(rows[i][2]) / 100;
        const method_choice m = parse_method(method);
        const auto drawing_before = method_period_error(m, theta0);
        const auto exact = method_period_error(m, theta0, precision::correctly_rounded);
        const auto drawing_after = method_period_error(m, theta0, precision::drawing);
        ASSERT_EQ(exact.what, period_error::kind::value);
        // Correctly rounded: within the rounding of the reference's decimal digits and /100.
        EXPECT_LE(std::fabs(exact.value - reference), 2 * DBL_EPSILON * std::fabs(reference)) << method << " at " << at;
        EXPECT_NEAR(drawing_before.value, reference, 1e-12 * std::fabs(reference)) << method << " at " << at;
        EXPECT_EQ(drawing_before.value, drawing_after.value) << method << " at " << at;
    }
}

TEST(Precision, ThreadsAskingDifferentlyDoNotMix) {
    const method_choice lowest = parse_method("lowest");
    const amplitude theta0 = pi / 2;
    const double drawing = method_period_error(lowest, theta0).value;
    const double rounded = method_period_error(lowest, theta0, precision::correctly_rounded).value;
    double drawing_meanwhile = 0;
    std::thread other([&] {
        for (int i = 0; i < 20; ++i) drawing_meanwhile = method_period_error(lowest, theta0).value;
    });
    for (int i = 0; i < 20; ++i) EXPECT_EQ(method_period_error(lowest, theta0, precision::correctly_rounded).value, rounded);
    other.join();
    EXPECT_EQ(drawing_meanwhile, drawing);
}

// Every period formula with a reference table method_NAME.csv (tests/data/method_reference.py
// and its make_method_NAME.py): T_m/T0 in doubles to a few ulps, the error T_m/T - 1 right to
// 1e-12 as drawn and to 1e-15 correctly rounded. A new formula adds its script and
// table, and this test reads them.
TEST(MethodReference, EveryMethodFile) {
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(PENDULUM_TEST_DATA)) {
        const std::string file = entry.path().filename().string();
        if (!file.starts_with("method_") || !file.ends_with(".csv")) continue;
        ++files;
        const std::string name = file.substr(7, file.size() - 11);
        const method_choice m = parse_method(name);
        const auto rows = test_support::read_reference_text(file);
        ASSERT_EQ(rows[0], (std::vector<std::string>{"theta0", "period", "error"})) << file;
        ASSERT_GE(rows.size(), 16u) << file;
        for (std::size_t i = 1; i < rows.size(); ++i) {
            const std::string& at = rows[i].at(0);
            const amplitude theta0 = parse_amplitude(at);
            const double period = std::stod(rows[i].at(1));
            EXPECT_LE(std::fabs(method_period(m, theta0) / period - 1), 1e-15) << name << " at " << at;
            const auto drawn = method_period_error(m, theta0);
            const auto exact = method_period_error(m, theta0, precision::correctly_rounded);
            if (rows[i].at(2) == "below") {
                EXPECT_EQ(drawn.what, period_error::kind::below_limit) << name << " at " << at;
                EXPECT_EQ(exact.what, period_error::kind::below_limit) << name << " at " << at;
                continue;
            }
            const double error = std::stod(rows[i].at(2));
            ASSERT_EQ(drawn.what, period_error::kind::value) << name << " at " << at;
            ASSERT_EQ(exact.what, period_error::kind::value) << name << " at " << at;
            EXPECT_LE(std::fabs(drawn.value / error - 1), 1e-12) << name << " at " << at;
            // Correctly rounded for the amplitude as the program holds it: away from pi an
            // expression's theta0 is rounded to a double first (a few ulps of the error here).
            EXPECT_LE(std::fabs(exact.value / error - 1), 1e-15) << name << " at " << at;
        }
    }
    EXPECT_GE(files, 1) << "no method_*.csv in " << PENDULUM_TEST_DATA;
}
