// SPDX-License-Identifier: GPL-3.0-or-later
// Specs, styles and names from strangers: see the tests below.
#include "process.hpp"

#include "figures/batch.hpp"
#include "figures/catalog.hpp"
#include "figures/render_cost.hpp"
#include "figures/render_plan.hpp"
#include "figures/spec_build.hpp"
#include "figures/themes.hpp"
#include "plot/output.hpp"
#include "plot/video.hpp"
#include "plot/workers.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace test_support;

/// Writes `text` to `path`.
void write_file(const fs::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
}

/// `panels` copies of a [[panel]] table under a [figure] (and `head`, e.g. an [animation]).
std::string spec_of(int panels, const std::string& panel, const std::string& head = "") {
    std::string text = "[figure]\ntitle = \"costs\"\ncolumns = 6\n" + head + "\n";
    for (int i = 0; i < panels; ++i) text += "[[panel]]\n" + panel + "\n";
    return text;
}

/// "order:N" `count` times, for a methods list.
std::string orders(int count, int n) {
    std::string list;
    for (int i = 0; i < count; ++i) list += std::string(i ? ", " : "") + "\"order:" + std::to_string(n) + "\"";
    return "[" + list + "]";
}

/// `count` amplitudes close to pi.
std::string near_pi(int count) {
    std::string list;
    for (int i = 0; i < count; ++i) list += std::string(i ? ", " : "") + "\"pi - 1e-" + std::to_string(300 - i) + "\"";
    return "[" + list + "]";
}

/// The reproductions: specs inside every limit of a spec that ran for hours, or took 1.4 GB.
struct reproduction {
    std::string name;
    std::string spec;
    std::vector<std::string> messages;  // in the refusal
    bool built_once_too = true;         // data, which builds it once, refuses it too
};

/// What every refusal of the time a render takes says.
const std::string too_long = "of computing (estimated from the specs before any work); a render takes at most 15.0 min";

std::vector<reproduction> reproductions() {
    const std::string twelve = "[\"exact\", \"harmonic\", \"lowest\", \"first\", \"second\", \"polynomial\", "
                               "\"order:2\", \"order:3\", \"order:4\", \"order:5\", \"order:6\", \"order:7\"]";
    return {
        {"motion-order200", spec_of(26, "plot = \"trajectory\"\ntheta0 = \"pi - 1e-300\"\nmethods = " + orders(12, 200)),
         {too_long, "panel 1 (trajectory): reduce its methods (12, up to order:200) and theta0 (1, 1 close to pi)"}},
        {"convergence", spec_of(26, "plot = \"convergence\"\ntheta0 = " + near_pi(32) + "\norders = [0, 200]"),
         {too_long, "panel 1 (convergence): reduce its orders (up to 200) and theta0 (32, 32 close to pi)"}},
        {"spectrum", spec_of(26, "plot = \"spectrum\"\ntheta0 = " + near_pi(32) + "\nmethods = " + orders(12, 200)),
         {too_long, "panel 1 (spectrum): reduce its methods (12, up to order:200) and theta0 (32, 32 close to pi)"}},
        {"period-orders", spec_of(26, "plot = \"period\"\ny = \"error-log\"\nmethods = " + orders(2, 200)),
         {too_long, "panel 1 (period): reduce its methods (2, up to order:200)"}},
        {"period-400-orders", spec_of(26, "plot = \"period\"\nmethods = " + orders(2, 200)),
         {too_long, "panel 1 (period): reduce its methods (2, up to order:200)"}},
        // One frame takes minutes (each frame solves each method again), each panel alone not.
        // 301 frames of one period at 30 fps and 15 of cross-fade (order:200's period is not
        // known before it is solved, so the loop cannot be whole periods).
        {"animation", spec_of(26, "plot = \"pendulum\"\ntheta0 = [\"0.999pi\"]\nmethods = [\"order:200\"]",
                              "[animation]\nfps = 30\nperiods = 1"),
         {too_long, "panel 1 (pendulum): reduce its methods (1, up to order:200) and theta0 (1, 1 close to pi), in each "
                    "of 316 frames ([animation] fps, periods or duration_s, or --frames)"},
         false},
        {"periods", spec_of(26, "plot = \"trajectory\"\ntheta0 = \"3\"\nrange = [0, 100]\nmethods = " + twelve),
         {"the curves of figure 'periods' would take about", "a render takes at most 1024 MiB: draw fewer periods "
                                                              "(range), methods or amplitudes, or fewer panels"}},
    };
}

