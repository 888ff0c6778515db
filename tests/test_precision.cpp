// SPDX-License-Identifier: GPL-3.0-or-later
// Amplitudes near pi and angle expressions, correctly rounded, against 400-digit mpmath
// references (tests/data/make_near_pi.py).
#include "pendulum/amplitude.hpp"
#include "pendulum/angle.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/motion.hpp"
#include "pendulum/mp_bessel.hpp"
#include "pendulum/period_error.hpp"
#include "pendulum/time_reduction.hpp"
#include "process.hpp"
#include "reference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <numbers>
#include <string>
#include <vector>

namespace {

using namespace pendulum;

/// A decimal as strtod reads it: subnormal values too (std::stod throws for them).
double number(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

struct near_pi_row {
    std::string expression;
    double theta0, d, k, kp, period, c1;
};

std::vector<near_pi_row> near_pi_rows() {
    std::vector<near_pi_row> rows;
    const auto text = test_support::read_reference_text("near_pi.csv");
    for (std::size_t i = 1; i < text.size(); ++i) {
        const auto& f = text[i];
        rows.push_back({f.at(0), number(f.at(1)), number(f.at(2)), number(f.at(3)), number(f.at(4)), number(f.at(5)),
                        number(f.at(6))});
    }
    return rows;
}

// The Bessel functions of the MPFR errors against MPFR's own mpfr_jn, correctly rounded: within
// 4 units of 2^-precision of the largest J (J_{n+1} included), and relative to themselves where they are not
// near a zero, over arguments from 1e-300 to 4 (zeros of J_0 and J_1 included) and n up to 40.
TEST(MpBessel, EveryOrderAgainstMpfr) {
    const double xs[] = {1e-300, 1e-30, 2.5e-6, 1e-3, 0.1, 0.5, 1.0, 2.0, 2.404825557695773, 3.0,
                         3.141592653589793, 3.6, 3.831705970207512, 4.0, -1.3};
    for (const mpfr_prec_t bits : {53, 128, 256, 1152}) {
        for (const double x0 : xs) {
            for (const int n : {0, 1, 3, 8, 40}) {
                const pendulum::mp::real x(x0, bits);
                std::vector<pendulum::mp::real> j;
                for (int m = 0; m <= n; ++m) j.push_back(pendulum::mp::bessel_j_nth(m, x));
                pendulum::mp::real largest(bits);
                std::vector<pendulum::mp::real> want;
                for (int m = 0; m <= n + 1; ++m) {  // J_{n+1} too: near a zero of J_n it sets the scale
                    want.push_back(pendulum::mp::bessel_j(m, x));
                    if (pendulum::mp::abs(want.back()) > largest) largest = pendulum::mp::abs(want.back());
                }
                for (int m = 0; m <= n; ++m) {
                    const auto& w = want[static_cast<std::size_t>(m)];
                    const pendulum::mp::real diff = pendulum::mp::abs(j[static_cast<std::size_t>(m)] - w);
                    const long scale = pendulum::mp::exponent(w) > pendulum::mp::exponent(largest) - 8
                                           ? pendulum::mp::exponent(largest)
                                           : pendulum::mp::exponent(w);
                    const bool near_zero = pendulum::mp::exponent(w) < pendulum::mp::exponent(largest) - 8 &&
                                           m <= 1 && std::fabs(x0) > 2;
                    const long limit = (near_zero ? pendulum::mp::exponent(largest) : scale) - static_cast<long>(bits) + 2;
                    EXPECT_TRUE(diff.is_zero() || pendulum::mp::exponent(diff) <= limit)
                        << "J_" << m << "(" << x0 << ") with " << bits << " bits (n = " << n << "): off by 2^"
                        << pendulum::mp::exponent(diff) << ", limit 2^" << limit;
                }
            }
        }
    }
}

TEST(NearPi, ExpressionsKeepTheirDistanceFromPiToTheLastBit) {
    const auto rows = near_pi_rows();
    ASSERT_GE(rows.size(), 15u);
    for (const auto& r : rows) {
        const amplitude a = parse_amplitude(r.expression);
        EXPECT_EQ(a.radians(), r.theta0) << r.expression;
        if (a.near_pi()) {
            EXPECT_EQ(a.from_pi(), r.d) << r.expression;
        }
        EXPECT_EQ(a.k(), r.k) << r.expression;
        EXPECT_EQ(a.kp(), r.kp) << r.expression;
    }
}

TEST(NearPi, PeriodAndCoefficientFromTheDistance) {
    for (const auto& r : near_pi_rows()) {
        const exact_solution e(parse_amplitude(r.expression));
        EXPECT_LE(std::fabs(e.period_ratio() / r.period - 1), 4.5e-16) << r.expression;
        EXPECT_LE(std::fabs(e.coefficient(0) / r.c1 - 1), 2e-15) << r.expression;
    }
}

TEST(NearPi, DoublesGiveTheirDistanceExactly) {
    // pi - 0.5 and pi - 2^-40 are doubles' distances from the double theta0 plus pi's own tail.
    const double theta0 = std::nextafter(3.141592653589793, 0.0);  // the double below the one nearest pi
    const amplitude a(theta0);
    EXPECT_EQ(a.from_pi(), 5.66553889764798e-16);  // pi - theta0, 400 digits rounded
    const amplitude b = amplitude::from_pi(1e-300);
    EXPECT_EQ(b.kp(), 5e-301);
    EXPECT_EQ(b.k(), 1.0);
    EXPECT_THROW(amplitude::from_pi(1e-310), domain_error);
    EXPECT_THROW(amplitude::from_pi(0.0), domain_error);
    EXPECT_THROW(amplitude(3.141592653589793), domain_error);
}

TEST(NearPi, TooCloseOrBeyondIsAnErrorNamingTheValue) {
    for (const char* text : {"pi", "pi - 1e-400", "pi - 1e-310", "pi + 1e-300", "0", "-1e-300", "4"}) {
        try {
            parse_amplitude(text);
            ADD_FAILURE() << text << " was accepted";
        } catch (const domain_error& e) {
            EXPECT_NE(std::string(e.what()).find("theta0"), std::string::npos) << e.what();
        }
    }
}

TEST(AngleExpressions, AreCorrectlyRounded) {
    EXPECT_EQ(parse_expression("0.1 + 0.2"), 0.3);
    EXPECT_EQ(parse_expression("1e300 - (1e300 - 1)"), 1.0);
    EXPECT_EQ(parse_expression("1/3"), 1.0 / 3.0);
    EXPECT_EQ(parse_angle("pi - 1e-300"), 3.141592653589793);
    EXPECT_EQ(parse_angle("0.1pi"), 0.3141592653589793);  // 400-digit pi/10, rounded
    EXPECT_EQ(parse_angle("1deg"), 0.017453292519943295);
    EXPECT_EQ(parse_angle("179.9999999deg"), 3.141592651844464);
    // Cancellation beyond the working precision is no value at all.
    EXPECT_THROW(parse_expression("1e300 - (1e300 - 1e-300)"), domain_error);
}

}  // namespace

namespace {

TEST(PeriodErrors, EveryClosedFormRightTo1e12DownTo1e300) {
    // theta0, method, error
    const auto rows = test_support::read_reference_text("period_errors.csv");
    ASSERT_GE(rows.size(), 280u);
    double worst = 0;
    std::string where;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const std::string& theta0 = rows[i].at(0);
        const std::string& method = rows[i].at(1);
        const std::string& error = rows[i].at(2);
        const auto e = method_period_error(parse_method(method), parse_amplitude(theta0));
        if (error == "below") {
            EXPECT_EQ(e.what, period_error::kind::below_limit) << method << " at " << theta0 << ": " << e.value;
            continue;
        }
        ASSERT_EQ(e.what, period_error::kind::value) << method << " at " << theta0;
        const double rel = std::fabs(e.value / number(error) - 1);
        EXPECT_LE(rel, 1e-12) << method << " at " << theta0 << ": got " << format_double(e.value) << ", want " << error;
        if (rel > worst) {
            worst = rel;
            where = method + " at " + theta0;
        }
    }
    std::cout << "worst relative error of T_m/T - 1: " << worst << " (" << where << ")\n";
}

TEST(PeriodErrors, IterationLevelsAgainstExactArithmetic) {
    // iteration.csv: theta0 expression, value, order, lambda, T_N/T0, T_N/T - 1 (empty: no period).
    const auto rows = test_support::read_reference_text("iteration.csv");
    struct level {
        int order;
        std::string error;
    };
    std::vector<std::pair<std::string, std::vector<level>>> by_amplitude;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        auto f = rows[i];
        f.resize(6);
        if (by_amplitude.empty() || by_amplitude.back().first != f[0]) by_amplitude.push_back({f[0], {}});
        const int order = std::stoi(f[2]);
        if (order <= 24) by_amplitude.back().second.push_back({order, f[5]});
    }
    ASSERT_GE(by_amplitude.size(), 6u);
    double worst = 0;
    for (const auto& [text, levels] : by_amplitude) {
        const auto errors = iterated_period_errors(parse_amplitude(text), levels.back().order);
        for (const auto& l : levels) {
            const auto& e = errors[static_cast<std::size_t>(l.order)];
            if (l.error.empty()) {
                EXPECT_EQ(e.what, period_error::kind::no_period) << text << " order " << l.order;
                continue;
            }
            ASSERT_EQ(e.what, period_error::kind::value) << text << " order " << l.order;
            const double rel = std::fabs(e.value / number(l.error) - 1);
            EXPECT_LE(rel, 1e-12) << text << " order " << l.order << ": got " << format_double(e.value) << ", want "
                                  << l.error;
            worst = std::max(worst, rel);
        }
    }
    std::cout << "worst relative error of T_N/T - 1 over the levels: " << worst << "\n";
}

}  // namespace

