// SPDX-License-Identifier: GPL-3.0-or-later
// What makes video fast and small in memory, checked for what it must keep: frames drawn
// over the still part drawn once look like frames drawn whole; the MP4's frames look like
// the drawn ones to ffmpeg's SSIM; peak memory does not grow with the length; the swing GIF
// stays within its size promise. Timing is measured in bench/compare.sh, never here.

#include "figures/animation.hpp"
#include "figures/build_options.hpp"
#include "figures/catalog.hpp"
#include "figures/themes.hpp"
#include "plot/errors.hpp"
#include "plot/frames.hpp"
#include "plot/video.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using namespace test_support;

namespace {

/// How far two drawings of one frame are apart: the RGB RMS (0..255) and the share of
/// pixels that differ by more than 8 in a channel.
struct difference {
    double rms = 0;
    double share = 0;
};

difference compare(const plot::argb_image& a, const plot::argb_image& b) {
    double sum = 0;
    long long differing = 0;
    const long long pixels = static_cast<long long>(a.width) * a.height;
    for (int y = 0; y < a.height; ++y) {
        const unsigned char* p = a.data.data() + static_cast<std::size_t>(y) * a.stride;
        const unsigned char* q = b.data.data() + static_cast<std::size_t>(y) * b.stride;
        for (int x = 0; x < a.width; ++x) {
            int worst = 0;
            for (int c = 0; c < 3; ++c) {
                const int d = p[4 * x + c] - q[4 * x + c];
                sum += d * d;
                worst = std::max(worst, std::abs(d));
            }
            differing += worst > 8 ? 1 : 0;
        }
    }
    return {std::sqrt(sum / (3.0 * static_cast<double>(pixels))), static_cast<double>(differing) / pixels};
}

/// The tolerance of a composited frame against the frame drawn whole: the moving parts are
/// drawn over the still ones where a whole drawing interleaves them by series, so a pixel
/// where a moving line crosses a still one may take the other's colour (measured at most RMS
/// 0.85 and 0.013 % of pixels, in over-the-top and swing in the slides themes).
constexpr double composite_rms = 1.5;
constexpr double composite_share = 0.001;

}  // namespace

TEST(VideoSpeed, CompositedFramesLookLikeFramesDrawnWhole) {
    int checked = 0;
    for (const auto& e : figures::catalog()) {
        if (!e.spec.animation) continue;
        for (const auto& theme_row : figures::builtin_themes()) {
            const plot::theme theme = figures::load_theme(std::string(theme_row.name));
            figures::build_options options = figures::sized_by({}, theme);
            options.animated = true;
            const auto plan = figures::plan_animation(e, options);
            const plot::figure base = figures::build(e, options);
            const double dpi = 100;
            // As the writers do: the still part of the first frame, drawn once.
            const plot::figure first = figures::planned_frame(e, options, plan, base, 0);
            const plot::argb_image still = plot::render_argb(first, theme, dpi, plot::draw_pass::still);
            for (const int i : {0, plan.frames / 3, plan.frames / 2, plan.frames - 1}) {
                const plot::figure f = figures::planned_frame(e, options, plan, base, i);
                const plot::argb_image whole = plot::render_argb(f, theme, dpi);
                const plot::argb_image composited = plot::render_argb(f, theme, dpi, plot::draw_pass::overlay, &still);
                ASSERT_EQ(whole.data.size(), composited.data.size());
                const difference d = compare(whole, composited);
                EXPECT_LE(d.rms, composite_rms) << e.id << " in " << theme_row.name << ", frame " << i;
                EXPECT_LE(d.share, composite_share) << e.id << " in " << theme_row.name << ", frame " << i;
                std::printf("%s %s frame %d: RMS %.3f, %.4f %% of pixels differ by more than 8\n", e.id.c_str(),
                            std::string(theme_row.name).c_str(), i, d.rms, 100 * d.share);
                ++checked;
            }
        }
    }
    EXPECT_GE(checked, 3 * 3 * 4);
}

namespace {

/// ffmpeg's SSIM (All) of a video against PNG frames, both compared in RGB (the video's
/// BT.709 limited range converted back as the file says).
double ssim_against_pngs(const std::filesystem::path& video, const std::string& png_pattern) {
    const auto r = run_command("ffmpeg -nostdin -v info -i '" + video.string() + "' -i '" + png_pattern +
                               "' -lavfi '[0:v]scale=in_color_matrix=bt709:in_range=limited,format=gbrp[a];"
                               "[1:v]format=gbrp[b];[a][b]ssim' -f null - 2>&1");
    const std::size_t at = r.out.rfind("All:");
    if (r.status != 0 || at == std::string::npos) {
        ADD_FAILURE() << "ffmpeg: " << r.out << r.err;
        return 0;
    }
    return std::atof(r.out.c_str() + at + 4);
}

/// Peak memory (max RSS, bytes) of the program run with `args`, by /usr/bin/time.
double peak_memory(const std::string& args, const std::filesystem::path& dir) {
    const auto rss = dir / "rss";
    const auto r = run_command("/usr/bin/time -f %M -o '" + rss.string() + "' '" + std::string(PENDULUM_EXE) + "' " +
                               args);
    EXPECT_EQ(r.status, 0) << r.err;
    return 1024.0 * std::atof(slurp(rss).c_str());
}

}  // namespace

