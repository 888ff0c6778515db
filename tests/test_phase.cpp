// SPDX-License-Identifier: GPL-3.0-or-later
// Angular velocities for the phase plane, against 60-digit references (tests/data/make_phase.py).
#include "pendulum/amplitude.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/phase.hpp"
#include "reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using namespace pendulum;
using std::numbers::pi;

TEST(Phase, ExactVelocityMatchesTheReference) {
    for (const auto& row : test_support::read_reference("phase.csv")) {
        const double theta0 = row[0];
        const double s = row[1];
        const double want = row[2];
        const double got = velocity_at_fraction(exact_solution(theta0), s);
        // Relative to the largest speed 2k, as theta itself is measured against theta0.
        const double scale = 2.0 * std::sin(theta0 / 2);
        EXPECT_LE(std::fabs(got - want), 5e-16 * scale)
            << "theta0 = " << format_double(theta0) << ", t/T = " << format_double(s) << ": got "
            << format_double(got) << ", want " << format_double(want);
    }
}

TEST(Phase, EnergyIsConservedAlongTheOrbit) {
    for (double theta0 : {0.3, pi / 2, 3.0}) {
        const exact_solution e(theta0);
        for (int i = 0; i <= 40; ++i) {
            const double s = i / 40.0;
            const double v = velocity_at_fraction(e, s);
            const double theta = e.theta_at_fraction(s);
            EXPECT_NEAR(v * v, 2 * (std::cos(theta) - std::cos(theta0)), 1e-14) << theta0 << " " << s;
        }
    }
}

TEST(Phase, FourierVelocityIsTheDerivative) {
    const auto f = first_order(2.0);
    const double h = 1e-6;
    for (double t : {0.0, 0.4, 1.3, 5.0}) {
        const double numeric = (f.theta(t + h) - f.theta(t - h)) / (2 * h);
        EXPECT_NEAR(velocity(f, t), numeric, 1e-8);
    }
    EXPECT_EQ(velocity(harmonic(1.0), 0.0), 0.0);
    EXPECT_DOUBLE_EQ(velocity(harmonic(1.0), pi / 2), -1.0);
}

TEST(Phase, Separatrix) {
    EXPECT_DOUBLE_EQ(separatrix_velocity(0), 2.0);
    EXPECT_NEAR(separatrix_velocity(pi), 0.0, 3e-16);
    EXPECT_THROW(separatrix_velocity(4.0), domain_error);
    // An orbit just inside the separatrix stays under it.
    const exact_solution e(pi - 1e-6);
    for (double s : {0.1, 0.2, 0.25}) {
        EXPECT_LE(std::fabs(velocity_at_fraction(e, s)), separatrix_velocity(e.theta_at_fraction(s)) + 1e-15);
    }
}

}  // namespace