namespace {

TEST(PeriodErrors, FirstBreakdownOfTheIterationIsAtPiMinus6995e4) {
    // Exact-arithmetic iteration (the physics notes): no period at levels 8 and 9 from pi - 6.995e-4 on.
    const auto at = iterated_period_errors(parse_amplitude("pi - 6.995e-4"), 12, 1e-16);
    const auto before = iterated_period_errors(parse_amplitude("pi - 6.996e-4"), 12, 1e-16);
    for (int n = 0; n <= 12; ++n) {
        const bool broken = n == 8 || n == 9;
        EXPECT_EQ(at[static_cast<std::size_t>(n)].what == period_error::kind::no_period, broken) << n;
        EXPECT_NE(before[static_cast<std::size_t>(n)].what, period_error::kind::no_period) << n;
    }
}

}  // namespace

namespace {

/// |got - want| in units in the last place of want.
double ulps(double got, double want) {
    const double ulp = std::nextafter(std::fabs(want), INFINITY) - std::fabs(want);
    return std::fabs(got - want) / ulp;
}

TEST(Scan, ThousandAmplitudesEveryMethodAgainstMpmath) {
    auto rows = test_support::read_reference_text("scan.csv");
    const std::vector<std::string> header = rows.front();
    rows.erase(rows.begin());
    ASSERT_EQ(rows.size(), 1000u);
    struct worst_case {
        double ulps = 0;
        std::string ulps_at;
        double error = 0;
        std::string error_at;
    };
    std::vector<std::pair<std::string, worst_case>> worst;
    const auto worst_of = [&](const std::string& method) -> worst_case& {
        for (auto& [name, w] : worst) {
            if (name == method) return w;
        }
        worst.push_back({method, {}});
        return worst.back().second;
    };
    for (const auto& r : rows) {
        ASSERT_EQ(r.size(), header.size());
        const amplitude a = parse_amplitude(r[0]);
        for (std::size_t i = 1; i < header.size(); ++i) {
            const std::string column = header[i];
            const std::string name = column.substr(2);
            const method_choice m = parse_method(name);
            worst_case& w = worst_of(name);
            if (column.starts_with("T:")) {
                const double u = ulps(method_period(m, a), number(r[i]));
                if (u > w.ulps) {
                    w.ulps = u;
                    w.ulps_at = r[0];
                }
                continue;
            }
            const auto e = method_period_error(m, a);
            if (r[i] == "below") {
                EXPECT_EQ(e.what, period_error::kind::below_limit) << name << " at " << r[0];
                continue;
            }
            ASSERT_EQ(e.what, period_error::kind::value) << name << " at " << r[0];
            const double rel = std::fabs(e.value / number(r[i]) - 1);
            EXPECT_LE(rel, 1e-12) << name << " at " << r[0] << ": got " << format_double(e.value) << ", want " << r[i];
            if (rel > w.error) {
                w.error = rel;
                w.error_at = r[0];
            }
        }
    }
    for (const auto& [name, w] : worst) {
        std::cout << name << ": period worst " << w.ulps << " ulps (" << w.ulps_at << "); error worst " << w.error
                  << " relative (" << w.error_at << ")\n";
        // Every closed form's period within 4 ulps of the 340-digit value, at every amplitude.
        EXPECT_LE(w.ulps, 4) << name << " at " << w.ulps_at;
    }
}

}  // namespace