// The quality accepted for speed: SSIM >= 0.98 against the drawn frames, computed by ffmpeg
// (x264's ultrafast preset with CABAC and the 8x8 transform measures 0.992 on the swing in slides and
// 0.998 in paper; a projector shows no difference).
TEST(VideoSpeed, Mp4FramesLookLikeTheDrawnFramesToFfmpeg) {
    const auto dir = temp_dir("video-speed-ssim");
    for (const char* theme : {"slides", "paper"}) {
        const std::string common = std::string("render swing --theme ") + theme + " --frames 1..40 --dpi 96 -o '" +
                                   dir.string() + "' --force";
        ASSERT_EQ(run_cli(common + " -f mp4").status, 0);
        ASSERT_EQ(run_cli(common + " -f png").status, 0);
        const double ssim = ssim_against_pngs(dir / "swing.mp4", (dir / "swing-%04d.png").string());
        std::printf("swing.mp4 in %s: SSIM %.5f against the PNG frames\n", theme, ssim);
        EXPECT_GE(ssim, 0.98) << theme;
    }
    std::filesystem::remove_all(dir);
}

// Memory does not grow with the length: a 1080p MP4 of 300 frames peaks within 8 MB of one
// of 25, and under the 200 MB promised for a 30-s 1080p video.
TEST(VideoSpeed, Mp4PeakMemoryDoesNotGrowWithTheLength) {
    const auto dir = temp_dir("video-speed-memory");
    const std::string common = "plot pendulum --theta0 1,2.5 --methods exact --apart --length 1 --size 1920x1080 -f mp4 -o '" +
                               dir.string() + "' --duration ";
    const double short_peak = peak_memory(common + "1", dir);
    std::filesystem::remove(dir / "pendulum.mp4");
    const double long_peak = peak_memory(common + "12", dir);
    std::printf("1080p MP4 peak memory: %.1f MB for 1 s, %.1f MB for 12 s\n", short_peak / 1e6, long_peak / 1e6);
    EXPECT_LE(long_peak, short_peak + 8e6);
    EXPECT_LE(long_peak, 200e6);
    std::filesystem::remove_all(dir);
}

// The swing GIF at 720p stays within 50 MB for 30 periods (3684 frames; 38.0 MB measured,
// about 45 s of CPU). A part of it does not tell: its first periods take more bytes a frame than
// the rest (381 frames, 5.09 MB).
TEST(VideoSpeed, SwingGifOf30PeriodsStaysWithin50MB) {
    const auto dir = temp_dir("video-speed-gif");
    std::string spec = slurp(std::filesystem::path(PENDULUM_TEST_DATA) / "../../src/figures/specs/swing.toml");
    const std::size_t at = spec.find("\nperiods = 3\n");
    ASSERT_NE(at, std::string::npos);
    spec.replace(at, 13, "\nperiods = 30\n");
    std::ofstream(dir / "swing30.toml") << spec;
    const auto r = run_cli("render swing30.toml --theme slides -f gif -o .", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const double bytes = static_cast<double>(std::filesystem::file_size(dir / "swing30.gif"));
    std::printf("swing30.gif, 30 periods at 1280x720: %.2f MB\n", bytes / 1e6);
    EXPECT_LE(bytes, 50e6);
    std::filesystem::remove_all(dir);
}

namespace {

/// The message check_video_memory throws for a video of side x side pixels, or "" if it fits.
std::string refusal(const plot::video_kind& kind, int side) {
    try {
        plot::check_video_memory(kind, side, side);
    } catch (const plot::bad_input& e) {
        return e.what();
    }
    return "";
}

}  // namespace

// Memory bounded before work: the largest square video each encoder may write is accepted,
// one pixel more a side refused with the size and what to lower.
TEST(VideoSpeed, VideoMemoryBoundAcceptsNAndRefusesNPlusOne) {
    for (const plot::video_kind* kind : {&plot::mp4_video, &plot::webm_video}) {
        int low = 16;     // fits
        int high = 65536; // does not
        ASSERT_EQ(refusal(*kind, low), "");
        ASSERT_NE(refusal(*kind, high), "");
        while (high - low > 1) {
            const int mid = low + (high - low) / 2;
            (refusal(*kind, mid).empty() ? low : high) = mid;
        }
        std::printf("%s: at most %d x %d pixels\n", kind->container, low, low);
        EXPECT_EQ(refusal(*kind, low), "") << kind->container;
        const std::string message = refusal(*kind, low + 1);
        const std::string side = std::to_string(low + 1);
        EXPECT_NE(message.find("a video of " + side + " x " + side + " pixels would take"), std::string::npos) << message;
        EXPECT_NE(message.find("lower --dpi or size_px"), std::string::npos) << message;
        // 4K fits, 8K does not.
        EXPECT_GE(low * low, 3840 * 2160) << kind->container;
        EXPECT_LT(low * low, 7680 * 4320) << kind->container;
    }
}

// The hostile request: an 8K video is refused with exit code 2 before any work, nothing written.
TEST(VideoSpeed, An8kVideoIsRefusedBeforeWork) {
    const auto dir = temp_dir("video-speed-8k");
    for (const char* format : {"mp4", "webm"}) {
        const auto r = run_cli(std::string("render swing --theme slides --size 7680x4320 -f ") + format + " -o '" +
                               dir.string() + "'");
        EXPECT_EQ(r.status, 2) << r.err;
        EXPECT_NE(r.err.find("a video of 7680 x 4320 pixels would take"), std::string::npos) << r.err;
        EXPECT_TRUE(files_in(dir).empty());
    }
    std::filesystem::remove_all(dir);
}
