// SPDX-License-Identifier: GPL-3.0-or-later
// The numbers at the edges of the domain: subnormal amplitudes, tiny and huge times, and the
// order-N iteration against its own 45-digit run (tests/data/make_iteration.py).
#include "figures/catalog.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/claims.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"
#include "process.hpp"
#include "reference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace {

using std::numbers::pi;

/// One row of iteration.csv.
struct iteration_row {
    std::string name;
    double theta0 = 0;
    int order = 0;
    double lambda = 0;
    double period_ratio = std::nan("");  ///< NaN where lambda <= 0
    double error = std::nan("");         ///< T_N/T - 1
};

std::vector<iteration_row> read_iteration() {
    const std::string path = std::string(PENDULUM_TEST_DATA) + "/iteration.csv";
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::vector<iteration_row> rows;
    std::string line;
    std::getline(in, line);  // comment
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream fields(line);
        std::string field;
        while (std::getline(fields, field, ',')) f.push_back(field);
        f.resize(6);
        iteration_row r{f[0], std::stod(f[1]), std::stoi(f[2]), std::stod(f[3])};
        if (!f[4].empty()) r.period_ratio = std::stod(f[4]);
        if (!f[5].empty()) r.error = std::stod(f[5]);
        rows.push_back(r);
    }
    return rows;
}

/// The rows of one amplitude, by order.
std::map<std::string, std::vector<iteration_row>> by_amplitude() {
    std::map<std::string, std::vector<iteration_row>> out;
    for (const auto& r : read_iteration()) out[r.name].push_back(r);
    return out;
}

/// The worst |T_N/T_N,ref - 1| over the orders of one amplitude.
double worst_period_error(const std::vector<iteration_row>& rows) {
    const auto levels = pendulum::iterated_sequence(rows.front().theta0, rows.back().order);
    double worst = 0;
    for (const auto& r : rows) {
        if (std::isnan(r.period_ratio)) continue;
        const double got = levels[static_cast<std::size_t>(r.order)].period_ratio();
        worst = std::max(worst, std::fabs(got / r.period_ratio - 1));
    }
    return worst;
}

}  // namespace

TEST(Iteration, EveryLevelWithin2e15OfTheExactArithmeticIteration) {
    // The projection is exact up to rounding at every level, for theta0 <= 9 pi/10, N <= 200.
    const auto rows = by_amplitude();
    for (const char* name : {"pi/2", "3pi/4", "9pi/10"}) {
        const auto& r = rows.at(name);
        ASSERT_EQ(r.back().order, 200) << name;
        const double worst = worst_period_error(r);
        EXPECT_LE(worst, 2e-15) << name;
        std::cout << name << ": worst |T_N/T_N,ref - 1| over N <= 200 = " << worst << "\n";
    }
}

TEST(Iteration, CloseToPiRoundingOfTheStoredCoefficientsIsAllThatIsLeft) {
    // Near pi the iteration amplifies the rounding of its c_k (see the physics notes); what
    // is left is still far below every plotted error.
    const auto rows = by_amplitude();
    for (const char* name : {"0.95pi", "0.99pi"}) {
        const double worst = worst_period_error(rows.at(name));
        EXPECT_LE(worst, 2e-14) << name;
        std::cout << name << ": worst |T_N/T_N,ref - 1| over N <= 40 = " << worst << "\n";
    }
}

TEST(Iteration, BreaksDownAtTheLevelsOfTheExactArithmeticIteration) {
    // lambda < 0 is the scheme's own: at pi - 1e-6 at N = 6, 8, 16, 17.
    const auto rows = by_amplitude();
    for (const char* name : {"pi-1e-6", "pi-1e-9"}) {
        const auto& r = rows.at(name);
        const auto levels = pendulum::iterated_sequence(r.front().theta0, r.back().order);
        for (const auto& row : r) {
            const auto& level = levels[static_cast<std::size_t>(row.order)];
            EXPECT_EQ(level.exists(), row.lambda > 0) << name << " N = " << row.order;
            if (!level.exists()) {
                EXPECT_TRUE(std::isnan(level.period_ratio())) << name << " N = " << row.order;
            }
        }
    }
}