namespace {

TEST(Coefficients, ExactC1C3C5InUlps) {
    // coefficients_dense.csv: theta0, c1, c3, c5 (mpmath). The nome's series below pi/2 keeps
    // c5 exact where exp((n + 1/2) ln q) lost 350 ulps near theta0 = 1e-8; extended precision
    // from the exact amplitude keeps every coefficient within 4 ulps.
    const auto rows = test_support::read_reference("coefficients_dense.csv");
    ASSERT_EQ(rows.size(), 400u);
    const double limit[] = {4, 4, 4};
    double worst[] = {0, 0, 0};
    for (const auto& r : rows) {
        const exact_solution e(r[0]);
        for (int n = 0; n < 3; ++n) {
            const double u = ulps(e.coefficient(n), r[static_cast<std::size_t>(n + 1)]);
            EXPECT_LE(u, limit[n]) << "c" << 2 * n + 1 << " at " << format_double(r[0]);
            worst[n] = std::max(worst[n], u);
        }
    }
    std::cout << "worst ulps: c1 " << worst[0] << ", c3 " << worst[1] << ", c5 " << worst[2] << "\n";
}

}  // namespace

namespace {

TEST(NearPiCli, EvalKeepsTheDistanceAndRejectsWhatNoDoubleCarries) {
    const auto r = test_support::run_cli("eval --theta0 'pi - 1e-300,pi - 1e-17' --method kidd-fogg");
    ASSERT_EQ(r.status, 0) << r.err;
    // period_exact 1/AGM(1, k') = 441.08517292857255 and 26.243623962816454 (near_pi.csv, to
    // 15 digits here); Kidd-Fogg 1/sqrt(5e-301) = 1.4142135623730950e+150 (50-digit mpmath).
    EXPECT_NE(r.out.find("3.141592653589793,441.085172928572"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(",1.41421356237309"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("3.141592653589793,26.2436239628164"), std::string::npos) << r.out;
    for (const char* bad : {"pi - 1e-400", "pi - 1e-310", "pi + 1e-300", "1e300 - (1e300 - 1e-300)"}) {
        const auto b = test_support::run_cli(std::string("eval --theta0 '") + bad + "'");
        EXPECT_EQ(b.status, 2) << bad << ": " << b.out;
        EXPECT_TRUE(b.out.empty()) << bad;
        EXPECT_NE(b.err.find("--theta0"), std::string::npos) << b.err;
    }
}

}  // namespace

namespace {

TEST(PeriodErrors, IterationNearPiRightTo1e14) {
    // iteration.csv's exact-arithmetic T_N/T0 next to pi, where the double iteration drifts
    // (at pi - 1e-12 by 16 % at N = 92): iterated_sequence() works with MPFR there.
    const auto rows = test_support::read_reference_text("iteration.csv");
    for (const char* text : {"pi-1e-6", "pi-1e-9"}) {
        const auto levels = iterated_sequence(parse_amplitude(text), 24);
        int checked = 0;
        for (std::size_t i = 1; i < rows.size(); ++i) {
            auto f = rows[i];
            f.resize(6);
            const int n = std::stoi(f[2]);
            if (f[0] != text || n > 24) continue;
            const auto& level = levels[static_cast<std::size_t>(n)];
            if (f[4].empty()) {
                EXPECT_FALSE(level.exists()) << text << " order " << n;
            } else {
                EXPECT_LE(std::fabs(level.period_ratio() / number(f[4]) - 1), 1e-14) << text << " order " << n;
            }
            ++checked;
        }
        EXPECT_GE(checked, 20) << text;
    }
}

}  // namespace

namespace {

/// The last number of the last line of a CLI table.
double last_number(const std::string& out) {
    const auto end = out.find_last_not_of('\n');
    const auto line = out.rfind('\n', end) + 1;  // npos + 1 = 0: a single line
    const auto comma = out.rfind(',', end);
    const auto from = comma == std::string::npos || comma < line ? line : comma + 1;
    return number(out.substr(from, end + 1 - from));
}

TEST(Seconds, ExtremeLengthsAndGravitiesAgainstMpmath) {
    // seconds.csv (make_seconds.py): kind, theta0, L, g, t, value. T0 = 2 pi sqrt(L/g) with a
    // subnormal L or g, or L/g beyond a double: eval's T_s and trajectory --time t/s.
    const auto rows = test_support::read_reference_text("seconds.csv");
    ASSERT_GE(rows.size(), 20u);
    double worst = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        auto f = rows[i];
        f.resize(6);
        const std::string pendulum = " --length " + f[2] + " --g " + f[3];
        const std::string args = f[0] == "period"
                                     ? "eval --theta0 " + f[1] + pendulum + " --columns T_s"
                                     : "trajectory --theta0 " + f[1] + pendulum + " --time t/s --at " + f[4];
        const auto r = test_support::run_cli(args);
        ASSERT_EQ(r.status, 0) << args << ": " << r.err;
        EXPECT_TRUE(r.err.empty()) << args << ": " << r.err;
        const double u = ulps(last_number(r.out), number(f[5]));
        EXPECT_LE(u, 6) << args << ": got " << r.out << "want " << f[5];
        worst = std::max(worst, u);
    }
    std::cout << "worst ulps of T_s and theta(t s): " << worst << "\n";
}

}  // namespace

namespace {

TEST(NearPiCli, EvalWritesTheDistanceFromPiOnRequest) {
    // Amplitudes near pi print as theta0 = 3.141592653589793; pi_minus_theta0 keeps them
    // (50-digit mpmath: pi - 1.5 = 1.6415926535897933, pi - 3 = 0.14159265358979323; the
    // periods 1/AGM(1, sin(d/2)) at 400 digits). The default table is unchanged.
    const auto r = test_support::run_cli(
        "eval --theta0 'pi - 1e-12,pi - 1e-300,1.5,3' --columns theta0,period_exact,pi_minus_theta0");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out,
              "theta0,period_exact,pi_minus_theta0\n"
              "3.141592653588793,18.914267974022174,1e-12\n"
              "3.141592653589793,441.08517292857255,1e-300\n"
              "1.5,1.1619687443866724,1.6415926535897933\n"
              "3,2.571233949432142,0.14159265358979323\n");
    const auto all = test_support::run_cli("eval --theta0 'pi - 1e-12'");
    EXPECT_EQ(all.out.find("pi_minus_theta0"), std::string::npos) << all.out;
    const auto json = test_support::run_cli("eval --theta0 'pi - 1e-300' --columns pi_minus_theta0 --format json");
    EXPECT_NE(json.out.find("\"pi_minus_theta0\": 1e-300"), std::string::npos) << json.out;
}

}  // namespace

