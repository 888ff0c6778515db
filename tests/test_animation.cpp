// SPDX-License-Identifier: GPL-3.0-or-later
// Animations: the frame plan, GIF, PDF pages and PNG sequences, one frame with --at, a
// Beamer document that plays the PDF, and bad input.
#include "figures/animation.hpp"
#include "figures/catalog.hpp"
#include "pendulum/exact.hpp"
#include "plot/workers.hpp"
#include "process.hpp"

#include <gif_lib.h>
#include <sched.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <string>

namespace {

namespace fs = std::filesystem;
using test_support::files_in;
using test_support::run_cli;
using test_support::run_command;
using test_support::slurp;
using test_support::temp_dir;

/// Frames, size, loop and total delay of a GIF, decoded with giflib.
struct gif_facts {
    int frames = 0;
    int width = 0;
    int height = 0;
    int total_delay = 0;  // hundredths of a second
    bool loops = false;
};

gif_facts read_gif(const std::string& bytes) {
    struct source {
        const std::string* data;
        std::size_t pos = 0;
    } src{&bytes};
    int error = 0;
    GifFileType* gif = DGifOpen(&src, [](GifFileType* g, GifByteType* buf, int n) {
        auto* s = static_cast<source*>(g->UserData);
        n = std::min<int>(n, static_cast<int>(s->data->size() - s->pos));
        std::memcpy(buf, s->data->data() + s->pos, static_cast<std::size_t>(n));
        s->pos += static_cast<std::size_t>(n);
        return n;
    }, &error);
    gif_facts f;
    if (!gif) return f;
    if (DGifSlurp(gif) == GIF_OK) {
        f.frames = gif->ImageCount;
        f.width = gif->SWidth;
        f.height = gif->SHeight;
        for (int i = 0; i < gif->ImageCount; ++i) {
            GraphicsControlBlock gcb;
            if (DGifSavedExtensionToGCB(gif, i, &gcb) == GIF_OK) f.total_delay += gcb.DelayTime;
        }
    }
    DGifCloseFile(gif, &error);
    f.loops = bytes.find("NETSCAPE2.0") != std::string::npos;
    return f;
}

TEST(Animation, FramesOfTheSwing) {
    const auto& swing = figures::find("swing");
    ASSERT_TRUE(swing.spec.animation);
    const auto plan = figures::plan_animation(swing, {});
    // Three exact periods of a 1 m pendulum at 170 degrees, 30 frames per second.
    const double period_s = 2 * std::numbers::pi * std::sqrt(1.0 / 9.80665) *
                            pendulum::period_ratio(170 * std::numbers::pi / 180);
    EXPECT_EQ(plan.frames, static_cast<int>(std::floor(3 * period_s * 30)) + 1);
    EXPECT_NEAR(plan.time(plan.frames - 1), 3 * plan.reference_period, plan.step);
    EXPECT_NEAR(plan.step * plan.seconds_per_unit, 1.0 / 30, 1e-15);
    // The separatrix has no [pendulum]: a 1 m pendulum's time.
    EXPECT_NEAR(figures::plan_animation(figures::find("separatrix"), {}).seconds_per_unit,
                std::sqrt(1.0 / 9.80665), 1e-15);
}

TEST(Animation, GifPdfAndPngSequence) {
    const auto dir = temp_dir("animation");
    auto r = run_cli("render swing --theme slides -f gif,pdf,png --frames 2..13 --dpi 16 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    std::set<std::string> expected = {"swing.gif", "swing.pdf"};
    for (int i = 2; i <= 13; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "swing-%04d.png", i);
        expected.insert(name);
    }
    EXPECT_EQ(files_in(dir), expected);
    const std::string gif = slurp(dir / "swing.gif");
    const auto facts = read_gif(gif);
    EXPECT_EQ(facts.frames, 12);
    EXPECT_EQ(facts.width, 160);  // 25.4 cm at 16 dpi
    EXPECT_EQ(facts.height, 90);
    EXPECT_TRUE(facts.loops);
    // 30 frames per second: delays that add up to the true 0.4 s.
    EXPECT_EQ(facts.total_delay, 40);
    const auto pages = run_command("pdfinfo '" + (dir / "swing.pdf").string() + "'");
    EXPECT_NE(pages.out.find("Pages:           12"), std::string::npos) << pages.out;
    // The same frames again: the same bytes.
    r = run_cli("render swing --theme slides -f gif --frames 2..13 --dpi 16 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir / "swing.gif"), gif);
    fs::remove_all(dir);
}

TEST(Animation, OneFrameAt) {
    const auto dir = temp_dir("animation-at");
    const auto r = run_cli("render swing --at 0.25 -f svg,png,pdf --dpi 20 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"swing.svg", "swing.png", "swing.pdf"}));
    // The clock shows the time asked for: a quarter of the exact period of the spec's 1 m
    // pendulum released at 170 degrees, in seconds, and no other time.
    const double period_s = 2 * std::numbers::pi * std::sqrt(1.0 / 9.80665) *
                            pendulum::period_ratio(170 * std::numbers::pi / 180);
    char clock[32];
    std::snprintf(clock, sizeof clock, "t = %.2f s", 0.25 * period_s);
    const auto text = run_command("pdftotext '" + (dir / "swing.pdf").string() + "' -");
    ASSERT_EQ(text.status, 0) << "pdftotext (poppler-utils): " << text.err;
    EXPECT_NE(text.out.find(clock), std::string::npos) << "no '" << clock << "' in:\n" << text.out;
    EXPECT_EQ(text.out.find("t = "), text.out.rfind("t = ")) << text.out;
    fs::remove_all(dir);
}

TEST(Animation, BeamerPlaysThePdf) {
    if (run_command("kpsewhich animate.sty beamer.cls").out.find("animate.sty") == std::string::npos) {
        GTEST_SKIP() << "animate.sty (texlive-latex-extra) is not installed";
    }
    const auto dir = temp_dir("beamer");
    auto r = run_cli("render separatrix -f pdf --frames 1..6 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    std::ofstream(dir / "talk.tex") << "\\documentclass{beamer}\n\\usepackage{animate}\n\\begin{document}\n"
                                       "\\begin{frame}\n\\animategraphics[loop,autoplay,width=\\linewidth]{30}{separatrix}{}{}\n"
                                       "\\end{frame}\n\\end{document}\n";
    r = run_command("cd '" + dir.string() + "' && pdflatex -interaction=nonstopmode -halt-on-error talk.tex");
    EXPECT_EQ(r.status, 0) << r.out.substr(r.out.size() > 2000 ? r.out.size() - 2000 : 0);
    EXPECT_TRUE(fs::exists(dir / "talk.pdf"));
    fs::remove_all(dir);
}

TEST(Animation, SameBytesForAnyNumberOfJobs) {
    // The GIF is encoded in parts, as many as the workers keep busy: the parts join into the
    // bytes of one encoder whatever their number. So do the PNG frames and still figures.
    std::map<std::string, std::string> first;
    for (const std::string jobs : {"--jobs 1", "--jobs 2", "--jobs 7", "", "--jobs 3"}) {
        const auto dir = temp_dir("animation-jobs");
        const std::string env = jobs.empty() ? "PENDULUM_FIGURES_JOBS=2 " : "";
        auto r = run_command("cd '" + dir.string() + "' && " + env + "'" + PENDULUM_EXE + "' render swing --theme slides " +
                             "-f gif,png --frames 3..40 --dpi 16 " + jobs + " && '" + PENDULUM_EXE +
                             "' render fig7 fig2 -f png,pdf --dpi 30 " + jobs);
        ASSERT_EQ(r.status, 0) << jobs << ": " << r.err;
        std::map<std::string, std::string> files;
        for (const auto& name : files_in(dir)) files[name] = slurp(dir / name);
        EXPECT_EQ(files.size(), 38u + 1 + 4) << jobs;
        if (first.empty()) {
            first = files;
        } else {
            EXPECT_TRUE(files == first) << jobs << " wrote other bytes than --jobs 1";
        }
        fs::remove_all(dir);
    }
    EXPECT_EQ(read_gif(first["swing.gif"]).frames, 38);
    for (const std::string bad : {"--jobs 0", "--jobs 1025", "--jobs x"}) {
        const auto r = run_cli("render swing -f gif --frames 1..2 --dpi 16 -o /nonexistent " + bad);
        EXPECT_EQ(r.status, 2) << bad;
        EXPECT_NE(r.err.find("--jobs"), std::string::npos) << r.err;
    }
    const auto r = run_command("PENDULUM_FIGURES_JOBS=two '" + std::string(PENDULUM_EXE) + "' plot period --methods exact -o /tmp");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("PENDULUM_FIGURES_JOBS='two': the number of workers"), std::string::npos) << r.err;
}

TEST(Workers, OnePerCpuOfTheAffinityMask) {
    // What taskset -c 0 does to the program: only CPU 0 is allowed, so one worker.
    cpu_set_t saved;
    ASSERT_EQ(sched_getaffinity(0, sizeof saved, &saved), 0);
    EXPECT_EQ(plot::usable_cpus(), static_cast<unsigned>(CPU_COUNT(&saved)));
    cpu_set_t one;
    CPU_ZERO(&one);
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
        if (CPU_ISSET(cpu, &saved)) {
            CPU_SET(cpu, &one);
            break;
        }
    }
    ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
    const unsigned narrowed = plot::usable_cpus();
    const unsigned workers = plot::worker_count(0, 100);
    ASSERT_EQ(sched_setaffinity(0, sizeof saved, &saved), 0);
    EXPECT_EQ(narrowed, 1u);
    EXPECT_EQ(workers, 1u);
    // --jobs wins over the mask, and there are never more workers than tasks.
    EXPECT_EQ(plot::worker_count(5, 100), 5u);
    EXPECT_EQ(plot::worker_count(5, 3), 3u);
    EXPECT_EQ(plot::worker_count(0, 0), 1u);
}

TEST(Animation, BadInputIsExit2AndWritesNothing) {
    const auto dir = temp_dir("animation-bad");
    const auto spec = [&](const std::string& animation, const std::string& panel) {
        std::ofstream(dir / "a.toml") << "[animation]\n" << animation << "\n[[panel]]\n" << panel << "\n";
    };
    const std::string pendulum = "plot = \"pendulum\"\ntheta0 = \"1\"\nmethods = [\"exact\"]";
    const std::pair<std::string, std::string> cases[] = {
        {"fps = 0", "'fps' = 0 is out of range; allowed from 1 to 120"},
        {"fps = 121", "'fps' = 121 is out of range"},
        {"periods = 0", "'periods' = 0 is out of range; allowed above 0"},
        {"periods = -1", "'periods' = -1 is out of range"},
        {"duration_s = 3", "duration_s needs a [pendulum] table"},
        {"periods = 1000", "would have"},
        {"periods = 1\nduration_s = 3", "takes periods or duration_s, not both"},
    };
    for (const auto& [animation, why] : cases) {
        spec(animation, pendulum);
        const auto r = run_cli("render a.toml -f gif", dir);
        EXPECT_EQ(r.status, 2) << animation;
        EXPECT_NE(r.err.find(why), std::string::npos) << animation << ": " << r.err;
        EXPECT_EQ(files_in(dir), (std::set<std::string>{"a.toml"})) << animation;
    }
    spec("periods = 1", "plot = \"pendulum\"\nmethods = [\"exact\"]");
    auto r = run_cli("render a.toml -f gif", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("a pendulum panel needs theta0"), std::string::npos) << r.err;
    for (const char* frames : {"0..5", "5..3", "1..100000", "x"}) {
        r = run_cli(std::string("render swing -f gif --frames ") + frames, dir);
        EXPECT_EQ(r.status, 2) << frames;
        EXPECT_NE(r.err.find("--frames"), std::string::npos) << r.err;
    }
    r = run_cli("render fig1 --frames 1..3", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("apply to animations"), std::string::npos) << r.err;
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"a.toml"}));
    fs::remove_all(dir);
}

}  // namespace
