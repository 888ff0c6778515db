// SPDX-License-Identifier: GPL-3.0-or-later
// The core's numbers at long times, near the zero crossings, in the iteration and in the
// claims, each against an mpmath reference committed beside its script in tests/data.
#include "pendulum/amplitude.hpp"
#include "pendulum/angle.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/claims.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/mp_iteration.hpp"
#include "pendulum/time_reduction.hpp"
#include "process.hpp"
#include "reference.hpp"
#include "reference_rows.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
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

/// theta of a method at time s (in exact periods) through the time reducer with the
/// solution's own exact frequency ratio.
double theta_at(const fourier_solution& solution, const amplitude& a, double s) {
    const time_reducer reduce(a, time_scale{}, std::fabs(s), solution);
    return solution.theta_at_phase(reduce.phase(s));
}

TEST(LongTimes, EveryMethodsPhaseIsExactUpToTheLargestDouble) {
    // long_time_phase.csv (make_long_time_phase.py): every method at 0.37 to 1.8e308 periods
    // for theta0 = 1, 2.5, pi - 0.01 and pi - 1e-12, the phase from the exact w/w0. With
    // w/w0 rounded to a double the lowest order at theta0 = 2.5 gave 2.4741424088724857 at
    // 1e15 T [2.3075842464475386] and 1.7400543364789234 at the largest double
    // [0.72327724458982943]; the first order at pi - 1e-12 was 175 ulps off within a period.
    const auto rows = test_support::read_reference_text("long_time_phase.csv");
    ASSERT_GE(rows.size(), 150u);
    std::map<std::string, double> worst;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const auto& f = rows[i];
        const amplitude a = amplitude_of(f.at(0));
        const fourier_solution solution = method_solution(parse_method(f.at(1)), a);
        const double s = number(f.at(2));
        const double got = theta_at(solution, a, s);
        const double u = std::fabs(got - number(f.at(3))) / ulp(a.radians());
        EXPECT_LE(u, 4) << f.at(0) << " " << f.at(1) << " at " << f.at(2) << ": got " << format_double(got)
                        << ", want " << f.at(3);
        worst[f.at(1)] = std::max(worst[f.at(1)], u);
    }
    for (const auto& [method, u] : worst) std::cout << method << ": worst " << u << " ulps of theta0\n";
}

TEST(LongTimes, TheReproductionsBeforeTheFix) {
    // The audit's cases one by one: lowest order at theta0 = 2.5.
    const amplitude a(2.5);
    const auto lowest = lowest_order(a);
    EXPECT_NEAR(theta_at(lowest, a, 1e15), 2.3075842464475386, 4 * ulp(2.5));
    EXPECT_NEAR(theta_at(lowest, a, 1.7976931348623157e308), 0.72327724458982943, 4 * ulp(2.5));
    // The same solution without its exact source (its double w/w0 taken as exact) is the old
    // behaviour, the whole amplitude off at 1e15 periods.
    fourier_solution doubles = lowest;
    doubles.exact.reset();
    const time_reducer old(a, time_scale{}, 1e15, doubles.frequency_ratio);
    EXPECT_GT(std::fabs(doubles.theta_at_phase(old.phase(1e15)) - 2.3075842464475386), 0.1);
}

TEST(LongTimes, TheLargestDoubleAcceptedInfinityRefusedWithItsMessage) {
    const amplitude a(1.0);
    const auto solution = first_order(a);
    const double largest = std::numeric_limits<double>::max();
    const time_reducer reduce(a, time_scale{}, largest, solution);
    EXPECT_TRUE(std::isfinite(solution.theta_at_phase(reduce.phase(largest))));
    EXPECT_TRUE(std::isfinite(solution.theta_at_phase(reduce.phase(-largest))));
    try {
        (void)reduce.phase(INFINITY);
        ADD_FAILURE() << "an infinite time was accepted";
    } catch (const domain_error& e) {
        EXPECT_STREQ(e.what(), "time must be finite, got inf");
    }
    try {
        (void)time_reducer(a, time_scale{}, INFINITY, solution);
        ADD_FAILURE() << "an infinite largest time was accepted";
    } catch (const domain_error& e) {
        EXPECT_STREQ(e.what(), "the largest time must be finite, got inf");
    }
}

TEST(LongTimes, EveryMethodCarriesItsExactSource) {
    const amplitude a(2.0);
    for (const char* m : {"harmonic", "lowest", "first", "second", "polynomial", "order:0", "order:4"}) {
        const auto solution = method_solution(parse_method(m), a);
        ASSERT_TRUE(solution.exact) << m;
        // The source's w/w0 rounded is the double's to an ulp.
        const double exact = solution.exact->at(128).ratio.to_double();
        EXPECT_LE(std::fabs(exact - solution.frequency_ratio), ulp(exact)) << m;
    }
    // Close to pi (MPFR levels) too.
    const auto near = iterated_sequence(amplitude::from_pi(1e-3), 3);
    for (const auto& level : near) EXPECT_TRUE(level.exact);
}