namespace {

TEST(HugeTimes, TrajectoryReducesTheTimeExactly) {
    // huge_times.csv (make_huge_times.py): theta up to a million periods on, in t/T, t/T0 and
    // seconds, exact and harmonic motion from amplitudes. In doubles w0 t alone is off by
    // 1e-16 of itself (1e-9 rad here); reduced in MPFR every value is within 4 ulps of theta0.
    const auto rows = test_support::read_reference_text("huge_times.csv");
    ASSERT_GE(rows.size(), 30u);
    double worst = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const std::string& args = rows[i].at(0);
        const auto r = test_support::run_cli(args);
        ASSERT_EQ(r.status, 0) << args << ": " << r.err;
        // The second line's second field: theta.
        const auto line = r.out.substr(r.out.find('\n') + 1);
        const auto first = line.find(',');
        const double theta = number(line.substr(first + 1, line.find_first_of(",\n", first + 1) - first - 1));
        const auto from = args.find("--theta0 ") + 9;
        const double theta0 = parse_amplitude(args.substr(from, args.find(' ', from) - from)).radians();
        const double u = std::fabs(theta - number(rows[i].at(1))) / (std::nextafter(theta0, 4.0) - theta0);
        EXPECT_LE(u, 6) << args << ": got " << format_double(theta) << ", want " << rows[i].at(1);
        worst = std::max(worst, u);
    }
    std::cout << "worst error in ulps of theta0: " << worst << "\n";
}

}  // namespace

