// SPDX-License-Identifier: GPL-3.0-or-later
// The build as a documentation project and a new user meet it: the CMake package from the
// build tree without installing, renders that keep to the build's job count, make's package
// lists (the runtime list suffices for the program; make builds no tests).

#include "process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using test_support::run_command;
using test_support::slurp;
using test_support::temp_dir;

/// The build directory: the program's.
fs::path build_dir() { return fs::path(PENDULUM_EXE).parent_path(); }

/// The source directory: the test data's grandparent.
fs::path source_dir() { return fs::path(PENDULUM_TEST_DATA).parent_path().parent_path(); }

void write(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
}

/// text with every run of white space one space (CMake wraps its messages).
std::string one_line(const std::string& text) {
    std::string out;
    for (const char c : text) {
        const bool space = c == ' ' || c == '\n';
        if (!space || (!out.empty() && out.back() != ' ')) out += space ? ' ' : c;
    }
    return out;
}

/// A documentation project using the build tree's package, configured with Ninja.
test_support::run_result configure(const fs::path& dir, const std::string& extra = "") {
    return run_command("cmake -S '" + (dir / "src").string() + "' -B '" + (dir / "b").string() + "' -G Ninja -Dpendulum_DIR='" +
                       build_dir().string() + "' " + extra);
}

const char* const small_spec = "[[panel]]\nplot = \"period\"\nmethods = [\"exact\", \"lowest\"]\n";

TEST(BuildTree, PackageWithoutInstalling) {
    const auto dir = temp_dir("build-tree-package");
    write(dir / "src/CMakeLists.txt",
          "cmake_minimum_required(VERSION 3.20)\nproject(docs CXX)\nfind_package(pendulum REQUIRED)\n"
          "pendulum_add_figures(TARGET figures ALL SPECS specs/a.toml c1-lowest FORMATS svg pdf)\n"
          "add_executable(probe probe.cpp)\ntarget_link_libraries(probe PRIVATE pendulum::core)\n");
    write(dir / "src/specs/a.toml", small_spec);
    write(dir / "src/probe.cpp",
          "#include <pendulum/exact.hpp>\n#include <cstdio>\nint main() { std::printf(\"%.6f\\n\", pendulum::agm(1.0, 1.0)); }\n");
    const auto conf = configure(dir);
    ASSERT_EQ(conf.status, 0) << conf.out << conf.err;
    // The build tree's program, not one installed or on PATH.
    EXPECT_NE(slurp(dir / "b/CMakeCache.txt").find("PENDULUM_FIGURES_EXECUTABLE:FILEPATH=" + fs::canonical(PENDULUM_EXE).string()),
              std::string::npos);
    const auto built = run_command("cmake --build '" + (dir / "b").string() + "'");
    ASSERT_EQ(built.status, 0) << built.out << built.err;
    for (const char* f : {"a.svg", "a.pdf", "c1-lowest.svg", "c1-lowest.pdf"}) {
        EXPECT_GT(fs::file_size(dir / "b/figures" / f), 100u) << f;
    }
    const auto probe = run_command("'" + (dir / "b/probe").string() + "'");
    EXPECT_EQ(probe.status, 0);
    EXPECT_EQ(probe.out, "1.000000\n");
    fs::remove_all(dir);
}

/// The largest sums of a log of "+ N" / "- N" lines: {workers at once, renders at once, renders}.
struct peaks {
    int workers = 0;
    int renders = 0;
    int started = 0;
};

peaks read_events(const fs::path& log) {
    std::istringstream in(slurp(log));
    peaks most;
    int workers = 0;
    int renders = 0;
    std::string sign;
    int n = 0;
    while (in >> sign >> n) {
        const int step = sign == "+" ? 1 : -1;
        workers += step * n;
        renders += step;
        most.started += sign == "+";
        most.workers = std::max(most.workers, workers);
        most.renders = std::max(most.renders, renders);
    }
    return most;
}

