// SPDX-License-Identifier: GPL-3.0-or-later
// Every number right on every surface: the trajectory command and the trajectory figures
// against the mpmath references in tests/data (long times, the iteration near pi), and the
// starts a spec writes reaching the core as written, the same numbers as the command's.
#include "pendulum/amplitude.hpp"
#include "pendulum/methods.hpp"
#include "process.hpp"
#include "reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using test_support::run_cli;

/// A number as printed (strtod: no exception for the tiny values near the top).
double number(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

/// The rows of a CSV table printed by a command, split at commas, the header first.
std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    std::stringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        std::vector<std::string> row;
        std::stringstream fields(line);
        for (std::string field; std::getline(fields, field, ',');) row.push_back(field);
        rows.push_back(row);
    }
    return rows;
}

/// Writes a spec file and returns its path.
std::filesystem::path write_spec(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
    const auto path = dir / name;
    std::ofstream(path) << text;
    return path;
}

/// A figure with one trajectory panel of `keys`.
std::string trajectory_spec(const std::string& keys) {
    return "[figure]\ndescription = \"numbers\"\n[[panel]]\nplot = \"trajectory\"\n" + keys + "\n";
}

/// The (x, y) points of one series of `data SPEC` (all series where `id` is empty).
std::vector<std::pair<double, double>> figure_points(const std::filesystem::path& spec, const std::string& id) {
    const auto r = run_cli("data '" + spec.string() + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    std::vector<std::pair<double, double>> points;
    const auto rows = csv_rows(r.out);
    for (std::size_t i = 1; i < rows.size(); ++i) {
        if (rows[i].size() < 5 || (!id.empty() && rows[i][4] != id)) continue;
        points.emplace_back(std::stod(rows[i][2]), std::stod(rows[i][3]));
    }
    return points;
}

/// The reference rows of long_time_phase.csv for one amplitude and method: time -> theta.
std::vector<std::pair<std::string, double>> long_time_rows(const std::string& theta0, const std::string& method) {
    std::vector<std::pair<std::string, double>> out;
    for (const auto& f : test_support::read_reference_text("long_time_phase.csv")) {
        if (f.at(0) == theta0 && f.at(1) == method) out.emplace_back(f.at(2), std::stod(f.at(3)));
    }
    return out;
}

/// The amplitude in radians of long_time_phase.csv's texts ("2.5", "pi-1e-12").
double radians(const std::string& text) {
    return text.starts_with("pi-") ? M_PI - std::stod(text.substr(3)) : std::stod(text);
}

TEST(LongTimesCommand, EveryMethodsPhaseFromItsOwnFrequencyUpToTheLargestDouble) {
    // long_time_phase.csv (make_long_time_phase.py, 1400 bits): the trajectory command formed
    // an approximant's phase with w/w0 rounded to a double: at theta0 = 2.5 the lowest order
    // gave 2.4741424088724857 at 1e15 T [2.3075842464475386] and 1.7400543364789234 at the
    // largest double [0.72327724458982943].
    for (const std::string theta0 : {"1", "2.5", "pi-1e-12", "pi-0.01"}) {
        for (const std::string method : {"harmonic", "lowest", "first", "second", "polynomial", "order:3"}) {
            const auto rows = long_time_rows(theta0, method);
            if (rows.empty()) continue;
            std::string at;
            for (const auto& [s, theta] : rows) at += (at.empty() ? "" : ",") + s;
            const auto r = run_cli("trajectory --theta0 " + theta0 + " --method " + method + " --at " + at);
            ASSERT_EQ(r.status, 0) << r.err;
            const auto got = csv_rows(r.out);
            ASSERT_EQ(got.size(), rows.size() + 1) << r.out;
            const double ulp = std::nextafter(radians(theta0), 4.0) - radians(theta0);
            for (std::size_t i = 0; i < rows.size(); ++i) {
                EXPECT_NEAR(std::stod(got[i + 1].at(1)), rows[i].second, 4 * ulp)
                    << theta0 << " " << method << " at t/T = " << rows[i].first;
            }
        }
    }
}

TEST(LongTimesCommand, TheIssuesReproductions) {
    const auto far = run_cli("trajectory --theta0 2.5 --method lowest --at 1e15,1.7976931348623157e308");
    ASSERT_EQ(far.status, 0) << far.err;
    const auto rows = csv_rows(far.out);
    EXPECT_NEAR(std::stod(rows.at(1).at(1)), 2.3075842464475386, 4 * 4.44e-16);
    EXPECT_NEAR(std::stod(rows.at(2).at(1)), 0.72327724458982943, 4 * 4.44e-16);
    // Near pi within a period: 175 ulp(theta0) before [0.2511412146364261481859648].
    const auto near = run_cli("trajectory --theta0 pi-1e-12 --method first --at 0.9");
    ASSERT_EQ(near.status, 0) << near.err;
    EXPECT_NEAR(std::stod(csv_rows(near.out).at(1).at(1)), 0.2511412146364261481859648, 4 * 4.44e-16);
}

TEST(LongTimesCommand, AStatesReducedTimeIsCarriedBeyondOneDouble) {
    // state_long_times.csv (make_state_long_times.py, 3500 bits): rotations from (1e-300, 2)
    // and (3, 0.5) out to the largest double. The reduced w0 t was one double (half an ulp of
    // up to 700 rad): theta(441 T0) for (1e-300, 2) was 11.543765862800525, 335 ulps from
    // 11.54376586279993. An angle beyond the largest double is left out (none can hold it).
    const auto rows = test_support::read_reference_text("state_long_times.csv");
    ASSERT_GE(rows.size(), 12u);
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const double want = number(rows[i].at(1));
        if (!(std::fabs(want) < 1e308)) continue;
        const auto r = run_cli(rows[i].at(0));
        ASSERT_EQ(r.status, 0) << rows[i].at(0) << ": " << r.err;
        const auto got = csv_rows(r.out);
        const double scale = std::max(std::fabs(want), 2 * M_PI);
        const double ulp = std::nextafter(scale, 1e308) - scale;
        EXPECT_LE(std::fabs(number(got.at(1).at(1)) - want), 4 * ulp) << rows[i].at(0);
        // omega at the double of the reduced time: right to an ulp or two of 2 up to 1e15 T0.
        if (std::fabs(number(rows[i].at(0).substr(rows[i].at(0).rfind(' ') + 1))) <= 1e15) {
            EXPECT_NEAR(number(got.at(1).at(2)), number(rows[i].at(2)), 2e-15) << rows[i].at(0);
        }
    }
}

