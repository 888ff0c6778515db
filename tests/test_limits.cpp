// SPDX-License-Identifier: GPL-3.0-or-later
// Every cost a spec or the command line asks for is bounded before work starts: a spec
// beyond a limit that no real figure meets is bad input (exit 2), naming the key and the
// limit, and nothing is written.
#include "figures/render_plan.hpp"
#include "figures/spec.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

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