TEST(ZeroCrossings, ThetaHeldTo1e14OfTheAmplitudeNextToEveryCrossing) {
    // crossing_times.csv (make_crossing_times.py): w0 t = K - u and 3K + u for u = 1e-12 to
    // 1e-2, where the Jacobi functions switch from their Maclaurin series (|u| < 1e-8) to the
    // Landen recursion. Moving the switch up a decade (1e-7) fails here.
    const auto rows = test_support::read_reference_text("crossing_times.csv");
    ASSERT_GE(rows.size(), 400u);
    double worst = 0;
    double worst_relative = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const auto& f = rows[i];
        const amplitude a = amplitude_of(f.at(0));
        const exact_solution e(a);
        const bool in_periods = f.at(1) == "s";
        const double got = in_periods ? e.theta_at_fraction(number(f.at(2))) : e.theta(number(f.at(2)));
        const double err = std::fabs(got - number(f.at(3))) / a.radians();
        EXPECT_LE(err, 1e-14) << f.at(0) << " at " << f.at(1) << " = " << f.at(2) << ": got " << format_double(got)
                              << ", want " << f.at(3);
        worst = std::max(worst, err);
        // In exact periods (1 - 4 s exact) theta is right to a few ulps of itself next to a
        // crossing: the Maclaurin branch's neglected u^2/6 would show from u = 1e-7 on. (At a
        // double w0 t the rounding of K itself moves a small theta by far more.)
        const double want = number(f.at(3));
        if (in_periods && std::fabs(want) < 1e-6 * a.radians()) {
            const double rel = std::fabs(got - want) / ulp(want);
            EXPECT_LE(rel, 4) << f.at(0) << " at s = " << f.at(2) << ": got " << format_double(got) << ", want "
                              << f.at(3);
            worst_relative = std::max(worst_relative, rel);
        }
    }
    std::cout << "worst error next to a crossing: " << worst << " theta0, " << worst_relative
              << " ulps of theta within 1e-6 theta0 of it\n";
}

/// The rows of iteration_switch.csv for one amplitude.
void check_levels(const std::string& which, const std::vector<fourier_solution>& levels, double* worst_period,
                  double* worst_coefficient) {
    const auto rows = test_support::read_reference_text("iteration_switch.csv");
    int seen = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const auto& f = rows[i];
        if (f.at(0) != which) continue;
        const auto n = static_cast<std::size_t>(std::stoi(f.at(1)));
        ASSERT_LT(n, levels.size());
        ++seen;
        if (f.at(2).empty()) {
            EXPECT_FALSE(levels[n].exists()) << which << " order " << n;
            continue;
        }
        const double want = number(f.at(2));
        const double u = std::fabs(levels[n].period_ratio() - want) / ulp(want);
        EXPECT_LE(u, 4) << which << " order " << n << ": T/T0 " << format_double(levels[n].period_ratio())
                        << ", want " << f.at(2);
        *worst_period = std::max(*worst_period, u);
        const auto c = split_at(f.at(3), ';');
        ASSERT_EQ(c.size(), levels[n].coefficients.size());
        for (std::size_t k = 0; k < c.size(); ++k) {
            const double uc = std::fabs(levels[n].coefficients[k] - number(c[k])) / ulp(levels[n].coefficients[0]);
            EXPECT_LE(uc, 4) << which << " order " << n << " c" << 2 * k + 1;
            *worst_coefficient = std::max(*worst_coefficient, uc);
        }
    }
    EXPECT_GE(seen, 38) << which;
}

TEST(Iteration, WithinFourUlpsOnBothSidesOfTheSwitchToMpfr) {
    // iteration_switch.csv (make_iteration_switch.py). At d = 0.0201 from pi the levels are
    // computed in extended precision (in doubles eval --order 37 gave T/T0 =
    // 3.811200505147771 [3.81120050514781661], 100 ulps); below d = 0.02 in MPFR.
    ASSERT_EQ(detail::iteration_mp_below, 0.02);
    for (const char* which : {"pi-0.0201", "pi-0.0199", "0.99pi"}) {
        double worst_period = 0;
        double worst_coefficient = 0;
        const int order = std::string(which) == "0.99pi" ? 40 : 37;
        check_levels(which, iterated_sequence(amplitude_of(which), order), &worst_period, &worst_coefficient);
        std::cout << which << ": worst T_N/T0 " << worst_period << " ulps, worst c_k " << worst_coefficient
                  << " ulps of c1\n";
    }
    const auto levels = iterated_sequence(amplitude::from_pi(0.0201), 37);
    EXPECT_NEAR(levels[37].period_ratio(), 3.81120050514781661, 4 * ulp(3.81120050514781661));
}

