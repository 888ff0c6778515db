// SPDX-License-Identifier: GPL-3.0-or-later
// eval's cost cuts (issue 37) change no byte: a million plain amplitudes as make bench writes
// them, and 30,000 mixed ones (plain numbers, degrees, pi fractions, expressions, values near
// pi and near 0), print the same tables and warnings as before the cuts.
#include "process.hpp"

#include "pendulum/amplitude.hpp"
#include "pendulum/angle.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cstdint>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace test_support;

namespace {

/// A uniform number in [0, 1) from the generator's top 53 bits (the same on every platform).
double unit(std::mt19937_64& gen) { return static_cast<double>(gen() >> 11) * 0x1p-53; }

/// x with `digits` significant digits, as printf's %.{digits}g writes it.
std::string digits_of(double x, int digits) {
    char buf[64];
    const auto end = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, digits).ptr;
    return std::string(buf, end);
}

/// x as the shortest text that reads back to it.
std::string shortest(double x) {
    char buf[64];
    const auto end = std::to_chars(buf, buf + sizeof buf, x).ptr;
    return std::string(buf, end);
}

/// An integer in [lo, hi].
long between(std::mt19937_64& gen, long lo, long hi) {
    return lo + static_cast<long>(gen() % static_cast<std::uint64_t>(hi - lo + 1));
}

/// One item of the mixed list, of kind `kind` (0..11).
std::string mixed_item(std::mt19937_64& gen, int kind) {
    const double u = unit(gen);
    const double below_pi = 3.141592653589793;  // the largest double below pi
    switch (kind) {
        case 0: return digits_of(0.01 + 3.09 * u, 17);                                  // the bench's kind
        case 1: return shortest(1e-3 + 2.99 * u);                                        // shortest, below 3
        case 2: return digits_of(3 + (below_pi - 3) * u, 17);                            // plain, 3 to pi
        case 3: return digits_of(below_pi - 1e-6 * u, between(gen, 16, 21));             // plain, next to pi
        case 4: return digits_of(0.001 + 179.99 * u, 6) + "deg";                         // degrees
        case 5: {
            const long b = between(gen, 2, 1000);
            return std::to_string(between(gen, 1, b - 1)) + "pi/" + std::to_string(b);  // pi fractions
        }
        case 6: return "pi/2+" + digits_of(1.5 * u, 6);                                   // an expression
        case 7: return "pi-" + digits_of(1 + 9 * u, 5) + "e-" + std::to_string(between(gen, 1, 300));  // near pi
        case 8: return digits_of(1 + 9 * u, 5) + "e-" + std::to_string(between(gen, 1, 300));  // near 0
        case 9: return shortest(3 + static_cast<double>(between(gen, 0, 144)) / 1024);  // doubles from 3 on
        case 10: {
            // 3 to pi as digits and an exponent: 31415926535897e-13.
            std::string d = digits_of(3 + (below_pi - 3) * u, 17);
            d.erase(1, 1);
            while (d.size() > 1 && d.back() == '0') d.pop_back();
            return d + "e-" + std::to_string(d.size() - 1);
        }
        default: return digits_of(0.001 + 0.998 * u, 6) + "pi";  // 0.9pi
    }
}

/// The first `n` of the mixed amplitudes, a few to a line, with comments and blanks as a file has them.
std::string mixed_list(int n) {
    std::mt19937_64 gen(37);
    std::string text = "# mixed amplitudes\n";
    for (int i = 0; i < n; ++i) {
        text += mixed_item(gen, i % 12);
        text += i % 7 == 3 ? ", " : i % 1000 == 999 ? "  # a comment\n" : "\n";
    }
    return text;
}

/// A million amplitudes as make bench writes them: %.17g of 0.01 + 3.09 u.
std::string bench_list() {
    std::mt19937_64 gen(1);
    std::string text;
    for (int i = 0; i < 1000000; ++i) text += digits_of(0.01 + 3.09 * unit(gen), 17) + "\n";
    return text;
}

/// The SHA-256 sum of eval's standard output and error (together, in order) for `args`; its
/// exit status must be 0.
std::string eval_sum(const std::string& args) {
    const auto r = run_command("{ '" + std::string(PENDULUM_EXE) + "' eval " + args + " 2>&1; echo \"exit $?\"; } | sha256sum");
    EXPECT_EQ(r.status, 0) << args << ": " << r.err;
    return r.out.substr(0, 64);
}

