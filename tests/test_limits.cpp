// SPDX-License-Identifier: GPL-3.0-or-later
// Every cost a spec or the command line asks for is bounded before work starts: a spec
// beyond a limit that no real figure meets is bad input (exit 2), naming the key and the
// limit, and nothing is written.
#include "figures/render_plan.hpp"
#include "figures/spec.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using test_support::files_in;
using test_support::run_cli;
using test_support::temp_dir;

namespace {

/// One case: a spec's text (or none), the command's arguments, and what the message says.
struct limit_case {
    std::string name;
    std::string spec;  ///< written as NAME.toml in the output directory's sibling; empty for none
    std::string args;  ///< after "render" or the command; SPEC and OUT are replaced
    std::vector<std::string> says;
};

std::string repeated(const std::string& item, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += (i ? ", " : "") + item;
    return out;
}

const std::string period_panel = "[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\n";

std::vector<limit_case> cases() {
    return {
        {"trajectory-range", "[[panel]]\nplot = \"trajectory\"\ntheta0 = 1\nmethods = [\"exact\"]\nrange = [-1e6, 1e6]\n",
         "render SPEC -f png -o OUT", {"'range' spans up to 2e+06 periods", "at most 100"}},
        {"trajectory-seconds",
         "[pendulum]\nlength_m = 1e-6\n[[panel]]\nplot = \"trajectory\"\ntheta0 = 1\nmethods = [\"exact\"]\n"
         "time = \"t/s\"\nrange = [0, 10]\n",
         "render SPEC -f png -o OUT", {"'range' spans up to", "at most 100"}},
        {"plot-range", "", "plot trajectory --theta0 1 --range 0,1e6 -f png -o OUT", {"at most 100"}},
        {"amplitudes",
         "[[panel]]\nplot = \"phase\"\nmethods = [\"exact\"]\ntheta0 = [" + repeated("1", 1000) + "]\n",
         "render SPEC -f png -o OUT", {"'theta0' lists 1000 amplitudes; a panel takes at most 32"}},
        {"methods", "[[panel]]\nplot = \"period\"\nmethods = [" + repeated("\"order:200\"", 1000) + "]\n",
         "render SPEC -f png -o OUT", {"'methods' lists 1000 methods; a panel takes at most 12"}},
        {"orders", "[[panel]]\nplot = \"period\"\nmethods = [\"order:200\", \"order:150\", \"order:60\"]\n",
         "render SPEC -f png -o OUT", {"the orders of the order:N methods add up to 410", "at most 400"}},
        {"title", "[figure]\ntitle = \"" + std::string(1'000'000, 'x') + "\"\n" + period_panel,
         "render SPEC -f png -o OUT", {"'title' has 1000000 bytes; at most 1000"}},
        {"spec-size", period_panel + std::string(2'000'000, 'k') + " = 1\n", "render SPEC -f png -o OUT",
         {"has 2000051 bytes; at most 1048576"}},
        {"unknown-key", period_panel + std::string(500'000, 'k') + " = 1\n", "render SPEC -f png -o OUT",
         {"unknown key 'kkkkkkkkkk", "kkk...kkk", "kkkk' in a period panel", "keys: plot"}},
        {"frames-pixels",
         "[animation]\nfps = 25\nperiods = 80\n[[panel]]\nplot = \"pendulum\"\ntheta0 = \"170deg\"\nmethods = [\"exact\"]\n",
         "render SPEC --dpi 300 -f gif -o OUT", {"pixels; an animation has at most 2e+10"}},
        {"list-line", "", "render phase-portrait --theta0 @/dev/zero -f png -o OUT",
         {"--theta0 @/dev/zero: '/dev/zero' is not a regular file (a device, FIFO or socket)"}},
        {"list-count", "", "render phase-portrait --theta0 @LIST -f png -o OUT",
         {"--theta0: more than 32 amplitudes"}},
        {"spec-device", "", "render /dev/zero.toml -f png -o OUT", {"no such file"}},
        {"theme-directory", "", "render fig1 --theme THEMEDIR -f png -o OUT", {"is a directory"}},
    };
}

}  // namespace

TEST(Limits, EachCostIsBoundedBeforeWork) {
    const auto work = temp_dir("limits");
    // A list of 100,000 amplitudes, and a spec that is a link to /dev/zero.
    {
        std::ofstream list(work / "list.txt");
        for (int i = 0; i < 100'000; ++i) list << "1\n";
    }
    fs::create_symlink("/dev/zero", work / "zero.toml");
    fs::create_directories(work / "dir.toml");
    const auto zero = run_cli("render '" + (work / "zero.toml").string() + "' -f png -o '" + work.string() + "'");
    EXPECT_EQ(zero.status, 2) << zero.err;
    EXPECT_NE(zero.err.find("is not a regular file"), std::string::npos) << zero.err;

    for (const auto& c : cases()) {
        const auto out = work / c.name;
        fs::create_directories(out);
        std::string args = c.args;
        const auto replace = [&](const std::string& from, const std::string& to) {
            for (std::size_t at; (at = args.find(from)) != std::string::npos;) args.replace(at, from.size(), "'" + to + "'");
        };
        if (!c.spec.empty()) {
            std::ofstream(work / (c.name + ".toml")) << c.spec;
            replace("SPEC", (work / (c.name + ".toml")).string());
        }
        replace("THEMEDIR", (work / "dir.toml").string());
        replace("OUT", out.string());
        replace("@LIST", "@" + (work / "list.txt").string());
        const auto r = run_cli(args);
        EXPECT_EQ(r.status, 2) << c.name << ": " << r.err;
        for (const auto& s : c.says) EXPECT_NE(r.err.find(s), std::string::npos) << c.name << ": " << r.err;
        EXPECT_LT(r.err.size(), 2000u) << c.name << ": a message of one or two lines";
        EXPECT_TRUE(files_in(out).empty()) << c.name << ": something was written";
    }
    fs::remove_all(work);
}

TEST(Limits, TheLimitsAreWhatTheHelpSays) {
    // The numbers the messages above name, in one place.
    EXPECT_EQ(figures::max_panels, 26);
    EXPECT_EQ(figures::max_amplitudes_per_panel, 32u);
    EXPECT_EQ(figures::max_methods_per_panel, 12u);
    EXPECT_EQ(figures::max_iteration_orders_per_panel, 400);
    EXPECT_EQ(figures::max_periods_per_panel, 100);
    EXPECT_EQ(figures::max_file_name_bytes, 100u);
    EXPECT_EQ(figures::max_animation_pixels, 2e10);
}

TEST(Limits, JustInsideEveryLimitIsAccepted) {
    const auto work = temp_dir("limits-inside");
    std::ofstream(work / "inside.toml")
        << "[[panel]]\nplot = \"phase\"\nmethods = [\"exact\"]\ntheta0 = [" << repeated("1", 32) << "]\n"
        // The orders' sum at its limit; the amplitudes kept from pi, where order:200 costs
        // minutes of MPFR per curve sampled as the PNG samples it (the costs' own tests
        // take the dearest panels).
        << "[[panel]]\nplot = \"period\"\nmethods = [\"exact\", \"order:200\", \"order:200\"]\n"
        << "range = [\"1deg\", \"120deg\"]\n"
        << "[[panel]]\nplot = \"trajectory\"\ntheta0 = 1\nrange = [0, 100]\nmethods = [" << repeated("\"lowest\"", 12)
        << "]\n";
    const auto r = run_cli("data '" + (work / "inside.toml").string() + "' -o '" + (work / "inside.csv").string() + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    fs::remove_all(work);
}

// data takes --jobs as render does: 1 and 1024 accepted with the same numbers, 0 and 1025
// refused with the limit named and no file written; the option wins over the variable.
TEST(Limits, DataTakesJobsWithinTheWorkersLimit) {
    const auto one = run_cli("data convergence --jobs 1");
    ASSERT_EQ(one.status, 0) << one.err;
    const auto most = run_cli("data convergence --jobs 1024");
    ASSERT_EQ(most.status, 0) << most.err;
    EXPECT_EQ(one.out, most.out);
    const auto over_variable =
        test_support::run_command("PENDULUM_FIGURES_JOBS=0 '" + std::string(PENDULUM_EXE) + "' data convergence --jobs 2");
    EXPECT_EQ(over_variable.status, 0) << over_variable.err;
    EXPECT_EQ(over_variable.out, one.out);
    const fs::path dir = temp_dir("data-jobs");
    for (const char* bad : {"0", "1025"}) {
        const fs::path out = dir / "numbers.csv";
        const auto r = run_cli(std::string("data convergence --jobs ") + bad + " -o '" + out.string() + "'");
        EXPECT_EQ(r.status, 2) << bad;
        EXPECT_NE(r.err.find(std::string("--jobs ") + bad + ": the number of workers, 1 to 1024"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(out)) << bad;
    }
    fs::remove_all(dir);
}

namespace {

/// A list of `count` amplitudes, one a line: plain decimals and expressions (pi-0.1-Ne-9), every
/// 2000th close enough to pi that the iteration has no period at order 6 (a warning on
/// standard error), and `bad` (index, text) put in place of the value there.
fs::path amplitude_list(const fs::path& dir, std::size_t count, const std::vector<std::pair<std::size_t, std::string>>& bad) {
    const fs::path file = dir / ("amplitudes-" + std::to_string(count) + "-" + std::to_string(bad.size()) + ".txt");
    std::ofstream out(file);
    for (std::size_t i = 0; i < count; ++i) {
        std::string item = i % 2000 == 1999 ? "pi-1e-6"
                           : i % 7 == 3     ? "pi-0.1-" + std::to_string(i) + "e-9"
                                            : std::to_string(0.01 + 3.09 * static_cast<double>(i % 997) / 997.0);
        for (const auto& [at, text] : bad) {
            if (at == i) item = text;
        }
        out << item << '\n';
    }
    return file;
}

}  // namespace

// eval takes --jobs as data and render do: amplitudes are parsed and their rows computed on
// every worker, a block at a time, and written in order. Across several blocks (40000
// amplitudes: 3 blocks of parsing, 10 of rows; 4500 with the iteration to order 6, 2 blocks
// of rows), 1, 2 and 1024 workers write the same table and the same warnings after the same
// rows; 0 and 1025 are refused with the limit named.
TEST(Limits, EvalTakesJobsAndWritesInOrder) {
    const fs::path dir = temp_dir("eval-jobs");
    const std::string exe = "'" + std::string(PENDULUM_EXE) + "'";
    const fs::path list = amplitude_list(dir, 40000, {});
    const auto one = test_support::run_command(exe + " eval --theta0 @'" + list.string() + "' --jobs 1");
    ASSERT_EQ(one.status, 0) << one.err;
    EXPECT_EQ(std::count(one.out.begin(), one.out.end(), '\n'), 40001);
    const fs::path short_list = amplitude_list(dir, 4500, {});
    const std::string warned = " eval --theta0 @'" + short_list.string() + "' --order 6 --columns theta0 2>&1";
    const auto one_warned = test_support::run_command(exe + warned + " --jobs 1");
    ASSERT_EQ(one_warned.status, 0) << one_warned.out.substr(0, 400);
    EXPECT_EQ(std::count(one_warned.out.begin(), one_warned.out.end(), '\n'), 4501 + 2);  // header, rows, 2 warnings
    // Each warning follows the row of its amplitude (the 2000th, 4000th, ... value).
    const auto warning = one_warned.out.find("warning: theta0 = pi - 1e-06");
    ASSERT_NE(warning, std::string::npos);
    EXPECT_EQ(std::count(one_warned.out.begin(), one_warned.out.begin() + static_cast<std::ptrdiff_t>(warning), '\n'), 2001);
    for (const char* jobs : {"2", "1024"}) {
        const auto many = test_support::run_command(exe + " eval --theta0 @'" + list.string() + "' --jobs " + jobs);
        EXPECT_EQ(many.status, 0) << jobs;
        EXPECT_TRUE(many.out == one.out) << "--jobs " << jobs << " differs from --jobs 1";
        const auto many_warned = test_support::run_command(exe + warned + " --jobs " + jobs);
        EXPECT_TRUE(many_warned.out == one_warned.out) << "--jobs " << jobs << " differs from --jobs 1 (with warnings)";
    }
    for (const char* bad : {"0", "1025"}) {
        const auto r = run_cli(std::string("eval --theta0 1 --jobs ") + bad);
        EXPECT_EQ(r.status, 2) << bad;
        EXPECT_EQ(r.out, "") << bad;
        EXPECT_NE(r.err.find(std::string("--jobs ") + bad + ": the number of workers, 1 to 1024"), std::string::npos) << r.err;
    }
    fs::remove_all(dir);
}

// The first bad amplitude in the list is the one refused, whichever worker parses it and in
// whichever block it falls, and nothing is written: bad values in the second block of
// parsing (from the 16385th) and later, on 1 and 2 workers.
TEST(Limits, EvalRefusesTheFirstBadAmplitudeOnAnyWorker) {
    const fs::path dir = temp_dir("eval-first-bad");
    const fs::path list = amplitude_list(dir, 40000, {{20001, "4"}, {20002, "x"}, {39999, "0"}});
    for (const char* jobs : {"1", "2"}) {
        const auto r = run_cli("eval --theta0 @'" + list.string() + "' --jobs " + jobs);
        EXPECT_EQ(r.status, 2) << jobs;
        EXPECT_EQ(r.out, "") << jobs;
        EXPECT_NE(r.err.find("--theta0 '4'"), std::string::npos) << r.err;
        EXPECT_EQ(r.err.find("'x'"), std::string::npos) << r.err;
    }
    // The first block's last item and the second block's first, each alone.
    for (const std::size_t at : {std::size_t{16383}, std::size_t{16384}}) {
        const fs::path one_bad = amplitude_list(dir, 20000, {{at, "nope"}});
        const auto r = run_cli("eval --theta0 @'" + one_bad.string() + "' --jobs 2");
        EXPECT_EQ(r.status, 2) << at;
        EXPECT_NE(r.err.find("--theta0 'nope'"), std::string::npos) << r.err;
    }
    fs::remove_all(dir);
}
