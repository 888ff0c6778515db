// SPDX-License-Identifier: GPL-3.0-or-later
// The catalog's cost cuts change no number: `data ID` of every built-in, in every format,
// is byte for byte what it was before them (the SHA-256 sums below were taken with the
// program of the commit before the cuts, "tests: four empty test programs registered").
#include "process.hpp"

#include "pendulum/angle.hpp"
#include "pendulum/formulas_mp.hpp"
#include "pendulum/mp_iteration.hpp"
#include "pendulum/period_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using test_support::run_command;

struct printed {
    const char* id;      ///< the built-in
    const char* format;  ///< data's format options
    const char* sha256;  ///< the sum of its output before the cuts
};

// clang-format off
const std::vector<printed> before_the_cuts = {
    {"fig1", "-f csv --layout long", "2272b40d2868aeb4d8dff469ee91a55877b0fac9ccf79efa8032ffe18303084c"},
    {"fig1", "-f csv --layout wide", "0b00b10e87a8c3ce2501d22fc4325667451412c50b7eff23fd4f843fbaa1507f"},
    {"fig1", "-f json", "dfcda480f1683efc3b5f88aa755305b5ee73dc7c77d0d956ae23d3b0d263eaa5"},
    {"fig2", "-f csv --layout long", "f35219093996e51ae9eb0de121cfbc04e0796025803c8309cbe41e04ea9046d7"},
    {"fig2", "-f csv --layout wide", "d2ac0627000513ef2be9995ba051f71754126b72bfc2477316474c5906ee9628"},
    {"fig2", "-f json", "026c1f4696bf8f9963e6b9f9862e19df05b849a23171e53d4f92a962239c9079"},
    {"fig3", "-f csv --layout long", "64691f922adc2a85373899eb0d5fb2933d511281932c083cf4c58b8f6a4d10af"},
    {"fig3", "-f csv --layout wide", "eaa1d47a9a30340a80b3a0865cb7a490b1c2ded00e207636ef63f95b0a5384cd"},
    {"fig3", "-f json", "1544798a5490ca1f6cd46e8b32af8d55021847005ee3aea7156be5d36f875209"},
    {"fig4", "-f csv --layout long", "dfab133d8e05bfcaf6978b7011d3791d8e106f9326617c4f7c5f060fdc85f326"},
    {"fig4", "-f csv --layout wide", "36872eedff62e879b95726e9c3dc0e1c5cdde8386cc6421bbd807468d46b2b61"},
    {"fig4", "-f json", "f2e35db7ed46e77008bcc4c454a0f2022e8b62e0e641a71b1c61f67a142d4a20"},
    {"fig5", "-f csv --layout long", "cb4e80742b2452ce33764df43ee78630d56f2bda7897ebbcd6ca7535aadf74e3"},
    {"fig5", "-f csv --layout wide", "976f27e91cbefc3bf87c3e7f53fb169583214343c01956663c498820ab3c169d"},
    {"fig5", "-f json", "c091cb101e2f25472a55f4d35c644aad73c9fa3a5582dbc56d7ba5985e3cbce8"},
    {"fig6", "-f csv --layout long", "fabdb3feac7f6c04405529ebe0ea36bf451dba32f82aaff53446a7835d5f85bb"},
    {"fig6", "-f csv --layout wide", "ba65f868c6493f1a7dd48679990ad2115c95284a537e19b0c297ee411240d904"},
    {"fig6", "-f json", "486e29497db1499b2984f549856f9b525b94489c0dd57b76ab40f6bff789670e"},
    {"fig7", "-f csv --layout long", "bae66cc47b24c47007f2760b21c9b9f3210107e94984a7b695a156bca7732f88"},
    {"fig7", "-f csv --layout wide", "ea789eec19089f95b4aa4b9b36f47d7a2fa368e51351bd9b4dba79db15a2440c"},
    {"fig7", "-f json", "6c422badff231f2360cb131f732ec2dcaeb979f646b8b9836a26103fe8155b57"},
    {"convergence", "-f csv --layout long", "e96157363606a9e40793b4d30fb0dfce5b22d8c61e4b2456812a41ed615b4b98"},
    {"convergence", "-f csv --layout wide", "0af1a43d8c23667c82905ca738f14c4075e3616e8585845193426e22da4f8daa"},
    {"convergence", "-f json", "7960b4ec86be58caf2a7cbdfade8eeec1f6072329d12c3197c2c2cb10186d003"},
    {"period-formulas", "-f csv --layout long", "611d12bac58706046a161a06143ef62d79484f4a0b9d0c1d8b00861cb1f4c97e"},
    {"period-formulas", "-f csv --layout wide", "e697820b6daae317d19da268a074ce96d2178a91a8878264dbb0738c058dda53"},
    {"period-formulas", "-f json", "10021e538c37fd48d4f946be8606d51ec2e7fbb26bb0f3fae7044aa3b46ea565"},
    {"period-error", "-f csv --layout long", "6b377a0956f2a651717429ae502f85e299b0febae501b446797d5d1e6655e3be"},
    {"period-error", "-f csv --layout wide", "2ba51ccb3f5597efd2a3af13d8d8e9e14dbacc5c248328768452a4df4ea241dc"},
    {"period-error", "-f json", "19543fe6e5f8ef5eda3e104cd1d7959268518399880fc81f06040aa2671e6c96"},
    {"phase-portrait", "-f csv --layout long", "4e811a3a2719ce9c653b9bb9b3b9a24fe1e1d8a54eec5ebebce678f81d9c84b9"},
    {"phase-portrait", "-f csv --layout wide", "2ec81f6152b8c0eb67e747fa0c9ebeafdefc4f9868de80079c712520ea1f4a03"},
    {"phase-portrait", "-f json", "87798d88b8cf22604686864643863bba0d84c1529775dfca7e852aa2fad84c17"},
    {"spectrum", "-f csv --layout long", "fb8304297d7a4b6e707141f8c536cb976aa7f68b8860516633debc4fab845fe5"},
    {"spectrum", "-f csv --layout wide", "10d0fb14340961909d94939cb04e59eedf7f0812dcdd0b5dbf3d4dc3b7d2a506"},
    {"spectrum", "-f json", "1ef419329112c0dc474adb5d095a7d3fe639a89a3cceabb895453bb7d2194b64"},
    {"regimes", "-f csv --layout long", "563778863a7d74789588134daa4b8f8afde60c7a164056a918fd12a14778f96e"},
    {"regimes", "-f csv --layout wide", "4a984eb1b0216b27de8b1097fb30ebeea076c361f23a42d2dc00f19063d3bf22"},
    {"regimes", "-f json", "7560cf8399c49c1d6405a78f289df5536971dd67bc337dc71e28eb45f05d17b5"},
    {"swing", "-f csv --layout long", "cc0a5805d46a1f690d3f303283caadf95135ffdaca00897ecb7ee8ef30664eff"},
    {"swing", "-f csv --layout wide", "69a79e1b62a70f9a3b2db1e8bf62b7c6b53482db724e0d401c78595032aeba23"},
    {"swing", "-f json", "919b62fac81fb38170f7b8ab1ee69cc02ba4b35c1d7e12bfd554a9b4723ad783"},
    {"separatrix", "-f csv --layout long", "1cfe6a3712b6e0b6043990bd00104a9141f6d317b0312e9706162441180c6abb"},
    {"separatrix", "-f csv --layout wide", "aa7b7648f7b31f579bfc319b5938d2f9cdcee430830a0d9cbb159f99c782ad5c"},
    {"separatrix", "-f json", "d7d8f11988a4b3662025d41e5344f226e614b343ce7dd3a978a69ceb9234337a"},
    {"over-the-top", "-f csv --layout long", "95a71663cc793046d74c355e8865f12c1f88a36862d2d28351c119d5612881b5"},
    {"over-the-top", "-f csv --layout wide", "5a104c3b23f107d5dae1c82e3763839fcb57c5c850a7e036eee6aa8584415a42"},
    {"over-the-top", "-f json", "f9ef85ce0faadd0a51485b09f975b11a439fcb544e5e85a0ceb4cfe03108fbe1"},
};
// clang-format on