struct printed {
    const char* args;    ///< eval's options after --theta0 @LIST
    const char* sha256;  ///< the sum of its output before the cuts
};

void expect_sums(const std::string& list_text, const std::string& name, const std::vector<printed>& sums) {
    const auto dir = temp_dir(name);
    std::ofstream(dir / "list", std::ios::binary) << list_text;
    for (const auto& p : sums) {
        for (const char* jobs : {"1", "2"}) {
            const std::string args = "--theta0 @'" + (dir / "list").string() + "' " + p.args + " --jobs " + jobs;
            EXPECT_EQ(eval_sum(args), p.sha256) << p.args << " --jobs " << jobs;
        }
    }
    std::filesystem::remove_all(dir);
}

}  // namespace

// clang-format off
// 30,000 mixed amplitudes: every default column, the bench's columns with pi - theta0, JSON.
TEST(EvalCost, MixedAmplitudesPrintAsBeforeTheCuts) {
    expect_sums(mixed_list(30000), "eval-mixed", {
        {"", "af11b3a71db45d9f265d82d1ebc873aca49833ac5836c09f8a8da6db8fdca948"},
        {"--columns theta0,period_exact,pi_minus_theta0", "43882b276af3fd168b01dcb6ff4a9d6c3fd954d79aefb6586e75fffffb670f6a"},
        {"--format json --columns theta0,period_exact,c1_exact,period_lowest", "2c00eb26ff248a94154c65753d0e0b8333815ab41340a87b838c1cca76dc1ad3"},
    });
}

// The first 240 of them (20 of each kind) with the iteration's orders 6 and 8: the warnings
// of the levels without a period (40 rows close to pi) follow their rows.
TEST(EvalCost, WarningsFollowTheirRowsAsBeforeTheCuts) {
    expect_sums(mixed_list(240), "eval-warnings", {
        {"--columns theta0,pi_minus_theta0 --order 6,8", "e0a93c02709d66cbc72b4b49caae19954b598bdd9994978d918b96ac4dbea901"},
    });
}

// The bench's million: theta0 and period_exact as before the cuts.
TEST(EvalCost, TheBenchsMillionPrintsAsBeforeTheCuts) {
    expect_sums(bench_list(), "eval-million", {
        {"--columns theta0,period_exact", "b2c0031f76e4decca4c3aeb75836c0063a5f92d0c74b7ae98b450bc4f636bb56"},
    });
}
// clang-format on

namespace {

/// A double as the reference writes it (repr: the shortest text that reads back to it).
double number(const std::string& text) {
    double x = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
    if (ec != std::errc() || end != text.data() + text.size()) throw std::runtime_error("bad number " + text);
    return x;
}

}  // namespace

// Plain numbers from 3 to pi against mpmath (make_eval_plain_moduli.py): theta0 is the text's
// double, and d = pi - x, k = sin(x/2), k' = cos(x/2) of the exact decimal x, each the double
// nearest, with or without MPFR (the largest double below pi in 16 to 19 digits, decimals
// closer to pi than any double, pi - 10^-n, exponents, 20 digits and more, 3000 random ones).
// A text that is a double itself ("3", "3.125") is that double, whose moduli are the double path's.
TEST(EvalCost, PlainNumbersFromThreeToPiAreRoundedOnce) {
    std::ifstream in(std::string(PENDULUM_TEST_DATA) + "/eval_plain_moduli.csv");
    ASSERT_TRUE(in) << "eval_plain_moduli.csv";
    std::string line;
    std::getline(in, line);
    int rows = 0;
    int exact = 0;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) f.push_back(cell);
        ASSERT_EQ(f.size(), 5u) << line;
        const pendulum::amplitude a = pendulum::parse_amplitude(f[0]);
        ++rows;
        EXPECT_EQ(a.radians(), number(f[1])) << f[0];
        if (a.exact_radians()) {
            EXPECT_EQ(number(f[1]), a.radians()) << f[0];
            EXPECT_EQ(pendulum::amplitude(a.radians()).kp(), a.kp()) << f[0];
            ++exact;
            continue;
        }
        EXPECT_EQ(a.from_pi(), number(f[2])) << f[0];
        EXPECT_EQ(a.k(), number(f[3])) << f[0];
        EXPECT_EQ(a.kp(), number(f[4])) << f[0];
    }
    EXPECT_EQ(rows, 3044);
    EXPECT_GE(exact, 5);  // 3, 3.0, 3.125, 3.140625, 3.0e0
}