/// Each reproduction is refused at once (the estimate, not the work), exit 2, with the
/// panel and the key to reduce, and nothing written; as data reads it too.
TEST(CostEstimate, ReproductionsRefusedBeforeAnyWork) {
    const auto dir = temp_dir("cost-reproductions");
    for (const auto& r : reproductions()) {
        const fs::path spec = dir / (r.name + ".toml");
        write_file(spec, r.spec);
        const fs::path out = dir / ("out-" + r.name);
        fs::create_directories(out);
        std::vector<std::string> commands{"render '" + spec.string() + "' -f png,pdf -o '" + out.string() + "'"};
        if (r.built_once_too) commands.push_back("data '" + spec.string() + "'");
        for (const std::string& command : commands) {
            const auto start = std::chrono::steady_clock::now();
            const auto run = run_cli(command);
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            EXPECT_EQ(run.status, 2) << r.name << ": " << run.err;
            EXPECT_LT(seconds, 10) << r.name << ": refused only after the work";
            for (const auto& m : r.messages) EXPECT_NE(run.err.find(m), std::string::npos) << r.name << ": " << run.err;
            EXPECT_EQ(run.out, "") << r.name;
        }
        EXPECT_TRUE(files_in(out).empty()) << r.name;
    }
    fs::remove_all(dir);
}

/// A render as render_command puts it together: every figure with its files or frames.
figures::cost_estimate render_estimate(const std::vector<const figures::entry*>& chosen, const std::string& theme,
                                       const std::vector<std::string>& formats) {
    const plot::theme th = figures::load_theme(theme);
    const plot::output_options output{th.dpi};
    const figures::render_style style{th, output, th, output};
    std::vector<figures::costed_figure> costed;
    figures::build_options build = figures::sized_by({}, th);
    for (const auto* e : chosen) {
        const auto [w, h] = plot::pixel_size(figures::figure_grid(e->spec, build), th, th.dpi);
        const int frames = e->spec.animation ? figures::plan_animation(*e, {}).frames : 0;
        costed.push_back({e, frames, formats, static_cast<double>(w) * h});
    }
    return figures::estimate_cost(costed, {});
}

/// Every built-in figure and animation, in every theme and every format, and render --all,
/// is accepted with room to spare (a quarter of the bound at most).
TEST(CostEstimate, EveryBuiltinPassesWithMargin) {
    const std::vector<std::string> still_formats{"png", "pdf", "svg", "eps", "gif"};
    const std::vector<std::string> moving_formats{"gif", "pdf", "png", "mp4", "webm"};
    for (const auto& t : figures::builtin_themes()) {
        const std::string theme(t.name);
        std::vector<const figures::entry*> stills;
        for (const auto& e : figures::catalog()) {
            const auto one = render_estimate({&e}, theme, e.spec.animation ? moving_formats : still_formats);
            EXPECT_LT(one.seconds, figures::max_render_seconds / 4) << e.id << " in " << theme;
            EXPECT_LT(one.series_bytes, figures::max_render_series_bytes / 4) << e.id << " in " << theme;
            if (!e.spec.animation) stills.push_back(&e);
        }
        const auto all = render_estimate(stills, theme, still_formats);
        EXPECT_LT(all.seconds, figures::max_render_seconds / 4) << "render --all in " << theme;
    }
}