TEST(LongTimesFigures, ApproximantsAThousandPeriodsOutAreTheReferenceAndTheCommands) {
    // A trajectory panel's first point is its range's start, 1000.3 periods: each method's
    // value there is long_time_phase.csv's, and every point is the trajectory command's.
    const auto dir = test_support::temp_dir("numbers-long-figures");
    const std::vector<std::string> methods{"harmonic", "lowest", "first", "second", "polynomial"};
    const auto spec = write_spec(dir, "far.toml",
                                 trajectory_spec("theta0 = \"2.5\"\nmethods = [\"harmonic\", \"lowest\", \"first\", "
                                                 "\"second\", \"polynomial\"]\nrange = [1000.3, 1000.8]"));
    for (const auto& method : methods) {
        const auto points = figure_points(spec, method);
        ASSERT_GE(points.size(), 20u) << method;
        EXPECT_EQ(points.front().first, 1000.3);
        double reference = NAN;
        for (const auto& [s, theta] : long_time_rows("2.5", method)) {
            if (s == "1000.3") reference = theta;
        }
        EXPECT_NEAR(points.front().second, reference, 4 * 4.44e-16) << method;
        // The command at the figure's own abscissae, printed to 17 digits.
        std::string exact_at;
        for (std::size_t i = 0; i < points.size(); i += 10) {
            char text[32];
            std::snprintf(text, sizeof text, "%.17g", points[i].first);
            exact_at += (exact_at.empty() ? "" : ",") + std::string(text);
        }
        const auto r = run_cli("trajectory --theta0 2.5 --method " + method + " --at " + exact_at);
        ASSERT_EQ(r.status, 0) << r.err;
        const auto rows = csv_rows(r.out);
        for (std::size_t i = 0, j = 1; i < points.size(); i += 10, ++j) {
            EXPECT_EQ(std::stod(rows.at(j).at(1)), points[i].second) << method << " at " << points[i].first;
        }
    }
}

