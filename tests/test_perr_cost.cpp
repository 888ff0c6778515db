// SPDX-License-Identifier: GPL-3.0-or-later
// The period errors' cost cuts change no number: every output that prints a period error
// (Fig. 7, period-error, period-formulas, convergence, every built-in's data, the claims and
// eval's err: columns of every closed-form method over 1100 amplitudes) is byte for byte what
// it was before them. The SHA-256 sums below were taken with the program of the commit
// before the cuts ("tests: four empty cost test files registered").
#include "process.hpp"

#include "pendulum/formulas_mp.hpp"
#include "pendulum/mp_bessel.hpp"
#include "pendulum/approximants_mp.hpp"
#include "pendulum/formula_methods.hpp"
#include "pendulum/period_error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using test_support::run_command;

struct printed {
    std::string args;    ///< the command's arguments after the program
    const char* sha256;  ///< the sum of its standard output before the cuts
};

/// eval's err: columns of every closed-form method (and agm, series at several N).
std::string every_closed_form_error() {
    std::string cols = "theta0";
    for (const char* m : {"harmonic", "lowest", "first", "second", "polynomial", "kidd-fogg", "lima-arun", "ganley",
                          "agm:1", "agm:2", "agm:3", "agm:5", "agm:10", "denman", "series:1", "series:3", "series:8",
                          "series:20", "log-asymptote", "molina"}) {
        cols += std::string(",err:") + m;
    }
    return "eval --theta0 @'" + std::string(PENDULUM_TEST_DATA) + "/perr_amplitudes.txt' --columns " + cols;
}

/// The outputs and their sums before the cuts.
std::vector<printed> before_the_cuts() {
    // clang-format off
    return {
        {"data fig1 -f csv --layout long", "2272b40d2868aeb4d8dff469ee91a55877b0fac9ccf79efa8032ffe18303084c"},
        {"data fig2 -f csv --layout long", "f35219093996e51ae9eb0de121cfbc04e0796025803c8309cbe41e04ea9046d7"},
        {"data fig3 -f csv --layout long", "64691f922adc2a85373899eb0d5fb2933d511281932c083cf4c58b8f6a4d10af"},
        {"data fig4 -f csv --layout long", "dfab133d8e05bfcaf6978b7011d3791d8e106f9326617c4f7c5f060fdc85f326"},
        {"data fig5 -f csv --layout long", "cb4e80742b2452ce33764df43ee78630d56f2bda7897ebbcd6ca7535aadf74e3"},
        {"data fig6 -f csv --layout long", "fabdb3feac7f6c04405529ebe0ea36bf451dba32f82aaff53446a7835d5f85bb"},
        {"data fig7 -f csv --layout long", "bae66cc47b24c47007f2760b21c9b9f3210107e94984a7b695a156bca7732f88"},
        {"data convergence -f csv --layout long", "e96157363606a9e40793b4d30fb0dfce5b22d8c61e4b2456812a41ed615b4b98"},
        {"data period-formulas -f csv --layout long", "611d12bac58706046a161a06143ef62d79484f4a0b9d0c1d8b00861cb1f4c97e"},
        {"data period-error -f csv --layout long", "6b377a0956f2a651717429ae502f85e299b0febae501b446797d5d1e6655e3be"},
        {"data phase-portrait -f csv --layout long", "4e811a3a2719ce9c653b9bb9b3b9a24fe1e1d8a54eec5ebebce678f81d9c84b9"},
        {"data spectrum -f csv --layout long", "fb8304297d7a4b6e707141f8c536cb976aa7f68b8860516633debc4fab845fe5"},
        {"data regimes -f csv --layout long", "563778863a7d74789588134daa4b8f8afde60c7a164056a918fd12a14778f96e"},
        {"data swing -f csv --layout long", "cc0a5805d46a1f690d3f303283caadf95135ffdaca00897ecb7ee8ef30664eff"},
        {"data separatrix -f csv --layout long", "1cfe6a3712b6e0b6043990bd00104a9141f6d317b0312e9706162441180c6abb"},
        {"data over-the-top -f csv --layout long", "95a71663cc793046d74c355e8865f12c1f88a36862d2d28351c119d5612881b5"},
        {"data fig7 -f csv --layout wide", "ea789eec19089f95b4aa4b9b36f47d7a2fa368e51351bd9b4dba79db15a2440c"},
        {"data fig7 -f json", "6c422badff231f2360cb131f732ec2dcaeb979f646b8b9836a26103fe8155b57"},
        {"data period-error -f csv --layout wide", "2ba51ccb3f5597efd2a3af13d8d8e9e14dbacc5c248328768452a4df4ea241dc"},
        {"data period-error -f json", "19543fe6e5f8ef5eda3e104cd1d7959268518399880fc81f06040aa2671e6c96"},
        {"data convergence -f csv --layout wide", "0af1a43d8c23667c82905ca738f14c4075e3616e8585845193426e22da4f8daa"},
        {"data convergence -f json", "7960b4ec86be58caf2a7cbdfade8eeec1f6072329d12c3197c2c2cb10186d003"},
        {"claims", "1299ce1e4f1070deab6bfba5c68187daf9401935b0c6a133787c53a5dace2477"},
        {"claims --format json", "a8cb88dfdaf72075062be8c6aff2d5a0f953e9ec02a676803066c0e0d545acda"},
        {every_closed_form_error(), "2ca75fbfa1d8d907296431600f7083e5f95cd2d8d1910ca2de7d7850471aa9da"},
        {every_closed_form_error() + " --format json", "a80c030860498b0861e619c6be14d131d1331717ed783dfb0f4fb0f248fc7918"},
    };
    // clang-format on
}

