// SPDX-License-Identifier: GPL-3.0-or-later
// Video of animations (mp4, webm) as Debian's ffprobe and ffmpeg read it: codec, size,
// frames, duration and colour tags, frames that look like the PNG frames of the same
// spec, the same bytes twice, odd pixel sizes, frame rates, and still figures refused.
#include "png_image.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

namespace {

namespace fs = std::filesystem;
using test_support::files_in;
using test_support::run_cli;
using test_support::run_command;
using test_support::slurp;
using test_support::temp_dir;

/// ffprobe's key=value lines of the first video stream and the format, frames counted.
std::map<std::string, std::string> probe(const fs::path& file) {
    const auto r = run_command("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                               "stream=codec_name,profile,width,height,pix_fmt,nb_read_frames,r_frame_rate,"
                               "color_range,color_space,color_transfer,color_primaries:format=duration,format_name:"
                               "format_tags=creation_time -of default=noprint_wrappers=1 '" +
                               file.string() + "'");
    std::map<std::string, std::string> out;
    EXPECT_EQ(r.status, 0) << "ffprobe (Debian's ffmpeg): " << r.err;
    std::size_t at = 0;
    while (at < r.out.size()) {
        const auto end = r.out.find('\n', at);
        const std::string line = r.out.substr(at, end - at);
        if (const auto eq = line.find('='); eq != std::string::npos) out[line.substr(0, eq)] = line.substr(eq + 1);
        at = end == std::string::npos ? r.out.size() : end + 1;
    }
    return out;
}

/// Frame n (from 0) of a video, decoded by ffmpeg to RGB and cropped to width x height.
/// Raw pixels, not a PNG: ffmpeg's PNG would carry BT.709's gamma, which libpng applies.
test_support::rgb_image video_frame(const fs::path& video, int n, unsigned width, unsigned height) {
    const fs::path raw = video.string() + "-" + std::to_string(n) + ".rgb";
    const auto r = run_command("ffmpeg -v error -y -i '" + video.string() + "' -vf 'select=eq(n\\," + std::to_string(n) +
                               "),format=rgb24,crop=" + std::to_string(width) + ":" + std::to_string(height) +
                               ":0:0' -frames:v 1 -f rawvideo -pix_fmt rgb24 '" + raw.string() + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    test_support::rgb_image im;
    const std::string bytes = slurp(raw);
    im.pixels.assign(bytes.begin(), bytes.end());
    if (im.pixels.size() == std::size_t{3} * width * height) {
        im.width = width;
        im.height = height;
    }
    return im;
}

/// The image averaged over 2 x 2 pixels (an odd last row or column left out).
test_support::rgb_image halved(const test_support::rgb_image& im) {
    test_support::rgb_image out;
    out.width = im.width / 2;
    out.height = im.height / 2;
    out.pixels.resize(std::size_t{3} * out.width * out.height);
    for (unsigned y = 0; y < out.height; ++y) {
        for (unsigned x = 0; x < out.width; ++x) {
            for (unsigned c = 0; c < 3; ++c) {
                const auto at = [&](unsigned dx, unsigned dy) {
                    return im.pixels[3 * ((2 * y + dy) * std::size_t{im.width} + 2 * x + dx) + c];
                };
                out.pixels[3 * (y * std::size_t{out.width} + x) + c] =
                    static_cast<unsigned char>((at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1) + 2) / 4);
            }
        }
    }
    return out;
}

/// The largest RGB RMS (0..255) of frames decoded from a video against our PNG frames of
/// the same spec, both averaged over 2 x 2 pixels (yuv420p's colour resolution): the
/// codecs' loss on thin coloured lines is at most 3.7 at 640 x 360; the frame after (in the
/// middle of the swing) is 8.4, other colours or another size far more.
constexpr double video_tolerance = 4.5;

/// How far colours are off where compression and half-resolution colour cannot reach:
/// inside areas of one saturated colour (a coloured background), the largest mean
/// difference of a channel, decoded less drawn. A wrong colour matrix (BT.601 for BT.709)
/// is 8 or more; right, it is about 1. `pixels` gets how many pixels were measured.
double interior_colour_error(const test_support::rgb_image& drawn, const test_support::rgb_image& decoded,
                             int& pixels) {
    double sum[3] = {0, 0, 0};
    pixels = 0;
    const auto at = [&](const test_support::rgb_image& im, unsigned x, unsigned y, unsigned c) {
        return int(im.pixels[3 * (y * std::size_t{im.width} + x) + c]);
    };
    for (unsigned y = 3; y + 3 < drawn.height; ++y) {
        for (unsigned x = 3; x + 3 < drawn.width; ++x) {
            const int r = at(drawn, x, y, 0), g = at(drawn, x, y, 1), b = at(drawn, x, y, 2);
            if (std::max({r, g, b}) - std::min({r, g, b}) < 100) continue;
            bool flat = true;
            for (unsigned v = y - 3; v <= y + 3 && flat; ++v) {
                for (unsigned u = x - 3; u <= x + 3 && flat; ++u) {
                    flat = at(drawn, u, v, 0) == r && at(drawn, u, v, 1) == g && at(drawn, u, v, 2) == b;
                }
            }
            if (!flat) continue;
            ++pixels;
            for (unsigned c = 0; c < 3; ++c) sum[c] += at(decoded, x, y, c) - at(drawn, x, y, c);
        }
    }
    double worst = 0;
    for (const double s : sum) worst = std::max(worst, pixels ? std::abs(s) / pixels : 0.0);
    return worst;
}

/// Compares frames `frames` (from 0) of the video with DIR/ID-NNNN.png.
void expect_frames_like_pngs(const fs::path& video, const fs::path& dir, const std::string& id,
                             std::initializer_list<int> frames, int first_number, bool colours) {
    for (const int n : frames) {
        char name[64];
        std::snprintf(name, sizeof name, "%s-%04d.png", id.c_str(), first_number + n);
        const auto png = test_support::decode_rgb(slurp(dir / name));
        ASSERT_GT(png.width, 0u) << name;
        const auto decoded = video_frame(video, n, png.width, png.height);
        const std::string diff = video.string() + "-" + std::to_string(n) + "-failed-diff.png";
        const auto c = test_support::compare_rgb(halved(png), halved(decoded), video_tolerance, diff);
        ASSERT_TRUE(c.same_size) << video << " frame " << n << ": " << decoded.width << " x " << decoded.height;
        EXPECT_LE(c.rms, video_tolerance) << video << " frame " << n << " against " << name << "; diff in " << diff;
        std::printf("%s frame %d: RMS %.2f\n", video.filename().c_str(), n, c.rms);
        if (!colours) continue;
        int pixels = 0;
        const double colour = interior_colour_error(png, decoded, pixels);
        EXPECT_GE(pixels, 10000) << video << " frame " << n << ": too few pixels of one colour to measure";
        EXPECT_LE(colour, 2) << video << " frame " << n << ": colours off";
        std::printf("%s frame %d: colour %.2f over %d pixels\n", video.filename().c_str(), n, colour, pixels);
    }
}

TEST(Video, Mp4AndWebmAsFfprobeAndFfmpegReadThem) {
    const auto dir = temp_dir("video");
    // On a saturated background (Okabe-Ito's bluish green) wrong colours show.
    auto r = run_cli("render swing --theme slides --set 'background=\"#009e73\"' -f mp4,webm,png --frames 2..13 "
                     "--dpi 64 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");  // the libraries' log stays out of the terminal
    struct expected {
        std::string file, codec, format;
    };
    for (const auto& [file, codec, format] : {expected{"swing.mp4", "h264", "mov,mp4,m4a,3gp,3g2,mj2"},
                                              expected{"swing.webm", "vp9", "matroska,webm"}}) {
        auto p = probe(dir / file);
        EXPECT_EQ(p["codec_name"], codec) << file;
        EXPECT_EQ(p["format_name"], format) << file;
        EXPECT_EQ(p["width"], "640") << file;  // 25.4 cm at 64 dpi
        EXPECT_EQ(p["height"], "360") << file;
        EXPECT_EQ(p["pix_fmt"], "yuv420p") << file;
        EXPECT_EQ(p["nb_read_frames"], "12") << file;
        EXPECT_EQ(p["r_frame_rate"], "25/1") << file;
        EXPECT_NEAR(std::stod(p["duration"]), 0.48, 1e-3) << file;  // 12 frames at 25 per second (the default)
        for (const char* key : {"color_space", "color_transfer", "color_primaries"}) EXPECT_EQ(p[key], "bt709") << file << " " << key;
        EXPECT_EQ(p["color_range"], "tv") << file;
        EXPECT_EQ(p.count("TAG:creation_time"), 0u) << file << ": no date without SOURCE_DATE_EPOCH";
        expect_frames_like_pngs(dir / file, dir, "swing", {0, 5, 11}, 2, true);
    }
    EXPECT_EQ(probe(dir / "swing.mp4")["profile"], "High");
    // Faststart: the index (moov) before the frames (mdat), so that a player starts at once.
    const std::string mp4 = slurp(dir / "swing.mp4");
    EXPECT_LT(mp4.find("moov"), mp4.find("mdat"));
    fs::remove_all(dir);
}

TEST(Video, SameSpecSameBytes) {
    const auto dir = temp_dir("video-twice");
    const std::string args = "render swing --theme slides -f mp4,webm --frames 1..40 --dpi 24 -o '" + dir.string() + "'";
    ASSERT_EQ(run_cli(args).status, 0);
    const std::string mp4 = slurp(dir / "swing.mp4");
    const std::string webm = slurp(dir / "swing.webm");
    ASSERT_EQ(run_cli(args + " --force").status, 0);
    EXPECT_TRUE(slurp(dir / "swing.mp4") == mp4) << "swing.mp4 changed";
    EXPECT_TRUE(slurp(dir / "swing.webm") == webm) << "swing.webm changed";
    // No library version in the files (WebM names its muxer "Lavf", without one).
    EXPECT_EQ(mp4.find("Lavf5"), std::string::npos);
    EXPECT_EQ(webm.find("Lavf5"), std::string::npos);
    // A date only from SOURCE_DATE_EPOCH, and then the same bytes again.
    ::setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
    ASSERT_EQ(run_cli(args + " --force").status, 0);
    const std::string dated = slurp(dir / "swing.mp4");
    const std::string dated_webm = slurp(dir / "swing.webm");
    ASSERT_EQ(run_cli(args + " --force").status, 0);
    ::unsetenv("SOURCE_DATE_EPOCH");
    EXPECT_TRUE(slurp(dir / "swing.mp4") == dated) << "swing.mp4 changed";
    EXPECT_TRUE(slurp(dir / "swing.webm") == dated_webm) << "swing.webm changed";
    EXPECT_EQ(probe(dir / "swing.mp4")["TAG:creation_time"], "2023-11-14T22:13:20.000000Z");
    EXPECT_EQ(probe(dir / "swing.webm")["TAG:creation_time"], "2023-11-14T22:13:20.000000Z");
    fs::remove_all(dir);
}

TEST(Video, OddPixelSizesGetOneMoreRowAndColumn) {
    // 25.3 cm at 19 dpi: 189 x 107 pixels, which yuv420p cannot hold; the video is 190 x 108,
    // its last row and column copies of the figure's (the background), the rest the frame.
    const auto dir = temp_dir("video-odd");
    const auto r = run_cli("render swing --theme slides --set figure_width_cm=25.3 -f mp4,webm,png --dpi 19 "
                           "--frames 1..6 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto png = test_support::decode_rgb(slurp(dir / "swing-0001.png"));
    ASSERT_EQ(png.width, 189u);
    ASSERT_EQ(png.height, 107u);
    for (const char* file : {"swing.mp4", "swing.webm"}) {
        auto p = probe(dir / file);
        EXPECT_EQ(p["width"], "190") << file;
        EXPECT_EQ(p["height"], "108") << file;
        EXPECT_EQ(p["nb_read_frames"], "6") << file;
        expect_frames_like_pngs(dir / file, dir, "swing", {0, 5}, 1, false);
    }
    fs::remove_all(dir);
}

/// A copy of the swing with another frame rate, half a second long, cut there (no frames added at the seam).
fs::path swing_at(const fs::path& dir, const std::string& fps) {
    const auto path = dir / "moving.toml";
    std::ofstream(path) << "[figure]\ncolumns = 2\n[pendulum]\nlength_m = 1.0\n[animation]\nfps = " << fps
                        << "\nduration_s = 0.5\nloop = \"periods\"\n[[panel]]\nplot = \"pendulum\"\ntheta0 = \"170deg\"\n"
                           "methods = [\"exact\"]\n";
    return path;
}

TEST(Video, FrameRatesOfTheSpec) {
    // Any rate the spec takes (1 to 120) plays: kept as a fraction in MP4, in WebM's milliseconds.
    struct rate {
        std::string fps, r_frame_rate;
        int frames;
        double duration;  // of the file, frames / fps (WebM: to the millisecond)
    };
    const auto dir = temp_dir("video-fps");
    for (const auto& [fps, fraction, frames, duration] :
         {rate{"29.97", "2997/100", 15, 15 / 29.97}, rate{"120", "120/1", 60, 60 / 120.0}, rate{"1", "1/1", 1, 1.0},
          rate{"12.5", "25/2", 7, 7 / 12.5}}) {
        const auto r = run_cli("render '" + swing_at(dir, fps).string() + "' -f mp4,webm --dpi 10 -o '" +
                               dir.string() + "'");
        ASSERT_EQ(r.status, 0) << fps << ": " << r.err;
        for (const char* file : {"moving.mp4", "moving.webm"}) {
            auto p = probe(dir / file);
            EXPECT_EQ(p["nb_read_frames"], std::to_string(frames)) << fps << " " << file;
            EXPECT_NEAR(std::stod(p["duration"]), duration, 1.5e-3) << fps << " " << file;
            if (std::string(file) == "moving.mp4") {
                EXPECT_EQ(p["r_frame_rate"], fraction) << fps;
            }
        }
    }
    fs::remove_all(dir);
}

TEST(Video, StillFiguresAreBadInputBeforeAnyFile) {
    const auto dir = temp_dir("video-still");
    const std::string formats = "png, pdf, svg, eps, gif, pdf_tex or eps_tex";
    struct refused {
        std::string args, message;
    };
    for (const auto& [args, message] : {
             refused{"render fig6 -f png,mp4", "trajectory-second.mp4: mp4 holds animations only; a still figure, or one frame "
                                               "of an animation (--at): " + formats},
             refused{"render swing fig6 -f webm", "trajectory-second.webm: webm holds animations only"},
             refused{"render swing --at 0.25 -f png,mp4", "swing.mp4: mp4 holds animations only"},
             refused{"render fig6 -f mp4 -o -", "mp4 holds animations only"},
         }) {
        const auto r = run_cli(args + (args.ends_with(" -") ? "" : " -o '" + dir.string() + "'"));
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
        EXPECT_EQ(r.out, "") << args;
        EXPECT_EQ(files_in(dir), std::set<std::string>{}) << args;
    }
    fs::remove_all(dir);
}

/// Every other run starts without FFmpeg's libraries: the program does not link them, and
/// a video without the module is an error that says so, with nothing written.
TEST(Video, LibrariesLoadWithTheModuleOnly) {
    const auto needed = run_command("objdump -p '" + std::string(PENDULUM_EXE) + "' | grep NEEDED");
    ASSERT_EQ(needed.status, 0);
    for (const char* lib : {"libavcodec", "libavformat", "libswscale", "libavutil"}) {
        EXPECT_EQ(needed.out.find(lib), std::string::npos) << lib << " is loaded by every run:\n" << needed.out;
    }
    const auto dir = temp_dir("video-no-module");
    const fs::path program = dir / "bin" / "pendulum-figures";
    fs::create_directories(program.parent_path());
    fs::copy_file(PENDULUM_EXE, program);
    const auto r = run_command("'" + program.string() + "' render swing --frames 1..2 -f mp4,png -o '" + dir.string() + "'");
    EXPECT_EQ(r.status, 1) << r.err;
    // A copy of the program looks where the installation puts the module, never beside itself.
    EXPECT_NE(r.err.find("the video module pendulum-figures-video.so is not installed (looked for /"), std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find((dir / "bin").string()), std::string::npos) << r.err;
    EXPECT_EQ(files_in(dir), std::set<std::string>{"bin"});
    // Beside the copy, the build's own module is not loaded either (see test_costs for one
    // planted there); the build's program finds it in the build directory.
    fs::copy_file(fs::path(PENDULUM_EXE).parent_path() / "pendulum-figures-video.so",
                  program.parent_path() / "pendulum-figures-video.so");
    const auto beside = run_command("'" + program.string() + "' render swing --frames 1..2 -f mp4 -o '" + dir.string() + "'");
    EXPECT_EQ(beside.status, 1) << beside.err;
    EXPECT_FALSE(fs::exists(dir / "swing.mp4"));
    const auto found = run_command("'" + std::string(PENDULUM_EXE) + "' render swing --frames 1..2 -f mp4 -o '" + dir.string() + "'");
    EXPECT_EQ(found.status, 0) << found.err;
    EXPECT_TRUE(fs::exists(dir / "swing.mp4"));
    fs::remove_all(dir);
}

}  // namespace