TEST(LongTimesFigures, TheIterationNearPiFromItsLevelsOwnFrequency) {
    // order92_near_pi.csv (make_order92_near_pi.py, fixed point at 256 and 512 bits): the
    // order-92 level at pi - 1e-12, in a figure whose range ends 1e6 periods out (the most a
    // panel takes); the level's phase needs its w/w0 to 2^-80 there, which the run that
    // found the level (agreeing with half its bits to 1e-15) does not give without more bits.
    std::map<std::string, double> want;
    for (const auto& f : test_support::read_reference_text("order92_near_pi.csv")) {
        if (f.at(0).starts_with("trajectory")) want[f.at(0).substr(f.at(0).rfind(' ') + 1)] = std::stod(f.at(1));
    }
    ASSERT_TRUE(want.count("999999.75") && want.count("1000000")) << "order92_near_pi.csv lacks the far times";
    const auto dir = test_support::temp_dir("numbers-long-order92");
    const auto spec = write_spec(dir, "order92.toml",
                                 trajectory_spec("theta0 = \"pi-1e-12\"\nmethods = [\"order:92\"]\n"
                                                 "range = [999999.75, 1000000]"));
    const auto points = figure_points(spec, "order:92");
    ASSERT_GE(points.size(), 2u);
    EXPECT_NEAR(points.front().second, want["999999.75"], 8 * 4.44e-16);
    EXPECT_NEAR(points.back().second, want["1000000"], 8 * 4.44e-16);
}

/// The worst difference in ulps between a spec start's figure data (time in T0) and the
/// trajectory command at the same times.
double worst_against_command(const std::string& theta0, const std::string& omega0, const std::string& range) {
    const auto dir = test_support::temp_dir("numbers-long-state");
    const auto spec = write_spec(dir, "state.toml",
                                 trajectory_spec("theta0 = \"" + theta0 + "\"\nomega0 = \"" + omega0 +
                                                 "\"\ntime = \"t/T0\"\nrange = " + range + "\nmethods = [\"exact\"]"));
    const auto points = figure_points(spec, "exact");
    EXPECT_GE(points.size(), 5u);
    std::string at;
    for (const auto& [x, y] : points) {
        char text[32];
        std::snprintf(text, sizeof text, "%.17g", x);
        at += (at.empty() ? "" : ",") + std::string(text);
    }
    const auto r = run_cli("trajectory --theta0 " + theta0 + " --omega0 " + omega0 + " --time t/T0 --at " + at);
    EXPECT_EQ(r.status, 0) << r.err;
    const auto rows = csv_rows(r.out);
    EXPECT_EQ(rows.size(), points.size() + 1);
    double worst = 0;
    for (std::size_t i = 0; i < points.size() && i + 1 < rows.size(); ++i) {
        const double want = std::stod(rows[i + 1].at(1));
        const double ulp = std::nextafter(std::fabs(want) + 1.0, 1e300) - (std::fabs(want) + 1.0);
        worst = std::max(worst, std::fabs(points[i].second - want) / ulp);
    }
    return worst;
}

TEST(SpecStates, AsWrittenTheSameNumbersAsTheCommand) {
    // Before, a spec's theta0/omega0 were doubles: pi-1e-9 at rest lost its distance from pi
    // (6e9 ulps apart at 30 T0), 2pi/3 with 1 was a rotation, not the separatrix (3e7), and
    // (1e-300, 2) the separatrix, not a rotation (its figure times, not reduced exactly, 223).
    EXPECT_LE(worst_against_command("pi-1e-9", "0", "[0, 30]"), 1.0);
    EXPECT_LE(worst_against_command("2pi/3", "1", "[0, 3]"), 1.0);
    EXPECT_LE(worst_against_command("1e-300", "2", "[400, 442]"), 1.0);
}