TEST(Edges, EveryMethodIsRightDownToTheSmallestSubnormalAmplitude) {
    // T/T0 = 1 + theta0^2/16 rounds to 1 below 1e-8; c1 = theta0 (1 + theta0^2/192) to theta0.
    const double smallest = std::numeric_limits<double>::denorm_min();
    for (double t : {smallest, 1e-320, 1e-310, 2.2e-308, 1e-300, 1e-200, 1e-102, 1e-38, 2.6e-38, 1e-16, 1e-9}) {
        for (const auto& row : pendulum::method_table()) {
            for (int n : {row.min_n, row.max_n}) {
                const pendulum::method_choice m{&row, n, nullptr};
                const double period = pendulum::method_period(m, t);
                // Every method's own limit (the large-amplitude asymptote's is (2/pi) ln 4), within 2 ulp.
                const double limit = row.name == "log-asymptote" ? 2 * std::log(4.0) / pi : 1.0;
                EXPECT_NEAR(period, limit, 4.5e-16) << m.text() << " at " << t;
                if (!m.has_motion() || row.name == "exact") continue;
                const auto s = pendulum::method_solution(m, t);
                EXPECT_EQ(s.coefficients.front(), t) << m.text() << " at " << t;
                for (double c : s.coefficients) EXPECT_TRUE(std::isfinite(c)) << m.text() << " at " << t;
                EXPECT_EQ(s.theta(0.0), t) << m.text() << " at " << t;
            }
        }
        const pendulum::exact_solution e(t);
        EXPECT_EQ(e.period_ratio(), 1.0) << t;
        EXPECT_EQ(e.coefficient(0), t) << t;
        EXPECT_EQ(e.theta(0.0), t) << t;
        EXPECT_EQ(e.theta_at_fraction(0.5), -t) << t;
        EXPECT_EQ(e.theta_at_fraction(1.0), t) << t;
        EXPECT_EQ(e.theta(2 * pi), t) << t;
        EXPECT_EQ(e.theta_at_fraction(0.25), 0.0) << t;
        // A sixth of a period: theta0 cos(pi/3) = theta0/2 (to the rounding of the phase).
        if (t > 1e-300) {
            EXPECT_NEAR(e.theta_at_fraction(1.0 / 6) / t, 0.5, 1e-15) << t;
        }
    }
    // c3 = -theta0^3/192 and c5 = theta0^5/20480, underflowing gracefully.
    EXPECT_EQ(pendulum::exact_solution(1e-100).coefficient(1), -1e-300 / 192);
    EXPECT_EQ(pendulum::exact_solution(1e-200).coefficient(1), 0.0);
}

TEST(Edges, EveryFiniteTimeGivesAFiniteAngle) {
    // Tiny times were NaN (the Landen recursion overflowed below 1e-154).
    for (double theta0 : {1e-300, 1e-9, 0.5, 1.0, pi / 2, 3.0, pi - 1e-9}) {
        const pendulum::exact_solution e(theta0);
        for (double t : {0.0, 1e-320, 1e-300, 1e-155, 1e-154, 1e-100, 1e-20, 1e-9, 1e-8, 1.1e-8, 1e-3, 1e10, 1e100,
                         1e300, std::numeric_limits<double>::max()}) {
            for (double sign : {1.0, -1.0}) {
                const double a = e.theta(sign * t);
                const double b = e.theta_at_fraction(sign * t);
                ASSERT_TRUE(std::isfinite(a) && std::isfinite(b)) << theta0 << " at " << t;
                ASSERT_LE(std::fabs(a), theta0) << theta0 << " at " << t;
                ASSERT_LE(std::fabs(b), theta0) << theta0 << " at " << t;
                if (t < 1e-20) {
                    EXPECT_EQ(a, theta0) << theta0 << " at " << t;
                    EXPECT_EQ(b, theta0) << theta0 << " at " << t;
                }
            }
        }
    }
    // Near t = 0: theta0 - theta = sin(theta0) t^2 / 2 (w0 t units), checked at t = 1e-5.
    const pendulum::exact_solution e(1.0);
    EXPECT_NEAR((1.0 - e.theta(1e-5)) / (std::sin(1.0) * 0.5e-10), 1.0, 1e-5);
    const auto j = pendulum::jacobi(1e-200, 0.5);
    EXPECT_EQ(j.sn, 1e-200);
    EXPECT_EQ(j.cn, 1.0);
    EXPECT_EQ(j.dn, 1.0);
}