namespace {

TEST(PeriodErrors, IterationAtPiMinus1e12AgainstAnIndependentRun) {
    // iteration_near_pi.csv (make_iteration_near_pi.py: trapezoidal rule with end points,
    // fixed point at 256 and 512 bits agreeing to 1e-40, at pi - d with d the double nearest
    // 1e-12, as the amplitude is held): T_92/T0 = 26.5922092087911138 and T_90/T0 =
    // 15.0627169505460400, not the 30.50 and 15.39 once claimed for exact arithmetic (doubles
    // give 22.26 and 13.30). Every level from 0 to 100, with or without a period.
    const auto rows = test_support::read_reference_text("iteration_near_pi.csv");
    ASSERT_EQ(rows.size(), 102u);
    const auto levels = iterated_sequence(parse_amplitude("pi-1e-12"), 100);
    double worst = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        auto f = rows[i];
        f.resize(4);
        const auto n = static_cast<std::size_t>(std::stoi(f[1]));
        if (f[3].empty()) {
            EXPECT_FALSE(levels[n].exists()) << "order " << n;
            continue;
        }
        ASSERT_TRUE(levels[n].exists()) << "order " << n;
        const double rel = std::fabs(levels[n].period_ratio() / number(f[3]) - 1);
        EXPECT_LE(rel, 1e-15) << "order " << n << ": got " << format_double(levels[n].period_ratio()) << ", want " << f[3];
        worst = std::max(worst, rel);
    }
    std::cout << "worst relative error of T_N/T0 at pi - 1e-12: " << worst << "\n";
}

}  // namespace