/// The SHA-256 sum of the program's output with `args` (data and eval on two workers).
std::string sum_of(const std::string& args) {
    const std::string jobs = args.rfind("claims", 0) == 0 ? "" : " --jobs 2";
    const auto r = run_command("'" + std::string(PENDULUM_EXE) + "' " + args + jobs + " | sha256sum");
    EXPECT_EQ(r.status, 0) << args << ": " << r.err;
    return r.out.substr(0, 64);
}

}  // namespace

// Every output that prints a period error, byte for byte as before the cuts.
TEST(PerrCost, EveryPrintedPeriodErrorIsAsBeforeTheCuts) {
    for (const auto& p : before_the_cuts()) EXPECT_EQ(sum_of(p.args), p.sha256) << p.args;
}

// The amplitudes' file is what its script writes (its first and last lines, and its length).
TEST(PerrCost, TheAmplitudesAreTheScriptsOwn) {
    const std::string text = test_support::slurp(std::string(PENDULUM_TEST_DATA) + "/perr_amplitudes.txt");
    EXPECT_EQ(text.rfind("# written by make_perr_amplitudes.py\n1.000000e-300\n", 0), 0u);
    EXPECT_NE(text.find("\npi-1.000000e-300\n"), std::string::npos);
    EXPECT_NE(text.find("\n3.0000\n"), std::string::npos);
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1101);
}

// ---- Bessel functions in MPFR: the same numbers by less work ----------------------------

namespace {

using pendulum::mp::real;

/// x with `bits`, from a double.
real at(double x, long bits) { return real(x, bits); }

/// The arguments of the Bessel checks: a sweep of (0, 4], the smallest and largest ones,
/// and the zeros of J_0 and J_1 to the last bit of a double (where the series cannot round
/// and MPFR's own function is used).
std::vector<double> bessel_arguments() {
    std::vector<double> xs = {1e-300, 1e-30, 1e-8, 1e-4, 0.01, 2.404825557695773, 2.4048255576957724,
                              2.4048255576957732, 3.8317059702075125, 3.831705970207512, 3.9999999999999996, 4.0};
    for (int i = 1; i <= 97; ++i) xs.push_back(0.0412 * i - 1e-3 * (i % 7));
    return xs;
}

}  // namespace

// J_n correctly rounded by its series is mpfr_jn's number, bit for bit, at every precision the
// period errors use, n = 0..10, across (0, 4] and at the zeros (where it falls back).
TEST(PerrCost, RoundedBesselIsMpfrsOwn) {
    for (const long bits : {128L, 256L, 512L, 1152L}) {
        for (const double x : bessel_arguments()) {
            for (int n = 0; n <= 10; ++n) {
                const real mine = pendulum::mp::bessel_j_rounded(n, at(x, bits));
                const real theirs = pendulum::mp::bessel_j(n, at(x, bits));
                ASSERT_TRUE(mpfr_equal_p(mine.get(), theirs.get()) != 0) << "J_" << n << "(" << x << ") at " << bits;
                ASSERT_EQ(mine.precision(), bits);
            }
        }
    }
}