TEST(Iteration, ExtendedRatioRightToTheBitsItClaims) {
    // A level's known_ratio (extended precision) is used for short phases in place of its MPFR
    // run: it must be right to 2^-known_bits, down to d = 0.0201 from pi (measured 2^-57.1).
    for (const double d : {2.5, 1.0, 0.3, 0.1, 0.0201}) {
        const amplitude a = amplitude::from_pi(d);
        const auto levels = iterated_sequence(a, 40);
        const auto x = mp::exact_amplitude(a, 160);
        const auto lambdas = detail::mp_lambdas(x, 40, 160);
        for (std::size_t n = 0; n < levels.size(); ++n) {
            ASSERT_TRUE(lambdas[n] && lambdas[n]->sign() > 0);
            const auto& source = *levels[n].exact;
            ASSERT_GE(source.known_bits, 50);
            const mp::real exact = mp::sqrt(*lambdas[n]);
            mp::real known(160);
            mpfr_set_ld(known.get(), source.known_ratio, MPFR_RNDN);
            const double relative = std::fabs(((known - exact) / exact).to_double());
            EXPECT_LE(relative, std::ldexp(1.0, -source.known_bits)) << "pi - " << d << ", order " << n;
        }
    }
}

TEST(Iteration, ThePathEachSideOfTheSwitchIsTheOneNamed) {
    // Just above the switch the extended iteration is the one used; just below it is not.
    const amplitude above = amplitude::from_pi(0.0201);
    const auto a = iterated_sequence(above, 5);
    const auto b = iterated_sequence_extended(above, 5);
    for (int n = 0; n <= 5; ++n) EXPECT_EQ(a[static_cast<std::size_t>(n)].frequency_ratio, b[static_cast<std::size_t>(n)].frequency_ratio);
    EXPECT_THROW(iterated_sequence_extended(above, max_order + 1), domain_error);
}

TEST(Iteration, Order200AcceptedAnd201RefusedWithItsMessage) {
    const auto levels = iterated_sequence(amplitude(1.0), max_order);
    EXPECT_EQ(levels.size(), static_cast<std::size_t>(max_order + 1));
    try {
        (void)iterated_sequence(amplitude(1.0), max_order + 1);
        ADD_FAILURE() << "order 201 was accepted";
    } catch (const domain_error& e) {
        EXPECT_STREQ(e.what(), "order must be between 0 and 200, got 201");
    }
    try {
        (void)iterated_sequence_extended(amplitude(1.0), -1);
        ADD_FAILURE() << "order -1 was accepted";
    } catch (const domain_error& e) {
        EXPECT_STREQ(e.what(), "order must be between 0 and 200, got -1");
    }
}

TEST(Coefficients, FirstAndPolynomialWithinFourUlps) {
    // c3' of the first order (was 9 ulps) and c5 of the polynomial (was 5.6) against their
    // MPFR values at the exact amplitude, on a sweep to pi - 1e-12.
    double worst_c3 = 0;
    double worst_c5 = 0;
    std::vector<amplitude> sweep;
    for (double t = 1e-6; t < 3.1; t *= 1.07) sweep.emplace_back(t);
    for (double d = 1e-12; d < 0.5; d *= 3.7) sweep.push_back(amplitude::from_pi(d));
    for (const auto& a : sweep) {
        const auto first = first_order(a);
        const auto poly = polynomial(a);
        const double c3 = first.exact->at(200).coefficients[1].to_double();
        const double c5 = poly.exact->at(200).coefficients[2].to_double();
        worst_c3 = std::max(worst_c3, std::fabs(first.coefficients[1] - c3) / ulp(c3));
        worst_c5 = std::max(worst_c5, std::fabs(poly.coefficients[2] - c5) / ulp(c5));
    }
    EXPECT_LE(worst_c3, 4);
    EXPECT_LE(worst_c5, 4);
    std::cout << "c3_first worst " << worst_c3 << " ulps, c5_poly worst " << worst_c5 << " ulps\n";
}

double claimed(const std::vector<claim_measure>& rows, const std::string& quantity) {
    for (const auto& r : rows) {
        if (r.quantity == quantity) return r.value;
    }
    ADD_FAILURE() << "no claim measures " << quantity;
    return std::nan("");
}

TEST(Claims, LargestDeviationsCorrectlyRounded) {
    // claims_deviations.csv (make_claims_deviations.py): at pi/3 the lowest order's was
    // 0.011454773129706997 [0.011454773129706292], 406 ulps.
    const auto rows = paper_claims();
    const auto ref = test_support::read_reference_text("claims_deviations.csv");
    ASSERT_EQ(ref.size(), 8u);
    for (std::size_t i = 1; i < ref.size(); ++i) {
        const std::string quantity = "max |theta_" + ref[i].at(0) + " - theta| over a period at " + ref[i].at(1);
        const double want = number(ref[i].at(4));
        const double got = claimed(rows, quantity);
        EXPECT_LE(std::fabs(got - want), 0.5 * ulp(want)) << quantity << ": " << format_double(got) << ", want "
                                                           << ref[i].at(4);
    }
}

TEST(Claims, CommandLinePrintsTheCorrectlyRoundedValue) {
    const auto r = test_support::run_cli("claims");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("0.011454773129706292"), std::string::npos) << r.out;
    // At 95pi/100 itself (at its double the second order's error was 0.03342282395781996).
    EXPECT_NE(r.out.find("T/T - 1 at 95pi/100,0.0334228239578193,"), std::string::npos) << r.out;
}

}  // namespace