namespace {

/// The fields of `text` split at `separator`.
std::vector<std::string> split_at(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::size_t from = 0;
    for (;;) {
        const auto at = text.find(separator, from);
        parts.push_back(text.substr(from, at - from));
        if (at == std::string::npos) return parts;
        from = at + 1;
    }
}

/// The time unit of a trajectory's --time text (seconds with L = 0.7, g = 9.80665).
time_scale scale_of(const std::string& unit) {
    if (unit == "t/T0") return {time_scale::unit::small_periods};
    if (unit == "t/s") return {time_scale::unit::seconds, 0.7, 9.80665};
    return {};
}

TEST(HugeTimes, ApproximantsReduceTheirPhaseExactly) {
    // approximant_times.csv (make_approximant_times.py): each approximant's own formula, with
    // the double coefficients and w/w0 written there, at 1e3 to 1.8e308 periods in t/T, t/T0
    // and seconds. The phase (w/w0) w0 t reduced modulo 2 pi in MPFR keeps theta within a few
    // ulps of theta0 at any time; formed in doubles it is off by 1e-16 of itself.
    const auto rows = test_support::read_reference_text("approximant_times.csv");
    ASSERT_GE(rows.size(), 300u);
    std::map<std::string, double> worst;
    double worst_in_doubles_1e6 = 0;
    int cli_checked = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const auto& f = rows[i];
        const amplitude a = parse_amplitude(f.at(0));
        const std::string& method = f.at(1);
        const double s = number(f.at(3));
        fourier_solution solution{number(f.at(4)), {}};
        for (const auto& c : split_at(f.at(5), ';')) solution.coefficients.push_back(number(c));
        const double want = number(f.at(6));
        const double ulp = std::nextafter(a.radians(), 4.0) - a.radians();
        const time_reducer reduce(a, scale_of(f.at(2)), std::fabs(s), solution.frequency_ratio);
        const double got = solution.theta_at_phase(reduce.phase(s));
        const double u = std::fabs(got - want) / ulp;
        EXPECT_LE(u, 4) << f.at(0) << " " << method << " " << f.at(2) << " " << f.at(3) << ": got "
                        << format_double(got) << ", want " << f.at(6);
        worst[method] = std::max(worst[method], u);
        if (f.at(2) == "t/T0" && std::fabs(s) < 2e6) {
            // The same formula at w0 t in doubles, for comparison.
            const double naive = solution.theta(2 * std::numbers::pi * s);
            worst_in_doubles_1e6 = std::max(worst_in_doubles_1e6, std::fabs(naive - want));
        }
        // The command line forms the phase with the solution's own w/w0 from the exact
        // amplitude (its exact source, checked against mpmath with long_time_phase.csv in
        // test_core_numerics and test_numbers_long), not with the double w/w0 taken as exact
        // as this file's rows do: it is the library's phase with that source.
        const fourier_solution own = method_solution(parse_method(method), a);
        const bool huge = f.at(3) == "1e300" || f.at(3) == "1.7976931348623157e308" || f.at(3) == "999999.3";
        if (huge && own.frequency_ratio == solution.frequency_ratio && own.coefficients == solution.coefficients) {
            const time_reducer exact_phase(a, scale_of(f.at(2)), std::fabs(s), own);
            const double with_source = own.theta_at_phase(exact_phase.phase(s));
            const std::string args = "trajectory --theta0 " + f.at(0) + " --method " + method + " --time " + f.at(2) +
                                     " --at " + f.at(3) + (f.at(2) == "t/s" ? " --length 0.7 --g 9.80665" : "");
            const auto r = test_support::run_cli(args);
            ASSERT_EQ(r.status, 0) << args << ": " << r.err;
            const auto line = r.out.substr(r.out.find('\n') + 1);
            const double cli = number(line.substr(line.find(',') + 1));
            EXPECT_LE(std::fabs(cli - with_source) / ulp, 1) << args << ": got " << format_double(cli) << ", want "
                                                           << format_double(with_source);
            ++cli_checked;
        }
    }
    for (const auto& [method, u] : worst) std::cout << method << ": worst error " << u << " ulps of theta0\n";
    std::cout << "the phase in doubles, up to 1e6 periods: worst error " << worst_in_doubles_1e6 << " rad\n";
    std::cout << "command-line rows (the program's coefficients are the file's doubles): " << cli_checked << "\n";
    EXPECT_GE(cli_checked, 21);
}

}  // namespace

