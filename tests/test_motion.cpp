// SPDX-License-Identifier: GPL-3.0-or-later
// The motion in all three regimes against 60-digit references (tests/data/make_regimes.py).
#include "figures/spec.hpp"
#include "figures/spec_build.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/motion.hpp"
#include "reference.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <numbers>
#include <string>

namespace {

using namespace pendulum;
using std::numbers::pi;

/// The motion a reference row starts: "state" theta omega, "energy" E, "amplitude" theta0.
motion start_of(const std::string& kind, double a, double b) {
    if (kind == "energy") return motion::from_energy(a);
    if (kind == "amplitude") return motion::from_amplitude(a);
    return motion::from_state({a, b});
}

std::string describe(const std::vector<std::string>& row) { return row[0] + " " + row[1] + " " + row[2]; }

TEST(Motion, ThetaAndVelocityMatchTheReferenceInAllRegimes) {
    const auto rows = test_support::read_reference_text("regimes.csv");
    double worst_theta = 0;
    double worst_velocity = 0;
    double worst_theta_absolute = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const auto& row = rows[i];
        const motion m = start_of(row[0], std::stod(row[1]), std::stod(row[2]));
        EXPECT_EQ(row_of(m.kind()).name, row[3]) << describe(row);
        const double t = std::stod(row[4]);
        const double want_theta = std::stod(row[5]);
        const double want_velocity = std::stod(row[6]);
        const double got_theta = m.theta(t);
        const double got_velocity = m.velocity(t);
        // The time w0 t + offset (the offset below a period) is rounded once: theta moves by
        // that times the speed; otherwise a few ulps of the angle (unwrapped, so of its size)
        // and of the largest speed 2/k.
        const double speed_scale = m.kind() == regime::rotation ? 2.0 / m.modulus() : 2.0;
        const double offset_bound = m.has_period() ? m.period() : 40.0;
        const double time_error = DBL_EPSILON * (std::fabs(t) + offset_bound);
        const double theta_tolerance =
            4.0 * DBL_EPSILON * std::max(std::fabs(want_theta), pi) + time_error * std::fabs(want_velocity);
        const double velocity_tolerance = 4.0 * DBL_EPSILON * speed_scale + time_error * 1.0;
        const double theta_error = std::fabs(got_theta - want_theta);
        const double velocity_error = std::fabs(got_velocity - want_velocity);
        worst_theta = std::max(worst_theta, theta_error / theta_tolerance);
        worst_theta_absolute = std::max(worst_theta_absolute, theta_error);
        worst_velocity = std::max(worst_velocity, velocity_error / velocity_tolerance);
        EXPECT_LE(theta_error, theta_tolerance) << describe(row) << " at w0 t = " << row[4] << ": theta "
                                                << format_double(got_theta) << ", want " << row[5];
        EXPECT_LE(velocity_error, velocity_tolerance) << describe(row) << " at w0 t = " << row[4]
                                                      << ": theta' " << format_double(got_velocity) << ", want "
                                                      << row[6];
    }
    std::cout << "worst error over tolerance: theta " << worst_theta << ", velocity " << worst_velocity
              << "; worst theta error " << worst_theta_absolute << " rad\n";
}

TEST(Motion, PeriodsAndEnergiesMatchTheReference) {
    const auto rows = test_support::read_reference_text("regime_periods.csv");
    double worst_period = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const auto& row = rows[i];
        const motion m = start_of(row[0], std::stod(row[1]), std::stod(row[2]));
        EXPECT_EQ(row_of(m.kind()).name, row[3]) << describe(row);
        // The energy gap to its last bit (an amplitude's through its rounded k'): it decides
        // the regime and the moduli.
        const double gap = -std::stod(row[4]);
        const double ulps = row[0] == "amplitude" ? 2.0 : 0.5;
        EXPECT_LE(std::fabs(m.energy_gap() - gap), ulps * DBL_EPSILON * std::fabs(gap)) << describe(row);
        if (row[5] == "none") {
            EXPECT_FALSE(m.has_period()) << describe(row);
            EXPECT_THROW(m.period(), domain_error);
            continue;
        }
        const double want = std::stod(row[5]);
        worst_period = std::max(worst_period, std::fabs(m.period() - want) / want);
        EXPECT_LE(std::fabs(m.period() - want), 4 * DBL_EPSILON * want)
            << describe(row) << ": period " << format_double(m.period()) << ", want " << row[5];
    }
    std::cout << "worst relative period error " << worst_period << "\n";
}