/// The SHA-256 sum of `data ID FORMAT` with `jobs` workers.
std::string data_sum(const printed& p, int jobs) {
    const auto r = run_command("'" + std::string(PENDULUM_EXE) + "' data " + p.id + " " + p.format +
                               " --jobs " + std::to_string(jobs) + " | sha256sum");
    EXPECT_EQ(r.status, 0) << p.id << " " << p.format << ": " << r.err;
    return r.out.substr(0, 64);
}

}  // namespace

// Every built-in (still and animated), every format: the numbers as before, with one
// worker and with two (the convergence figure's amplitudes on both cores).
TEST(CatalogCost, EveryBuiltinPrintsTheSameNumbersAsBeforeTheCuts) {
    ASSERT_EQ(before_the_cuts.size(), 48u);  // 16 built-ins x (long CSV, wide CSV, JSON)
    for (const auto& p : before_the_cuts) {
        EXPECT_EQ(data_sum(p, 2), p.sha256) << p.id << " " << p.format;
    }
    for (const auto& p : before_the_cuts) {
        if (std::string(p.id) == "convergence") {
            EXPECT_EQ(data_sum(p, 1), p.sha256) << p.format;
        }
    }
}

// The list above is the whole catalog: every id that `list` names has its three rows.
TEST(CatalogCost, TheSumsCoverEveryBuiltin) {
    const auto r = run_command("'" + std::string(PENDULUM_EXE) + "' list");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string figures = r.out.substr(0, r.out.find("Methods"));
    int rows = 0;
    for (const auto& p : before_the_cuts) {
        const bool named = figures.find(std::string("\n  ") + p.id + " ") != std::string::npos ||
                           figures.find(std::string("(") + p.id + ")") != std::string::npos;
        EXPECT_TRUE(named) << p.id;
        ++rows;
    }
    int ids = 0;
    for (std::size_t at = figures.find('\n'); at != std::string::npos; at = figures.find('\n', at + 1)) {
        if (figures.compare(at + 1, 2, "  ") == 0) ++ids;
    }
    EXPECT_EQ(ids * 3, rows);
}