// Outside the series' domain (x = 0, |x| > 4, negative x) it is mpfr_jn itself.
TEST(PerrCost, RoundedBesselOutsideTheSeriesIsMpfrs) {
    for (const double x : {0.0, 4.000000000000001, 5.0, 100.0, -1.5, -4.0}) {
        for (int n = 0; n <= 4; ++n) {
            const real mine = pendulum::mp::bessel_j_rounded(n, at(x, 128));
            const real theirs = pendulum::mp::bessel_j(n, at(x, 128));
            EXPECT_TRUE(mpfr_equal_p(mine.get(), theirs.get()) != 0 || (mine.is_zero() && theirs.is_zero()))
                << "J_" << n << "(" << x << ")";
        }
    }
}

// J_n alone refuses what it cannot take: n < 0, x = 0 and |x| > 4 (its accuracy against
// mpfr_jn, every order to 40: MpBessel.EveryOrderAgainstMpfr).
TEST(PerrCost, OneBesselRefusesWhatItCannotTake) {
    EXPECT_THROW((void)pendulum::mp::bessel_j_nth(-1, at(1.0, 128)), std::invalid_argument);
    EXPECT_THROW((void)pendulum::mp::bessel_j_nth(1, at(0.0, 128)), std::domain_error);
    EXPECT_THROW((void)pendulum::mp::bessel_j_nth(1, at(4.000000000000001, 128)), std::domain_error);
    EXPECT_NO_THROW((void)pendulum::mp::bessel_j_nth(1, at(4.0, 128)));
    EXPECT_NO_THROW((void)pendulum::mp::bessel_j_nth(1, at(-4.0, 128)));
}

// ---- Closed forms' MPFR tier: the first precision is foreseen ---------------------------

namespace {

using pendulum::amplitude;
using pendulum::mp_period;
using pendulum::period_error;
using pendulum::mp::mp_amplitude;

/// A closed form's MPFR period and its N.
struct closed_form {
    const char* name;
    mp_period f;
    int n;
};

/// Every closed form of the method table (the paper's three orders by their own MPFR
/// formulas, as period_error.cpp has them).
std::vector<closed_form> closed_forms() {
    namespace f = pendulum::formulas;
    using pendulum::closed_form_period_mp;
    return {
        {"harmonic", closed_form_period_mp<f::harmonic>, 0},
        {"lowest", [](const mp_amplitude& x, int) { return 1.0 / f::lowest_frequency(x.theta); }, 0},
        {"first", [](const mp_amplitude& x, int) { return 1.0 / f::first_order_of(x.theta).frequency; }, 0},
        {"second", pendulum::detail::second_period_mp, 0},
        {"polynomial", closed_form_period_mp<f::polynomial>, 0},
        {"kidd-fogg", closed_form_period_mp<f::kidd_fogg>, 0},
        {"lima-arun", closed_form_period_mp<f::lima_arun>, 0},
        {"ganley", closed_form_period_mp<f::ganley>, 0},
        {"agm:1", closed_form_period_mp<f::agm>, 1},
        {"agm:3", closed_form_period_mp<f::agm>, 3},
        {"agm:10", closed_form_period_mp<f::agm>, 10},
        {"denman", closed_form_period_mp<f::denman>, 0},
        {"series:1", closed_form_period_mp<f::series>, 1},
        {"series:8", closed_form_period_mp<f::series>, 8},
        {"series:20", closed_form_period_mp<f::series>, 20},
        {"log-asymptote", closed_form_period_mp<f::log_asymptote>, 0},
        {"molina", closed_form_period_mp<f::molina>, 0},
    };
}

/// The precisions of the MPFR tier, in turn.
constexpr long tier_bits[] = {128, 256, 512, 1152};

/// The tier as before the cuts, written out: the index of the first precision whose error
/// is 56 bits above its rounding (4 where none is).
std::size_t resolving_precision(const amplitude& a, const closed_form& c) {
    for (std::size_t i = 0; i < 4; ++i) {
        const long bits = tier_bits[i];
        const auto x = pendulum::mp::exact_amplitude(a, bits);
        const real e = c.f(x, c.n) / (1.0 / pendulum::mp::agm(real(1.0, bits), x.kp)) - 1.0;
        if (!e.is_zero() && pendulum::mp::exponent(e) > -(bits - 56)) return i;
    }
    return 4;
}

/// The foreseen tier against the tier from 128 bits: the same kind and the same value.
void expect_same(const amplitude& a, const closed_form& c, const std::string& where) {
    const period_error foreseen = pendulum::detail::mp_closed_form_error(a, c.n, c.f);
    const period_error from_128 = pendulum::detail::mp_closed_form_error_from(a, c.n, c.f, 0);
    EXPECT_EQ(foreseen.what, from_128.what) << c.name << " at " << where;
    EXPECT_EQ(foreseen.value, from_128.value) << c.name << " at " << where;
}

/// The amplitudes on either side of a change of the resolving precision between lo < hi
/// (log-spaced bisection down to adjacent doubles).
double resolving_boundary(const closed_form& c, double lo, double hi) {
    const std::size_t at_lo = resolving_precision(lo, c);
    while (std::nextafter(lo, hi) < hi) {
        const double mid = std::sqrt(lo) * std::sqrt(hi);
        const double m = mid > lo && mid < hi ? mid : std::nextafter(lo, hi);
        (resolving_precision(m, c) == at_lo ? lo : hi) = m;
    }
    return hi;
}

}  // namespace

