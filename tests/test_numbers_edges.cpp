// SPDX-License-Identifier: GPL-3.0-or-later
// Edge numbers on every surface: half periods of a state, energies a double does not hold,
// starts whose energy is 0 to every bit, and fields left empty; against numbers_edges.csv
// (make_numbers_edges.py, mpmath at 1300 bits).
#include "process.hpp"
#include "reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace {

using test_support::run_cli;

std::vector<std::string> split_at(const std::string& text, char sep) {
    std::vector<std::string> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, sep)) out.push_back(item);
    return out;
}

/// The fields of the first data row of a CSV (after its header).
std::vector<std::string> first_row(const std::string& csv) {
    const auto lines = split_at(csv, '\n');
    return lines.size() > 1 ? split_at(lines[1], ',') : std::vector<std::string>{};
}

double number(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

/// |got - want| in ulps of `scale`.
double ulps(double got, double want, double scale) {
    scale = std::fabs(scale);
    return std::fabs(got - want) / (std::nextafter(scale, INFINITY) - scale);
}

/// The time of a trajectory's arguments (after --at).
double time_of(const std::string& args) { return number(args.substr(args.rfind("--at ") + 5)); }

// A libration from any state is at its start's mirror image (2 center - theta_s, -omega_s) at
// every odd multiple of half a period and at its start at every whole one: those fields are the
// double nearest the exact value, whatever the start's place in its period (a state not at a
// turning point or the bottom was 28 ulps off at t/T = 0.5: (0.5, 1.9) gave -0.5000000000000014).
// The quarter periods in between keep a few ulps of the amplitude.
TEST(NumbersEdges, HalfPeriodsLandOnTheStartOrItsMirrorImage) {
    const auto rows = test_support::read_reference_text("numbers_edges.csv");
    int checked = 0;
    double worst_quarter = 0;
    for (const auto& row : rows) {
        if (row.at(0) != "motion") continue;
        const std::string& args = row.at(1);
        const auto r = run_cli(args);
        ASSERT_EQ(r.status, 0) << args << ": " << r.err;
        const auto fields = first_row(r.out);
        ASSERT_EQ(fields.size(), 3u) << args << ": " << r.out;
        const double want_theta = number(row.at(2));
        const double want_omega = number(row.at(3));
        const double s = time_of(args);
        if (2 * s == std::nearbyint(2 * s)) {
            EXPECT_LE(ulps(number(fields[1]), want_theta, want_theta), 1.0) << args << ": theta " << fields[1]
                                                                            << ", want " << row.at(2);
            if (std::fabs(want_theta) <= 3.2) {  // about 0: the start's angle negated, exactly
                EXPECT_EQ(number(fields[1]), want_theta) << args << ": theta " << fields[1] << ", want " << row.at(2);
            }
            EXPECT_EQ(number(fields[2]), want_omega) << args << ": omega " << fields[2] << ", want " << row.at(3);
        } else {
            const double scale = std::max(std::fabs(want_theta), 1.0);
            const double off = std::max(ulps(number(fields[1]), want_theta, scale), ulps(number(fields[2]), want_omega, 2.0));
            EXPECT_LE(off, 4.0) << args << ": " << fields[1] << ", " << fields[2] << ", want " << row.at(2) << ", "
                                << row.at(3);
            worst_quarter = std::max(worst_quarter, off);
        }
        ++checked;
    }
    EXPECT_GE(checked, 90);
    std::cout << "quarter periods: worst " << worst_quarter << " ulps\n";
}

/// The number after `key` in a message, in extended precision (1.2e-647 is below a double).
long double number_after(const std::string& text, const std::string& key) {
    const auto at = text.find(key);
    return at == std::string::npos ? NAN : std::strtold(text.c_str() + at + key.size(), nullptr);
}

// A state at rest whose energy is below the smallest normal double (1e-160: 5e-321) or below
// every double (5e-324: 1.2e-647) said nothing: its energy field had fewer digits, or was
// empty, without a word. Now it is said as for any other state, with the exact energy.
TEST(NumbersEdges, EnergiesADoubleDoesNotHoldAreSaid) {
    const auto rows = test_support::read_reference_text("numbers_edges.csv");
    int checked = 0;
    for (const auto& row : rows) {
        if (row.at(0) != "energy") continue;
        const auto r = run_cli(row.at(1));
        ASSERT_EQ(r.status, 0) << row.at(1) << ": " << r.err;
        const long double want = std::strtold(row.at(2).c_str(), nullptr);
        const long double said = number_after(r.err, "the energy is ");
        EXPECT_LE(std::fabs(said / want - 1), 1e-15L) << row.at(1) << ": " << r.err << " want " << row.at(2);
        const auto fields = first_row(r.out);
        ASSERT_GE(fields.size(), 3u) << r.out;
        // The field: the double nearest where there is one above 0, else empty.
        if (want >= 4.9406564584124654e-324L / 2) {
            EXPECT_EQ(number(fields[2]), static_cast<double>(want)) << row.at(1) << ": " << r.out;
        } else {
            EXPECT_EQ(fields[2], "") << row.at(1) << ": " << r.out;
        }
        ++checked;
    }
    EXPECT_EQ(checked, 4);
    // The boundary: the smallest normal double's energy is held, and said nothing of.
    const auto held = run_cli("eval --energy 2.2250738585072014e-308");
    EXPECT_EQ(held.status, 0);
    EXPECT_EQ(held.err, "");
    const auto below = run_cli("eval --energy 2.2250738585072009e-308");
    EXPECT_EQ(below.status, 0);
    EXPECT_NE(below.err.find("fewer digits"), std::string::npos) << below.err;
}

// A start whose energy is 0 to every bit its numbers carry (at rest at a multiple of 2 pi, as
// written) was a libration with the energy of the rounding of pi: (2pi, 0) printed E =
// 7.297143928690786e-232 and an amplitude of 3.8e-116; (1e307pi, 0) an amplitude 0. Now the
// energy must agree at two precisions, as the gap does, or the start is refused with a message.
TEST(NumbersEdges, AStartWhoseEnergyIsZeroToEveryBitIsRefused) {
    for (const char* theta : {"2pi", "-4pi", "1e307pi", "1e300pi"}) {
        const auto r = run_cli(std::string("eval --theta0 ") + theta + " --omega0 0");
        EXPECT_EQ(r.status, 2) << theta << ": " << r.out;
        EXPECT_NE(r.err.find("E = 0 (at rest at the bottom)"), std::string::npos) << theta << ": " << r.err;
        EXPECT_EQ(r.out, "") << theta;
        const auto t = run_cli(std::string("trajectory --theta0 ") + theta + " --omega0 0 --at 1");
        EXPECT_EQ(t.status, 2) << theta << ": " << t.out;
    }
    // The boundary: the smallest double from 2 pi is a start, with its energy (5e-324)^2/2.
    const auto r = run_cli("eval --theta0 2pi+5e-324 --omega0 0");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_LE(std::fabs(number_after(r.err, "the energy is ") / 1.25e-647L - 1), 1e-15L) << r.err;
    EXPECT_EQ(first_row(r.out).at(4), "5e-324") << r.out;
    // An angle far out that is not a multiple of 2 pi keeps its energy: 2 sin^2(1/2).
    const auto far = run_cli("eval --theta0 1e300pi+1 --omega0 0");
    EXPECT_EQ(far.status, 0) << far.err;
    EXPECT_EQ(first_row(far.out).at(2), "0.4596976941318603") << far.out;
}

// A field left empty says why on standard error: a rotation's unwrapped angle beyond the
// largest double was an empty field with no word.
TEST(NumbersEdges, AnEmptyFieldIsSaid) {
    const auto r = run_cli("trajectory --theta0 0 --omega0 3 --time t/T0 --at 1,1e308,1e307");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto lines = split_at(r.out, '\n');
    ASSERT_EQ(lines.size(), 4u) << r.out;
    EXPECT_EQ(split_at(lines[2], ',').at(1), "") << r.out;
    EXPECT_NE(r.err.find("1 field of column theta left empty (null in JSON), the first at t_over_T0 = 1e+308"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("beyond the largest double"), std::string::npos) << r.err;
    // Every field a number: no word.
    const auto full = run_cli("trajectory --theta0 0 --omega0 3 --time t/T0 --at 1,1e307");
    EXPECT_EQ(full.status, 0);
    EXPECT_EQ(full.err, "");
    EXPECT_EQ(full.out.find(",,"), std::string::npos) << full.out;
    // JSON: null, and the same word.
    const auto json = run_cli("trajectory --theta0 0 --omega0 3 --time t/T0 --at 1e308 --format json");
    EXPECT_NE(json.out.find("null"), std::string::npos) << json.out;
    EXPECT_NE(json.err.find("left empty"), std::string::npos) << json.err;
}

// omega of a rotation next to the separatrix far out: (1e-300, 2) 1e15 T0 on it is 6.4e-143,
// next to the top, and kept 3 of its digits against the decimal as written (6.359484957786013e-143
// for 6.359484957786664e-143): the Landen recursion formed dn from a cosine next to pi/2, and
// omega was left at the reduced time's double. Past K/2 from the bottom (1e12 T0, omega
// 6e-189 = k'/dn(K - r)) K - r was formed from K and r as doubles: 1553 ulps. Now the place in
// the revolution and K - r are double-doubles: omega within 4 ulps of itself at every row (both
// halves of the revolution, an energy as written, a backwards start, up to the largest double),
// theta within 2 ulps of itself.
TEST(NumbersEdges, OmegaNextToTheTopFarOutKeepsItsDigits) {
    const auto rows = test_support::read_reference_text("numbers_edges.csv");
    int checked = 0;
    for (const auto& row : rows) {
        if (row.at(0) != "far") continue;
        const auto r = run_cli(row.at(1));
        ASSERT_EQ(r.status, 0) << row.at(1) << ": " << r.err;
        const auto fields = first_row(r.out);
        ASSERT_EQ(fields.size(), 3u) << r.out;
        const double theta = number(row.at(2));
        const double omega = number(row.at(3));
        EXPECT_LE(ulps(number(fields[1]), theta, theta), 2.0) << row.at(1) << ": " << fields[1] << ", want " << row.at(2);
        EXPECT_LE(ulps(number(fields[2]), omega, omega), 4.0) << row.at(1) << ": " << fields[2] << ", want "
                                                              << row.at(3);
        ++checked;
    }
    EXPECT_EQ(checked, 20);
}

}  // namespace