// ---- The iteration's period errors: the first run's precision is foreseen -----------------

namespace {

using pendulum::mp::real;

/// The errors as computed before the cuts: runs at 128, 192, ... 1152 bits, each from
/// level 0, each stopping at the first level its bits cannot resolve (margin 56 bits).
std::vector<pendulum::period_error> errors_from_128_bits(const pendulum::amplitude& a, int order, double floor) {
    using kind = pendulum::period_error::kind;
    std::vector<pendulum::period_error> out(static_cast<std::size_t>(order + 1), {kind::below_limit, 0});
    std::vector<bool> done(out.size(), false);
    for (const long bits : {128L, 192L, 256L, 384L, 512L, 768L, 1152L}) {
        const auto x = pendulum::mp::exact_amplitude(a, bits);
        const real exact = 1.0 / pendulum::mp::agm(real(1.0, bits), x.kp);
        const auto error_of = [&](const real& lambda) { return 1.0 / (pendulum::mp::sqrt(lambda) * exact) - 1.0; };
        const auto resolved = [&](const real& e) { return !e.is_zero() && pendulum::mp::exponent(e) > -(bits - 56); };
        const bool more = bits != 1152 && !(std::ldexp(1.0, -static_cast<int>(bits - 56)) < floor);
        auto lambdas = pendulum::detail::mp_lambdas(x, order, bits, [&](const real& l) {
            return more && l.sign() > 0 && !resolved(error_of(l));
        });
        lambdas.resize(out.size());
        bool all = true;
        for (std::size_t n = 0; n < out.size(); ++n) {
            if (done[n]) continue;
            if (!lambdas[n]) {
                out[n] = {kind::not_computed, 0};
                all = false;
            } else if (!(lambdas[n]->sign() > 0)) {
                out[n] = {kind::no_period, 0};
                done[n] = true;
            } else if (const real e = error_of(*lambdas[n]); resolved(e)) {
                out[n] = pendulum::mp::abs(e) < 1e-300 ? pendulum::period_error{kind::below_limit, 0}
                                                        : pendulum::period_error{kind::value, e.to_double()};
                done[n] = true;
            } else {
                out[n] = {kind::below_limit, 0};
                all = false;
            }
        }
        if (all || std::ldexp(1.0, -static_cast<int>(bits - 56)) < floor) break;
    }
    return out;
}

}  // namespace

// Where the foreseen precision is right, too low (the decay slows) or too high, and where
// nothing can be foreseen (tiny amplitudes, whose errors are all below 1e-12), the errors
// are those of the runs from 128 bits, each within 2^-50 of itself (the runs round
// differently), with the same kinds; floors 1e-300, 1e-30 and 1e-16.
TEST(CatalogCost, ForeseenPrecisionChangesNoPeriodError) {
    const char* amplitudes[] = {"1e-300", "1e-8", "0.1", "0.5pi", "0.75pi", "0.9pi", "0.95pi", "0.99pi",
                                "pi - 0.0201", "pi - 0.0199", "pi - 6.995e-4", "pi - 1e-9", "pi - 1e-12"};
    for (const double floor : {1e-300, 1e-30, 1e-16}) {
        for (const char* text : amplitudes) {
            const auto a = pendulum::parse_amplitude(text);
            const auto got = pendulum::iterated_period_errors(a, 40, floor);
            const auto want = errors_from_128_bits(a, 40, floor);
            ASSERT_EQ(got.size(), want.size());
            for (std::size_t n = 0; n < got.size(); ++n) {
                EXPECT_EQ(got[n].what, want[n].what) << text << " level " << n << " floor " << floor;
                EXPECT_LE(std::fabs(got[n].value - want[n].value), std::ldexp(std::fabs(want[n].value), -50))
                    << text << " level " << n << " floor " << floor << ": " << got[n].value << " vs " << want[n].value;
            }
        }
    }
}