// The brief's sweep and tiny amplitudes down to 1e-300 (below_limit), every closed form.
TEST(PerrCost, ForeseenPrecisionGivesTheErrorsFrom128Bits) {
    const std::vector<std::pair<amplitude, std::string>> sweep = {
        {1e-300, "1e-300"}, {1e-200, "1e-200"}, {1e-150, "1e-150"}, {1e-100, "1e-100"}, {1e-70, "1e-70"},
        {1e-40, "1e-40"},   {1e-30, "1e-30"},   {1e-20, "1e-20"},   {1e-15, "1e-15"},   {1e-12, "1e-12"},
        {1e-8, "1e-8"},     {1e-4, "1e-4"},     {0.01, "0.01"},     {0.1, "0.1"},       {1.0, "1"},
        {2.0, "2"},         {3.0, "3"},         {amplitude::from_pi(1e-6), "pi - 1e-6"},
        {amplitude::from_pi(1e-15), "pi - 1e-15"}, {4.9406564584124654e-324, "the smallest double"},
    };
    for (const auto& c : closed_forms()) {
        for (const auto& [a, where] : sweep) expect_same(a, c, where);
    }
    // The sweep reaches every precision and below_limit.
    const closed_form harmonic = closed_forms().front();
    EXPECT_EQ(resolving_precision(1e-8, harmonic), 0u);    // theta0^2/16 = 6e-18
    EXPECT_EQ(resolving_precision(1e-20, harmonic), 1u);   // 6e-42
    EXPECT_EQ(resolving_precision(1e-40, harmonic), 2u);   // 6e-82
    EXPECT_EQ(resolving_precision(1e-100, harmonic), 3u);  // 6e-202
    EXPECT_EQ(resolving_precision(1e-150, harmonic), 3u);  // 6e-302: resolved, below 1e-300
    EXPECT_EQ(resolving_precision(1e-200, harmonic), 4u);  // 6e-402: not resolved at all
    EXPECT_EQ(pendulum::detail::mp_closed_form_error(1e-150, 0, harmonic.f).what, period_error::kind::below_limit);
    EXPECT_EQ(pendulum::detail::mp_closed_form_error(1e-200, 0, harmonic.f).what, period_error::kind::below_limit);
    EXPECT_EQ(pendulum::detail::mp_closed_form_error(1e-100, 0, harmonic.f).what, period_error::kind::value);
}