// Decimals just above pi, which round to the largest double below it, are refused as pi is
// (with 19 digits by the bounds' own test of d, with 20 by MPFR), and pi itself too.
TEST(EvalCost, PlainNumbersAbovePiAreRefused) {
    for (const char* text : {"3.141592653589793239", "3.1415926535897932385", "3.1415926535897933", "3.1415926535897936"}) {
        const auto r = run_cli(std::string("eval --theta0 ") + text);
        EXPECT_EQ(r.status, 2) << text;
        EXPECT_NE(r.err.find(text), std::string::npos) << r.err;
        EXPECT_EQ(r.out, "") << text;
    }
}

// The list reader takes a megabyte at a time: a line of 65536 bytes is read, one of 65537 is
// refused naming its line, first or last, with or without its newline.
TEST(EvalCost, ListLinesOfTheLongestLengthAndOneMore) {
    const auto dir = temp_dir("eval-lines");
    const std::string longest = "1" + std::string(65535, ' ');
    std::ofstream(dir / "longest.txt", std::ios::binary) << "0.5\n" << longest << "\n2";
    std::ofstream(dir / "longer.txt", std::ios::binary) << longest << " \n0.5\n";
    std::ofstream(dir / "longer-last.txt", std::ios::binary) << "0.5\n0.25\n" << longest << " ";
    const auto ok = run_cli("eval --theta0 @longest.txt --columns theta0", dir);
    EXPECT_EQ(ok.status, 0) << ok.err;
    EXPECT_EQ(ok.out, "theta0\n0.5\n1\n2\n");
    const auto first = run_cli("eval --theta0 @longer.txt --columns theta0", dir);
    EXPECT_EQ(first.status, 2);
    EXPECT_NE(first.err.find("--theta0 @longer.txt: line 1 is longer than 65536 bytes"), std::string::npos) << first.err;
    EXPECT_EQ(first.out, "");
    const auto last = run_cli("eval --theta0 - --columns theta0 <longer-last.txt", dir);
    EXPECT_EQ(last.status, 2);
    EXPECT_NE(last.err.find("--theta0 -: line 3 is longer than 65536 bytes"), std::string::npos) << last.err;
    EXPECT_EQ(last.out, "");
    std::filesystem::remove_all(dir);
}

// Standard input that never ends a line (/dev/zero) is refused after the longest line, and
// a NUL byte inside an item is named as a control character.
TEST(EvalCost, HostileListBytesAreRefused) {
    const auto zero = run_command("'" + std::string(PENDULUM_EXE) + "' eval --theta0 - </dev/zero");
    EXPECT_EQ(zero.status, 2);
    EXPECT_NE(zero.err.find("line 1 is longer than 65536 bytes"), std::string::npos) << zero.err;
    const auto dir = temp_dir("eval-nul");
    std::ofstream(dir / "nul.txt", std::ios::binary) << std::string("0.5\n1\0002\n", 8);
    const auto nul = run_cli("eval --theta0 @nul.txt", dir);
    EXPECT_EQ(nul.status, 2);
    EXPECT_NE(nul.err.find("'1\\x002' has the control character U+0000"), std::string::npos) << nul.err;
    EXPECT_EQ(nul.out, "");
    std::filesystem::remove_all(dir);
}

// Lines that straddle the reader's megabyte blocks at every offset of a 61 kB comment: every
// item is read once, in order, CRLF and a last line without its newline included.
TEST(EvalCost, LinesAcrossTheReadersBlocksAreReadWhole) {
    const auto dir = temp_dir("eval-blocks");
    std::string text;
    std::string expected = "theta0\n";
    for (int i = 1; i <= 60; ++i) {
        const std::string item = shortest(i / 32.0);
        text += item + (i % 2 ? ", " : " ,") + shortest(i / 64.0) + " #" + std::string(61000 + 977 * i % 3000, 'x');
        text += i % 3 == 0 ? "\r\n" : "\n";
        expected += item + "\n" + shortest(i / 64.0) + "\n";
    }
    text += "3.0625";  // no newline
    expected += "3.0625\n";
    ASSERT_GT(text.size(), std::size_t{3} << 20);
    std::ofstream(dir / "blocks.txt", std::ios::binary) << text;
    const auto r = run_cli("eval --theta0 @blocks.txt --columns theta0", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, expected);
    std::filesystem::remove_all(dir);
}