namespace {

/// The value after `flag ` in a command line, or "" without it.
std::string argument(const std::string& args, const std::string& flag) {
    const auto at = args.find(flag + " ");
    if (at == std::string::npos) return "";
    const auto from = at + flag.size() + 1;
    return args.substr(from, args.find(' ', from) - from);
}

/// The arguments with --theta0, --omega0 and --energy written as the exact decimals of their
/// doubles: the program takes numbers as written, and these references are of the doubles.
std::string doubles_as_written(const std::string& args) {
    std::string out = args;
    for (const char* option : {"--theta0 ", "--omega0 ", "--energy "}) {
        const auto at = out.find(option);
        if (at == std::string::npos) continue;
        const auto start = at + std::string(option).size();
        const auto end = out.find(' ', start);
        const std::string text = out.substr(start, end == std::string::npos ? std::string::npos : end - start);
        char exact[1200];
        std::snprintf(exact, sizeof exact, "%.800g", std::strtod(text.c_str(), nullptr));
        out.replace(start, text.size(), exact);
    }
    return out;
}

TEST(HugeTimes, StatesAndEnergiesReduceTheTimeExactly) {
    // state_times.csv (make_state_times.py): librations from a state or an energy, rotations
    // both ways and the separatrix, up to 1e300 periods on. The period comes from the exact
    // energy of the state, the time is reduced modulo it in MPFR, and a rotation's whole turns
    // are added back exactly: theta modulo 2 pi and omega within a few ulps, the unwrapped
    // angle (1e301 at 1e300 periods) within an ulp or two of itself.
    const auto rows = test_support::read_reference_text("state_times.csv");
    ASSERT_GE(rows.size(), 80u);
    const double two_pi = 2 * std::numbers::pi;
    const double ulp_two_pi = std::nextafter(two_pi, 7.0) - two_pi;
    double worst_reduced = 0;
    double worst_unwrapped = 0;
    double worst_omega = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const std::string& args = rows[i].at(0);
        const double s = number(argument(args, "--at"));
        const std::string energy = argument(args, "--energy");
        const motion m = energy.empty() ? motion::from_state({number(argument(args, "--theta0")),
                                                              number(argument(args, "--omega0"))})
                                        : motion::from_energy(number(energy));
        const double want_omega = number(rows[i].at(3));
        // The library: theta at the reduced time is theta modulo 2 pi.
        if (m.has_period()) {
            const time_reducer reduce(m, scale_of(argument(args, "--time")), std::fabs(s));
            const double t = reduce(s);
            const double off = std::remainder(m.theta(t) - number(rows[i].at(2)), two_pi) / ulp_two_pi;
            EXPECT_LE(std::fabs(off), 4) << args << ": theta mod 2 pi off by " << off << " ulps of 2 pi";
            worst_reduced = std::max(worst_reduced, std::fabs(off));
        }
        // The command line: the unwrapped angle and omega.
        const auto r = test_support::run_cli(doubles_as_written(args));
        ASSERT_EQ(r.status, 0) << args << ": " << r.err;
        const auto fields = split_at(r.out.substr(r.out.find('\n') + 1), ',');
        ASSERT_EQ(fields.size(), 3u) << r.out;
        const double theta = number(fields[1]);
        const double want = number(rows[i].at(1));
        const double scale = std::max(std::fabs(want), two_pi);
        const double u = std::fabs(theta - want) / (std::nextafter(scale, INFINITY) - scale);
        EXPECT_LE(u, 6) << args << ": got " << fields[1] << ", want " << rows[i].at(1);
        worst_unwrapped = std::max(worst_unwrapped, u);
        const double omega_off = std::fabs(number(fields[2]) - want_omega);
        EXPECT_LE(omega_off, 2e-15) << args << ": omega " << fields[2] << ", want " << rows[i].at(3);
        worst_omega = std::max(worst_omega, omega_off);
    }
    std::cout << "worst: theta mod 2 pi " << worst_reduced << " ulps of 2 pi, unwrapped theta " << worst_unwrapped
              << " ulps of itself, omega " << worst_omega << "\n";
}

}  // namespace

namespace {

TEST(PeriodErrors, Order92AtPiMinus1e12AgainstAnIndependentRun) {
    // order92_near_pi.csv (make_order92_near_pi.py): theta(t) of the order-92 level at
    // pi - 1e-12, its coefficients from a fixed-point run at 256 and 512 bits, evaluated at 60
    // digits. The program's level (MPFR, rounded once to doubles) must give the same motion:
    // at one period, -3.883 (the level is a poor solution there, but the number is its own).
    const auto rows = test_support::read_reference_text("order92_near_pi.csv");
    ASSERT_GE(rows.size(), 6u);
    // One run for every time (the level costs a few seconds in MPFR).
    std::string times;
    for (std::size_t i = 1; i < rows.size(); ++i) times += (i > 1 ? "," : "") + argument(rows[i].at(0), "--at");
    const std::string first = rows[1].at(0);
    const std::string args = first.substr(0, first.find(" --at ")) + " --at " + times;
    const auto r = test_support::run_cli(args);
    ASSERT_EQ(r.status, 0) << args << ": " << r.err;
    const auto lines = split_at(r.out, '\n');
    ASSERT_GE(lines.size(), rows.size()) << r.out;
    double worst = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const auto fields = split_at(lines[i], ',');
        const double got = number(fields.at(1));
        const double want = number(rows[i].at(1));
        EXPECT_LE(std::fabs(got - want), 1e-14) << rows[i].at(0) << ": got " << fields.at(1) << ", want " << rows[i].at(1);
        worst = std::max(worst, std::fabs(got - want));
    }
    std::cout << "worst error: " << worst << " rad\n";
}

}  // namespace