// Where a precision just resolves (adjacent doubles on either side, found by bisection) and
// where the foreseen start moves (theta0^2 = 2^(49 - bits)), every closed form the same.
TEST(PerrCost, ForeseenPrecisionAtTheBoundaries) {
    int boundaries = 0;
    for (const auto& c : closed_forms()) {
        double lo = 1e-300;
        for (const double hi : {1e-250, 1e-150, 1e-100, 1e-60, 1e-40, 1e-25, 1e-15, 1e-8, 0.5}) {
            if (resolving_precision(lo, c) != resolving_precision(hi, c)) {
                const double b = resolving_boundary(c, lo, hi);
                ++boundaries;
                for (const double t : {std::nextafter(b, 0.0), b, std::nextafter(b, 1.0)}) {
                    expect_same(t, c, "boundary " + std::to_string(t));
                }
            }
            lo = hi;
        }
        for (const long bits : {128L, 256L, 512L}) {
            const double t = std::ldexp(1.0, static_cast<int>(49 - bits) / 2) * std::sqrt(0.5);  // 2^((49-bits)/2)
            for (const double s : {std::nextafter(t, 0.0), t, std::nextafter(t, 1.0), t * 0.99, t * 1.01}) {
                expect_same(s, c, "foreseen start " + std::to_string(s));
            }
        }
    }
    EXPECT_GE(boundaries, 40);  // the harmonic alone has four
}

// The foreseen start: 128 bits from 2^-39.5 up, 1152 bits below 2^-231.5; one more double
// up moves it back.
TEST(PerrCost, ForeseenStartAtItsLimits) {
    using pendulum::detail::foreseen_closed_form_start;
    const double to_256 = std::ldexp(std::sqrt(0.5), -39);    // theta0^2 = 2^-79
    const double to_512 = std::ldexp(std::sqrt(0.5), -103);   // 2^-207
    const double to_1152 = std::ldexp(std::sqrt(0.5), -231);  // 2^-463
    EXPECT_EQ(foreseen_closed_form_start(1.0), 0u);
    EXPECT_EQ(foreseen_closed_form_start(amplitude::from_pi(1e-300)), 0u);
    EXPECT_EQ(foreseen_closed_form_start(std::nextafter(to_256, 1.0)), 0u);
    EXPECT_EQ(foreseen_closed_form_start(std::nextafter(to_256, 0.0)), 1u);
    EXPECT_EQ(foreseen_closed_form_start(std::nextafter(to_512, 1.0)), 1u);
    EXPECT_EQ(foreseen_closed_form_start(std::nextafter(to_512, 0.0)), 2u);
    EXPECT_EQ(foreseen_closed_form_start(std::nextafter(to_1152, 1.0)), 2u);
    EXPECT_EQ(foreseen_closed_form_start(std::nextafter(to_1152, 0.0)), 3u);
    EXPECT_EQ(foreseen_closed_form_start(1e-300), 3u);
    EXPECT_EQ(foreseen_closed_form_start(4.9406564584124654e-324), 3u);
}

// A hostile period whose error (2^-60 + 2^(20 - bits)) is far above theta0^2: 128 bits
// resolve it, and their value (2^-60 + 2^-108) is the one given, not 1152 bits' (2^-60), at
// an amplitude whose foreseen start is 1152 bits.
TEST(PerrCost, AnErrorAboveTheForesightIsComputedFrom128Bits) {
    const mp_period hostile = [](const mp_amplitude& x, int) {
        const long bits = x.theta.precision();
        const real t = 1.0 / pendulum::mp::agm(real(1.0, bits), x.kp);
        return t * (1.0 + (real(std::ldexp(1.0, -60), bits) + real(std::ldexp(1.0, static_cast<int>(20 - bits)), bits)));
    };
    const amplitude tiny = 1e-200;
    ASSERT_EQ(pendulum::detail::foreseen_closed_form_start(tiny), 3u);
    const period_error e = pendulum::detail::mp_closed_form_error(tiny, 0, hostile);
    ASSERT_EQ(e.what, period_error::kind::value);
    EXPECT_EQ(e.value, std::ldexp(1.0, -60) + std::ldexp(1.0, -108));
    EXPECT_EQ(pendulum::detail::mp_closed_form_error_from(tiny, 0, hostile, 3).value, std::ldexp(1.0, -60));
}