TEST(Motion, LibrationIsTheExactSolutionOfItsAmplitude) {
    const motion m = motion::from_amplitude(2.0);
    const exact_solution e(2.0);
    for (double t : {0.0, 0.7, 3.0, -11.0}) EXPECT_EQ(m.theta(t), e.theta(t));
    EXPECT_DOUBLE_EQ(motion::from_state({0.0, 1.9}).amplitude().radians(), 2 * std::asin(0.95));
    EXPECT_DOUBLE_EQ(motion::from_energy(1.5).period_ratio(), exact_solution(2 * std::asin(std::sqrt(0.75))).period_ratio());
}

TEST(Motion, LibrationClockGivesTheSameMotion) {
    for (const pendulum_state start : {pendulum_state{1.0, -1.5}, pendulum_state{-20.0, 1.0}, pendulum_state{7.0, 0.5}}) {
        const motion m = motion::from_state(start);
        for (double t : {0.0, 0.4, -3.0, 9.0}) {
            EXPECT_NEAR(m.libration_center() + m.libration().theta(m.libration_clock(t)), m.theta(t), 1e-14)
                << start.theta << " " << start.omega << " " << t;
        }
    }
    EXPECT_THROW((void)motion::from_energy(2.0).libration_clock(0.0), domain_error);
}

TEST(Motion, RotationRisesAndItsRemainderIsPeriodic) {
    const motion m = motion::from_state({0.0, 2.2});
    const double T = m.period();
    double last = m.theta(0);
    for (int i = 1; i <= 200; ++i) {
        const double theta = m.theta(0.05 * i);
        EXPECT_GT(theta, last);
        last = theta;
    }
    for (double t : {0.3, 1.1, 2.9}) EXPECT_NEAR(m.theta(t + 3 * T) - m.theta(t), 6 * pi, 1e-13);
    // The notes' example: w0 = 2.2 from the bottom, t = 0.3 T0.
    EXPECT_NEAR(m.theta(0.3 * 2 * pi), 2.932804920263, 1e-12);
}

TEST(Motion, BadStartsNameWhatWouldWork) {
    EXPECT_THROW(motion::from_energy(-1.0), domain_error);
    EXPECT_THROW(motion::from_energy(0.0), domain_error);
    EXPECT_THROW(motion::from_state({0.0, 0.0}), domain_error);
    EXPECT_THROW(motion::from_state({NAN, 1.0}), domain_error);
    try {
        (void)motion::from_energy(2.5).amplitude();
        FAIL();
    } catch (const domain_error& e) {
        EXPECT_NE(std::string(e.what()).find("only a libration"), std::string::npos) << e.what();
    }
    try {
        (void)motion::from_energy(-0.5);
        FAIL();
    } catch (const domain_error& e) {
        EXPECT_NE(std::string(e.what()).find("must be > 0"), std::string::npos) << e.what();
    }
}

TEST(Motion, PeriodAgainstEnergyPlotMatchesTheReference) {
    // plot = "period" with x = "energy": T/T0 from E = 0 to 4, the libration's period below
    // the separatrix and one revolution above it, each its own curve, and a line at E = 2.
    const auto spec = figures::parse_spec("[[panel]]\nplot = \"period\"\nx = \"energy\"\nrange = [0, 4]\n", "e.toml");
    const auto f = figures::build_figure(spec);
    ASSERT_EQ(f.panels.size(), 1u);
    const auto& data = f.panels[0].data;
    ASSERT_EQ(data.size(), 3u);
    const auto& libration = data[0];
    const auto& rotation = data[1];
    ASSERT_TRUE(libration.curve && rotation.curve);
    EXPECT_LT(libration.curve->u1, 2.0);
    EXPECT_GT(rotation.curve->u0, 2.0);
    EXPECT_EQ(data[2].x, (std::vector<double>{2, 2}));
    EXPECT_NE(data[2].label.markup.find("separatrix"), std::string::npos);
    for (const auto& s : {libration, rotation}) {
        for (double x : s.x) EXPECT_NE(x, 2.0);
    }
    const auto rows = test_support::read_reference_text("energy_periods.csv");
    double worst = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const double e = std::stod(rows[i][0]);
        const double want = std::stod(rows[i][1]);
        const auto& s = e < 2 ? libration : rotation;
        const auto [x, y] = s.curve->at(e);
        EXPECT_EQ(x, e);
        worst = std::max(worst, std::fabs(y - want) / want);
        EXPECT_LE(std::fabs(y - want), 8 * DBL_EPSILON * want) << "E = " << rows[i][0] << ": T/T0 " << y << ", want " << rows[i][1];
    }
    std::cout << "period against energy: worst relative error " << worst << "\n";
}

}  // namespace