/// The bound's edge: N trajectory panels close to pi with 12 methods order:100 are accepted,
/// one more is refused with its message (the accepted one on its estimate: it would run).
TEST(CostEstimate, BoundaryPair) {
    const auto dir = temp_dir("cost-boundary");
    const std::string panel = "plot = \"trajectory\"\ntheta0 = \"pi - 1e-300\"\nmethods = " + orders(12, 100);
    const auto estimate = [&](int n) {
        write_file(dir / (std::to_string(n) + ".toml"), spec_of(n, panel));
        const auto e = figures::load((dir / (std::to_string(n) + ".toml")).string());
        return figures::estimate_cost({{&e, 0, {"svg"}, 0}}, {}).seconds;
    };
    int under = 0;
    while (under < 25 && estimate(under + 1) <= figures::max_render_seconds) ++under;
    ASSERT_GT(under, 1);
    ASSERT_LT(under, 25) << "the panel is too cheap for the bound's edge";
    const auto fits = figures::load((dir / (std::to_string(under) + ".toml")).string());
    EXPECT_NO_THROW(figures::check_cost({{&fits, 0, {"svg"}, 0}}, {}));
    const auto r = run_cli("render '" + (dir / (std::to_string(under + 1) + ".toml")).string() + "' -f svg -o '" +
                           dir.string() + "'");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(too_long), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("panel 1 (trajectory): reduce its methods (12, up to order:100) and theta0 (1, 1 close to pi)"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(files_in(dir).count(std::to_string(under + 1) + ".svg"), 0u);
    fs::remove_all(dir);
}

/// A vendored copy of the program with a module planted where the old lookup found it
/// (beside the program and in ../lib/x86_64-linux-gnu/pendulum-figures/): neither is loaded,
/// the constructor never runs, and no video is written.
TEST(VideoModule, PlantedBesideACopyIsNeverLoaded) {
    const auto dir = temp_dir("planted-module");
    const fs::path program = dir / "vendor" / "bin" / "pendulum-figures";
    fs::create_directories(program.parent_path());
    fs::copy_file(PENDULUM_EXE, program);
    const fs::path libdir = dir / "vendor" / "lib" / "x86_64-linux-gnu" / "pendulum-figures";
    fs::create_directories(libdir);
    for (const fs::path& place : {program.parent_path(), libdir}) {
        fs::copy_file(PLANTED_MODULE, place / "pendulum-figures-video.so");
    }
    const fs::path out = dir / "out";
    fs::create_directories(out);
    const fs::path marker = dir / "marker";
    const auto r = run_command("PLANTED_MARKER='" + marker.string() + "' '" + program.string() +
                               "' render swing --frames 1..2 -f mp4 -o '" + out.string() + "'");
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_FALSE(fs::exists(marker)) << "the planted module was loaded";
    EXPECT_EQ(r.err.find(dir.string()), std::string::npos) << r.err;
    EXPECT_TRUE(files_in(out).empty());
    fs::remove_all(dir);
}

/// The program's own module is found in the build directory, a copy's in the installation's.
TEST(VideoModule, PlacesFixedByTheBuild) {
    const fs::path exe = PENDULUM_EXE;
    EXPECT_EQ(plot::video_module_path(exe), exe.parent_path() / "pendulum-figures-video.so");
    const fs::path copy = plot::video_module_path("/tmp/repo/bin/pendulum-figures");
    EXPECT_TRUE(copy.is_absolute());
    EXPECT_EQ(copy.filename(), "pendulum-figures-video.so");
    EXPECT_EQ(copy.parent_path().filename(), "pendulum-figures");
    EXPECT_NE(copy.string().find("/lib"), std::string::npos) << copy;
    EXPECT_NE(copy.parent_path(), fs::path("/tmp/repo/lib/x86_64-linux-gnu/pendulum-figures"));
    EXPECT_EQ(plot::video_module_path("/usr/bin/pendulum-figures").string().rfind("/usr/lib", 0), 0u);
}

/// A module is checked before it is loaded: a regular file of root or this user, neither it
/// nor its directory writable by group or others.
TEST(VideoModule, OwnerAndModeCheckedBeforeLoading) {
    struct stat file {};
    struct stat dir {};
    file.st_mode = S_IFREG | 0644;
    file.st_uid = ::geteuid();
    dir.st_mode = S_IFDIR | 0755;
    dir.st_uid = 0;
    EXPECT_EQ(plot::module_file_problem(file, dir), "");
    struct stat bad = file;
    bad.st_mode = S_IFIFO | 0644;
    EXPECT_EQ(plot::module_file_problem(bad, dir), "it is not a regular file");
    bad = file;
    bad.st_uid = ::geteuid() + 1 == 0 ? 2 : ::geteuid() + 1;
    EXPECT_EQ(plot::module_file_problem(bad, dir), "it is owned by another user");
    for (const mode_t w : {S_IWGRP, S_IWOTH}) {
        bad = file;
        bad.st_mode |= w;
        EXPECT_EQ(plot::module_file_problem(bad, dir), "others may write it");
        struct stat open_dir = dir;
        open_dir.st_mode |= w;
        EXPECT_EQ(plot::module_file_problem(file, open_dir), "others may write its directory");
    }
    struct stat foreign_dir = dir;
    foreign_dir.st_uid = ::geteuid() + 1 == 0 ? 2 : ::geteuid() + 1;
    EXPECT_EQ(plot::module_file_problem(file, foreign_dir), "its directory is owned by another user");
}

}  // namespace