TEST(Iteration, TheConvergenceFigurePlotsOnlyPointsRightTo10Percent) {
    // Every drawn point within 10 % of the iteration's true |T_N/T - 1| (45-digit run); the
    // rounding noise below (3.3e-16 drawn at pi/2, N = 40, where the truth is 3.7e-42) is a gap.
    const auto rows = by_amplitude();
    const auto fig = figures::build(figures::find("convergence"), {});
    const auto& series = fig.panels.at(0).data;
    const char* names[] = {"pi/2", "3pi/4", "9pi/10", "0.95pi", "0.99pi"};
    ASSERT_EQ(series.size(), std::size(names));
    for (std::size_t i = 0; i < series.size(); ++i) {
        const auto& ref = rows.at(names[i]);
        int drawn = 0;
        int drawable = 0;
        for (std::size_t p = 0; p < series[i].x.size(); ++p) {
            const int n = static_cast<int>(series[i].x[p]);
            const double truth = std::fabs(ref.at(static_cast<std::size_t>(n)).error);
            if (truth >= 1e-13) ++drawable;
            if (std::isnan(series[i].y[p])) continue;
            ++drawn;
            EXPECT_NEAR(series[i].y[p] / truth, 1.0, 0.1) << names[i] << " N = " << n;
        }
        // Nothing that can be computed to 10 % is left out.
        EXPECT_GE(drawn, drawable) << names[i];
        std::cout << names[i] << ": " << drawn << " of " << series[i].x.size() << " points drawn\n";
    }
}

TEST(EdgesCli, TinyAmplitudesAndTimesGiveNumbersNotErrors) {
    // These were exit 1 (a Bessel underflow), exit 2 (agm of 1 and 0) and nan.
    for (const char* t : {"5e-324", "1e-320", "1e-300", "1e-100", "1e-38"}) {
        const auto r = test_support::run_cli(std::string("eval --theta0 ") + t + " --order 6 --method second");
        EXPECT_EQ(r.status, 0) << t << r.err;
        EXPECT_EQ(r.out.find("nan"), std::string::npos) << t;
        for (const char* m : {"exact", "first", "second", "order:6"}) {
            const auto tr = test_support::run_cli(std::string("trajectory --samples 3 --theta0 ") + t + " --method " + m);
            EXPECT_EQ(tr.status, 0) << t << " " << m << tr.err;
            EXPECT_EQ(tr.out.find("nan"), std::string::npos) << t << " " << m;
        }
    }
    const auto r = test_support::run_cli("trajectory --theta0 1 --at 1e-155,1e-320,-1e-200");
    EXPECT_EQ(r.out, "t_over_T,theta\n1e-155,1\n1e-320,1\n-1e-200,1\n");
    const auto p = test_support::run_cli("trajectory --theta0 1 --periods 1e-320 --samples 10");
    EXPECT_EQ(p.status, 0);
    EXPECT_EQ(p.out.find("nan"), std::string::npos) << p.out;
}

TEST(EdgesCli, TheBreakdownOfTheIterationIsSaidNotPrintedAsNan) {
    // At pi - 1e-6 the levels 6, 8, 16, 17 have lambda < 0: empty fields, JSON null, a warning.
    const auto r = test_support::run_cli("eval --theta0 'pi-1e-6,pi/2' --order 5..8");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
    const auto first_row = r.out.substr(r.out.find('\n') + 1);
    const auto fields = first_row.substr(0, first_row.find('\n'));
    // ..., period_order5, period_order6 (empty), period_order7, period_order8 (empty)
    EXPECT_NE(fields.find(",,"), std::string::npos) << fields;
    EXPECT_EQ(fields.back(), ',') << fields;
    // Named by its exact distance from pi, which the double theta0 cannot show.
    EXPECT_NE(r.err.find("theta0 = pi - 1e-06: the iteration has no period at order 6, 8"), std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("1.5707963267948966"), std::string::npos) << "no warning for pi/2: " << r.err;
    const auto j = test_support::run_cli("eval --theta0 pi-1e-6 --order 6 --format json");
    EXPECT_NE(j.out.find("\"period_order6\": null"), std::string::npos) << j.out;
    // A trajectory of a level that does not exist is an error naming --theta0.
    const auto t = test_support::run_cli("trajectory --theta0 pi-1e-6 --method order:6 --at 0");
    EXPECT_EQ(t.status, 2);
    EXPECT_EQ(t.out, "");
    EXPECT_NE(t.err.find("--theta0 pi-1e-6: the iteration has no period at order 6"), std::string::npos) << t.err;
}