TEST(BuildTree, ParallelNinjaRendersKeepToTheJobCount) {
    const auto dir = temp_dir("build-tree-jobs");
    // The program behind a wrapper that logs each render's workers: --jobs N, or without it
    // the render's own default, one per CPU.
    write(dir / "wrapper",
          "#!/bin/bash\nworkers=$(nproc); prev=\nfor a in \"$@\"; do [ \"$prev\" = --jobs ] && workers=$a; prev=$a; done\n"
          "log='" + (dir / "events").string() + "'\nexec 9>>\"$log.lock\"\n"
          "flock 9; echo \"+ $workers\" >>\"$log\"; flock -u 9\nsleep 0.2\n'" + std::string(PENDULUM_EXE) +
          "' \"$@\"; status=$?\nflock 9; echo \"- $workers\" >>\"$log\"; flock -u 9\nexit $status\n");
    fs::permissions(dir / "wrapper", fs::perms::owner_all);
    std::string specs;
    for (int i = 1; i <= 20; ++i) {
        const std::string name = "specs/s" + std::to_string(i) + ".toml";
        write(dir / "src" / name, small_spec);
        specs += " " + name;
    }
    write(dir / "src/CMakeLists.txt", "cmake_minimum_required(VERSION 3.20)\nproject(docs NONE)\nfind_package(pendulum REQUIRED)\n"
                                      "pendulum_add_figures(TARGET figures ALL SPECS" + specs + " FORMATS svg png pdf)\n");
    const auto conf = configure(dir, "-DPENDULUM_FIGURES_EXECUTABLE='" + (dir / "wrapper").string() + "'");
    ASSERT_EQ(conf.status, 0) << conf.out << conf.err;
    const auto built = run_command("cmake --build '" + (dir / "b").string() + "' -j 2");
    ASSERT_EQ(built.status, 0) << built.out << built.err;
    const peaks most = read_events(dir / "events");
    EXPECT_EQ(most.started, 20);
    EXPECT_EQ(most.renders, 2) << "the build ran its renders one at a time: nothing was measured";
    EXPECT_LE(most.workers, 2) << "more workers than the build's 2 jobs";
    fs::remove_all(dir);
}

TEST(BuildTree, JobsOfEachRenderAreOneOrMore) {
    const auto dir = temp_dir("build-tree-jobs-arg");
    write(dir / "src/specs/a.toml", small_spec);
    const auto with = [&](const std::string& args) {
        write(dir / "src/CMakeLists.txt", "cmake_minimum_required(VERSION 3.20)\nproject(docs NONE)\nfind_package(pendulum REQUIRED)\n"
                                          "pendulum_add_figures(TARGET figures SPECS specs/a.toml " + args + ")\n");
        fs::remove_all(dir / "b");
        return configure(dir);
    };
    EXPECT_EQ(with("JOBS 1").status, 0);
    EXPECT_NE(slurp(dir / "b/build.ninja").find("--jobs 1"), std::string::npos);
    EXPECT_EQ(with("JOBS 3").status, 0);
    EXPECT_NE(slurp(dir / "b/build.ninja").find("--jobs 3"), std::string::npos);
    const auto zero = with("JOBS 0");
    EXPECT_NE(zero.status, 0);
    EXPECT_NE(one_line(zero.err).find("JOBS 0: the number of workers of each render, 1 or more"), std::string::npos) << zero.err;
    const auto option = with("OPTIONS --jobs 4");
    EXPECT_NE(option.status, 0);
    EXPECT_NE(one_line(option.err).find("OPTIONS --jobs: give the workers of each render as JOBS n"), std::string::npos) << option.err;
    fs::remove_all(dir);
}

TEST(BuildTree, RuntimePackageListSuffices) {
    const auto r = run_command("/usr/bin/python3 '" + (source_dir() / "tests/runtime_packages.py").string() + "' '" +
                               source_dir().string() + "' '" + PENDULUM_EXE + "' '" +
                               (build_dir() / "pendulum-figures-video.so").string() + "'");
    EXPECT_EQ(r.status, 0) << r.out << r.err;
}

/// What make would run for a target (make -n), in the source directory.
std::string make_plan(const std::string& target) {
    return run_command("make -n -C '" + source_dir().string() + "' BUILD='" + build_dir().string() + "' " + target).out;
}

TEST(BuildTree, MakeInstallsAndBuildsOnlyTheProgram) {
    for (const char* target : {"build", "install", "figures"}) {
        const std::string plan = make_plan(target);
        EXPECT_NE(plan.find("libcairo2-dev"), std::string::npos) << target;
        for (const char* test_only : {"libgtest-dev", "chromium", "texlive-latex-base", "lintian", "clang", "valgrind"}) {
            EXPECT_EQ(plan.find(test_only), std::string::npos) << target << " installs " << test_only;
        }
        EXPECT_EQ(plan.find("PENDULUM_BUILD_TESTS=ON"), std::string::npos) << target;
        EXPECT_NE(plan.find("--target pendulum-figures pendulum_core"), std::string::npos) << target;
    }
    const std::string test = make_plan("test");
    EXPECT_NE(test.find("libgtest-dev"), std::string::npos);
    EXPECT_NE(test.find("chromium"), std::string::npos);
    EXPECT_NE(test.find("-DPENDULUM_BUILD_TESTS=ON"), std::string::npos);
}

}  // namespace
