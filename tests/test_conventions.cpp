// SPDX-License-Identifier: GPL-3.0-or-later
// Command-line conventions: --version, unknown options, - for standard output and input,
// @FILE lists, and files left alone when they would not change.
#include "process.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace {

namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::run_command;
using test_support::slurp;
using test_support::temp_dir;

TEST(Conventions, VersionAndUnknownOptions) {
    const auto v = run_cli("--version");
    ASSERT_EQ(v.status, 0);
    EXPECT_EQ(v.out.substr(0, v.out.find('\n')), "pendulum-figures 0.1.0");
    EXPECT_NE(v.out.find("License GPL-3.0-or-later"), std::string::npos);
    const auto bogus = run_cli("--bogus");
    EXPECT_EQ(bogus.status, 2);
    EXPECT_NE(bogus.err.find("unknown option '--bogus'"), std::string::npos) << bogus.err;
}

TEST(Conventions, DashIsStandardOutputAndInput) {
    const auto data = run_cli("data fig1 -o -");
    ASSERT_EQ(data.status, 0) << data.err;
    EXPECT_EQ(data.out, run_cli("data fig1").out);
    const auto svg = run_cli("render fig1 -f svg -o -");
    ASSERT_EQ(svg.status, 0) << svg.err;
    EXPECT_EQ(svg.out.rfind("<?xml", 0), 0u);
    EXPECT_EQ(run_cli("render fig1 fig2 -f svg -o -").status, 2);
    EXPECT_EQ(run_cli("render fig1 -f svg,pdf -o -").status, 2);
    const auto in = run_command("printf 'pi/3\\n# a comment\\npi/2, 170deg\\n' | '" + std::string(PENDULUM_EXE) +
                                "' eval --theta0 -");
    ASSERT_EQ(in.status, 0) << in.err;
    EXPECT_EQ(in.out, run_cli("eval --theta0 pi/3,pi/2,170deg").out);
}

TEST(Conventions, AmplitudesFromAFile) {
    const auto dir = temp_dir("at-file");
    std::ofstream(dir / "a.txt") << "# amplitudes\n0.5\n1, 1.5  # two more\n\n";
    const auto r = run_cli("eval --theta0 @a.txt", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, run_cli("eval --theta0 0.5,1,1.5").out);
    EXPECT_EQ(run_cli("eval --theta0 @missing.txt", dir).status, 2);
    std::ofstream(dir / "empty.txt") << "# nothing\n";
    EXPECT_EQ(run_cli("eval --theta0 @empty.txt", dir).status, 2);
    fs::remove_all(dir);
}

TEST(Conventions, UnchangedFilesAreLeftAlone) {
    const auto dir = temp_dir("unchanged");
    ASSERT_EQ(run_cli("render fig1 -f svg,png --dpi 40", dir).status, 0);
    const auto before = fs::last_write_time(dir / "c1-lowest.svg");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ASSERT_EQ(run_cli("render fig1 -f svg,png --dpi 40", dir).status, 0);
    EXPECT_EQ(fs::last_write_time(dir / "c1-lowest.svg"), before);
    ASSERT_EQ(run_cli("render fig1 -f svg,png --dpi 40 --force", dir).status, 0);
    EXPECT_NE(fs::last_write_time(dir / "c1-lowest.svg"), before);
    // A changed figure is written.
    const auto png = slurp(dir / "c1-lowest.png");
    ASSERT_EQ(run_cli("render fig1 -f png --dpi 41", dir).status, 0);
    EXPECT_NE(slurp(dir / "c1-lowest.png"), png);
    fs::remove_all(dir);
}

}  // namespace