TEST(EdgesCli, OrdersAreRangesComputedOnceAndEachAColumn) {
    // --order 0..200 in one call: one sequence per amplitude (it took 167 s as 201 sequences).
    const auto r = test_support::run_cli("eval --theta0 pi/2 --order 0..200 --order 7 --method order:200");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto header = r.out.substr(0, r.out.find('\n'));
    EXPECT_NE(header.find(",period_order0,period_order1,"), std::string::npos);
    EXPECT_NE(header.find(",period_order200,period_order:200"), std::string::npos) << header;
    EXPECT_EQ(std::count(header.begin(), header.end(), ','), 17 + 201 + 1 - 1) << "order 7 is one column";
    const auto levels = pendulum::iterated_sequence(pi / 2, 200);
    const auto row = r.out.substr(r.out.find('\n') + 1);
    std::vector<std::string> f;
    std::stringstream fields(row.substr(0, row.find('\n')));
    for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
    ASSERT_EQ(f.size(), 17u + 201 + 1);
    for (int n = 0; n <= 200; ++n) {
        EXPECT_EQ(std::stod(f[static_cast<std::size_t>(17 + n)]), levels[static_cast<std::size_t>(n)].period_ratio()) << n;
    }
    EXPECT_EQ(f.back(), f[17 + 200]);
    for (const char* bad : {"5..2", "0..201", "..4", "1..", "a..b", "1...3"}) {
        const auto b = test_support::run_cli(std::string("eval --theta0 1 --order '") + bad + "'");
        EXPECT_EQ(b.status, 2) << bad;
        EXPECT_NE(b.err.find("--order"), std::string::npos) << bad << ": " << b.err;
    }
}

TEST(Edges, TheExactCirclesOfTheCoefficientFiguresAreRightTo1e13) {
    // c5 at pi/24 from mpmath (40 digits): 8 q^(5/2) / (5 (1 + q^5)).
    EXPECT_NEAR(pendulum::exact_solution(pi / 24).coefficient(2) / 1.879917827205231314298837e-9, 1.0, 1e-13);
    EXPECT_NEAR(pendulum::exact_solution(pi / 24).coefficient(1) / -0.000011694457029861857183856, 1.0, 1e-13);
    // Every circle of the paper's coefficient figures (the exact series) is the closed form.
    int circles = 0;
    for (const char* id : {"c1-lowest", "coefficients-first", "coefficients-second"}) {
        const auto fig = figures::build(figures::find(id), {});
        for (std::size_t p = 0; p < fig.panels.size(); ++p) {
            const auto& s = fig.panels[p].data.front();  // the exact series comes first
            for (std::size_t i = 0; i < s.x.size(); ++i) {
                if (!(s.x[i] > 0 && s.x[i] < pi)) continue;
                const double c = pendulum::exact_solution(s.x[i]).coefficient(static_cast<int>(p));
                EXPECT_NEAR(s.y[i] / c, 1.0, 1e-13) << id << " panel " << p << " at " << s.x[i];
                ++circles;
            }
        }
    }
    EXPECT_GT(circles, 100);
}

namespace {

/// The measured value of the claims row whose quantity is `quantity`.
double claimed(const std::vector<pendulum::claim_measure>& rows, const std::string& quantity) {
    for (const auto& r : rows) {
        if (r.quantity == quantity) return r.value;
    }
    ADD_FAILURE() << "no row " << quantity;
    return std::nan("");
}

}  // namespace