TEST(SpecStates, TheSeparatrixAndItsNeighboursByTheirRegime) {
    const auto dir = test_support::temp_dir("numbers-long-regimes");
    // E = 2 - 1e-20 is a libration with a period: the default t/T axis is accepted.
    EXPECT_EQ(run_cli("data '" + write_spec(dir, "below.toml", trajectory_spec("energy = \"2-1e-20\"")).string() + "'")
                  .status,
              0);
    // 2pi/3 with 1 is the separatrix exactly: it has no period T, and the message says so.
    const auto at = run_cli(
        "data '" + write_spec(dir, "at.toml", trajectory_spec("theta0 = \"2pi/3\"\nomega0 = 1")).string() + "'");
    EXPECT_EQ(at.status, 2);
    EXPECT_NE(at.err.find("is a separatrix (E = 2): it has no period T"), std::string::npos) << at.err;
    // pi at rest is refused, as an amplitude pi is.
    const auto top = run_cli(
        "data '" + write_spec(dir, "top.toml", trajectory_spec("theta0 = \"pi\"\nomega0 = 0")).string() + "'");
    EXPECT_EQ(top.status, 2);
    EXPECT_NE(top.err.find("top.toml"), std::string::npos) << top.err;
}

TEST(SpecStates, HostileTextIsOneMessageNamingIt) {
    const auto dir = test_support::temp_dir("numbers-long-hostile");
    const auto r = run_cli("data '" + write_spec(dir, "bad.toml",
                                                 trajectory_spec("theta0 = \"pi-1e-9$(touch x)\"\nomega0 = \"0\""))
                                          .string() + "'",
                           dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("theta0"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x"));
}

TEST(LongTimesFigures, TheRangeLimitAMillionPeriodsAcceptedOneMoreRefused) {
    const auto dir = test_support::temp_dir("numbers-long-range");
    const auto ok = write_spec(dir, "ok.toml", trajectory_spec("theta0 = \"1\"\nmethods = [\"lowest\"]\n"
                                                               "range = [999999, 1000000]"));
    EXPECT_EQ(run_cli("data '" + ok.string() + "'").status, 0);
    const auto over = write_spec(dir, "over.toml", trajectory_spec("theta0 = \"1\"\nmethods = [\"lowest\"]\n"
                                                                   "range = [999999, 1000000.0000000001]"));
    const auto r = run_cli("data '" + over.string() + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("at most 1e6"), std::string::npos) << r.err;
}

}  // namespace

// describe's "leaving the exact curve by more than 1 % of the axis": the amplitude where
// |T_lowest - T|/T0 first reaches 1 % of the axis the text names (the spec's exact range,
// [1, 30]: 0.29, not 1 % of the data's 1 to 3.7), found here by bisection on the core's
// periods, and printed to its three digits of pi (a sample of the curve past it would be
// up to pi/512 late).
TEST(DescribeNumbers, DepartureIsWhereTheGapReachesOnePercentOfTheAxis) {
    const auto dir = test_support::temp_dir("describe-departure");
    std::ofstream(dir / "gap.toml") << "[[panel]]\nplot = \"period\"\nmethods = [\"exact\", \"lowest\"]\n"
                                       "y_range = [1, 30]\n";
    const auto r = run_cli("describe " + (dir / "gap.toml").string());
    ASSERT_EQ(r.status, 0) << r.err;
    const auto gap = [](double x) {
        const pendulum::amplitude a(x);
        return std::fabs(pendulum::method_period(pendulum::parse_method("lowest"), a) -
                         pendulum::method_period(pendulum::parse_method("exact"), a));
    };
    double lo = 0.1, hi = 3.1;
    for (int k = 0; k < 100; ++k) (gap((lo + hi) / 2) > 0.29 ? hi : lo) = (lo + hi) / 2;
    char want[64];
    std::snprintf(want, sizeof want, "lowest order at theta0 = %.3gpi", hi / M_PI);
    EXPECT_NE(r.out.find(want), std::string::npos) << want << "\n" << r.out;
    std::filesystem::remove_all(dir);
}