namespace {

TEST(NearPi, PeriodRatioAloneIsTheSolutionsOwn) {
    // period_ratio() skips the nome the coefficients need: the same double as the solution's,
    // from subnormal amplitudes to pi - 1e-300.
    std::vector<amplitude> amplitudes{amplitude(5e-324), amplitude(1e-10), amplitude(1.0), amplitude(2.5)};
    for (const auto& r : near_pi_rows()) amplitudes.push_back(parse_amplitude(r.expression));
    for (int i = 1; i < 100; ++i) amplitudes.emplace_back(i * std::numbers::pi / 100);
    for (const auto& a : amplitudes) {
        EXPECT_EQ(period_ratio(a), exact_solution(a).period_ratio()) << format_double(a.radians());
    }
}

}  // namespace

namespace {

TEST(HugeTimes, ApproximantsOfStatesRunOnTheLibrationsClock) {
    // state_approximant_times.csv (make_state_approximant_times.py): approximants of
    // librations from a state or an energy, on the libration's exact clock (the time since its
    // turning point +theta0), with the file's double coefficients and w/w0, up to 1e300 periods
    // of T0: within a few ulps of theta0 (of theta about 2 pi n; the clock's start is a double).
    const auto rows = test_support::read_reference_text("state_approximant_times.csv");
    ASSERT_GE(rows.size(), 80u);
    double worst = 0;
    int cli_checked = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const std::string& args = rows[i].at(0);
        const double s = number(argument(args, "--at"));
        const std::string energy = argument(args, "--energy");
        const motion m = energy.empty() ? motion::from_state({number(argument(args, "--theta0")),
                                                              number(argument(args, "--omega0"))})
                                        : motion::from_energy(number(energy));
        fourier_solution solution{number(rows[i].at(1)), {}};
        for (const auto& c : split_at(rows[i].at(2), ';')) solution.coefficients.push_back(number(c));
        const double want = number(rows[i].at(3));
        // In ulps of theta0, or of theta where the libration swings about 2 pi n.
        const double size = std::max(m.amplitude().radians(), std::fabs(want));
        const double ulp = std::nextafter(size, INFINITY) - size;
        const time_reducer reduce(m, scale_of("t/T0"), std::fabs(s), solution.frequency_ratio);
        const double got = m.libration_center() + solution.theta_at_phase(reduce.phase(s) + start_phase(m, solution));
        const double u = std::fabs(got - want) / ulp;
        EXPECT_LE(u, 6) << args << ": got " << format_double(got) << ", want " << rows[i].at(3);
        worst = std::max(worst, u);
        // The command line, where the program's own coefficients are the file's doubles: its
        // phase is formed with the solution's own w/w0 from the exact amplitude (its exact
        // source), not the double taken as exact as this file's rows do, and its start's phase
        // from the clock of the numbers as written (time_reducer::start_phase).
        const fourier_solution own = method_solution(parse_method(argument(args, "--method")), m.amplitude());
        if (own.frequency_ratio == solution.frequency_ratio && own.coefficients == solution.coefficients) {
            const auto r = test_support::run_cli(doubles_as_written(args));
            ASSERT_EQ(r.status, 0) << args << ": " << r.err;
            const auto fields = split_at(r.out.substr(r.out.find('\n') + 1), ',');
            const time_reducer exact_phase(m, scale_of("t/T0"), std::fabs(s), own);
            const double with_source =
                m.libration_center() + own.theta_at_phase(exact_phase.phase(s) + exact_phase.start_phase(m));
            EXPECT_LE(std::fabs(number(fields.at(1)) - with_source) / ulp, 1) << args << ": got " << fields.at(1)
                                                                              << ", want " << format_double(with_source);
            ++cli_checked;
        }
    }
    std::cout << "worst error " << worst << " ulps of theta0 (or theta); command-line rows: " << cli_checked << "\n";
    EXPECT_GE(cli_checked, 20);
}

}  // namespace