TEST(Claims, EveryMeasuredNumberIsPinned) {
    const auto rows = pendulum::paper_claims();
    // Periods and crossings against mpmath (30 digits: findroot of the same differences).
    EXPECT_NEAR(claimed(rows, "lowest-order T/T - 1 at pi/2"), -0.27284126778990233191, 3e-14);  // in %: 3e-16 of T
    EXPECT_NEAR(claimed(rows, "amplitude where |T/T - 1| reaches 0.1 %"), 1.2600532771255706208, 1e-11);
    EXPECT_NEAR(claimed(rows, "amplitude where |T/T - 1| reaches 0.2 %"), 84.194988770239208117, 1e-9);
    EXPECT_NEAR(claimed(rows, "first-order T/T - 1 at pi/2"), 0.40887399333867626284, 3e-14);
    EXPECT_NEAR(claimed(rows, "amplitude below which first order is worse than lowest"), 1.7252107699859170575, 1e-11);
    // Fig. 6: second order at 95pi/100 is 0.046 rad off with a +0.03 % period: adequate.
    EXPECT_NEAR(claimed(rows, "max |theta_second - theta| over a period at 95pi/100"), 0.0458299, 1e-6);
    EXPECT_NEAR(claimed(rows, "second-order T/T - 1 at 95pi/100"), 0.0334228, 1e-6);
    EXPECT_NEAR(claimed(rows, "second-order T/T - 1 at 99pi/100"), -6.98747, 1e-4);
    EXPECT_NEAR(claimed(rows, "max |theta_lowest - theta| over a period at pi/2"), 0.0516163, 1e-6);
    EXPECT_NEAR(claimed(rows, "max |theta_lowest - theta| over a period at 9pi/10"), 1.60387, 1e-5);
    // The closing remark: the first orders within 1e-12 are those of the 45-digit iteration.
    const auto ref = by_amplitude();
    for (const char* name : {"pi/2", "9pi/10", "0.99pi"}) {
        int first = -1;
        for (const auto& r : ref.at(name)) {
            if (std::fabs(r.error) < 1e-12) {
                first = r.order;
                break;
            }
        }
        EXPECT_EQ(claimed(rows, std::string("first order N with |T_N/T - 1| < 1e-12 at ") + name), first) << name;
    }
    EXPECT_EQ(claimed(rows, "first order N without a period (lambda < 0) at pi - 1e-6"), 6);
    for (const auto& r : rows) EXPECT_FALSE(r.verdict.empty()) << r.quantity;
}

// The claims print 17 digits: their period errors are the correctly rounded ones (MPFR
// throughout, 100 (T_m/T - 1) rounded once), at the exact amplitudes the claims name
// (tests/data/make_claims_exact_errors.py).
TEST(Claims, PeriodErrorsRightToTheLastDigit) {
    const auto rows = pendulum::paper_claims();
    const auto ref = test_support::read_reference_text("claims_exact_errors.csv");
    ASSERT_EQ(ref.size(), 6u);
    for (std::size_t i = 1; i < ref.size(); ++i) {
        const std::string quantity =
            (ref[i].at(0) == "second" ? "second-order" : ref[i].at(0) + "-order") + " T/T - 1 at " + ref[i].at(1);
        const double want = std::stod(ref[i].at(2));
        const double got = claimed(rows, quantity);
        EXPECT_LE(std::fabs(got - want), std::fabs(want) * std::numeric_limits<double>::epsilon())
            << quantity << ": " << pendulum::format_double(got) << ", want " << ref[i].at(2);
    }
}

TEST(Claims, TheLargestDeviationIsTheLargestOfADenseScan) {
    for (const auto& [method, theta0] : {std::pair{"lowest", pi / 2}, {"second", 0.95 * pi}, {"first", 2.0}}) {
        const pendulum::exact_solution e(theta0);
        const auto approx = pendulum::method_solution(pendulum::parse_method(method), theta0);
        double scan = 0;
        for (int i = 0; i <= 100000; ++i) {
            const double s = i / 100000.0;
            scan = std::max(scan, std::fabs(approx.theta(s * 4 * e.quarter_period()) - e.theta_at_fraction(s)));
        }
        const double found = pendulum::max_deviation_over_period(method, theta0);
        EXPECT_GE(found, scan - 1e-15) << method;
        EXPECT_LE(found, scan + 1e-8) << method;
    }
}

TEST(Claims, CsvAndJsonLikeEval) {
    const auto csv = test_support::run_cli("claims");
    ASSERT_EQ(csv.status, 0) << csv.err;
    EXPECT_EQ(csv.out.substr(0, csv.out.find('\n')), "claim,where,statement,quantity,value,unit,verdict");
    EXPECT_NE(csv.out.find("lowest-period-0.1%,Sec. 1 (Introduction),lowest-order period better than 0.1 % up to "
                           "pi/2,lowest-order T/T - 1 at pi/2,-0.2728412677899023,%,fails\n"),
              std::string::npos)
        << csv.out;
    EXPECT_NE(csv.out.find("\"Abstract; Sec. 2.2, Fig. 2\""), std::string::npos) << "fields with commas are quoted";
    const auto json = test_support::run_cli("claims --format json");
    ASSERT_EQ(json.status, 0);
    EXPECT_NE(json.out.find("{\"claim\": \"lowest-period-0.2%\", \"where\": \"Sec. 3 (Conclusions)\""), std::string::npos)
        << json.out;
    EXPECT_NE(json.out.find("\"value\": 84.19498877023"), std::string::npos);
    EXPECT_EQ(test_support::run_cli("claims --format xml").status, 2);
}
