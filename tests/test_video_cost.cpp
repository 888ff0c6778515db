// SPDX-License-Identifier: GPL-3.0-or-later
// The cost of a video: frames drawn over a still are converted only where they differ from
// it (a counter, in blocks of 64 columns of a pair of rows), with the same bytes as
// converting them whole; the encoder's options as x264 writes them into the file.
#include "plot/video_module.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <dlfcn.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::slurp;
using test_support::temp_dir;

/// The build's video module, loaded as the build's program loads it.
const plot::video_module& video_module() {
    static const plot::video_module* loaded = [] {
        const fs::path file = fs::path(PENDULUM_EXE).parent_path() / plot::video_module_file;
        void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) throw std::runtime_error(dlerror());
        using entry = const plot::video_module* (*)();
        auto* get = reinterpret_cast<entry>(dlsym(handle, "pendulum_figures_video_module"));
        return get ? get() : nullptr;
    }();
    if (!loaded || loaded->version != plot::video_module_version) throw std::runtime_error("another module");
    return *loaded;
}

/// A still of width x height: a grey ramp, every pixel its own shade of its row and column.
plot::argb_image still_of(int width, int height) {
    plot::argb_image im;
    im.width = width;
    im.height = height;
    im.stride = 4 * width;
    im.data.resize(static_cast<std::size_t>(im.stride) * static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            unsigned char* p = &im.data[static_cast<std::size_t>(y) * im.stride + 4 * static_cast<std::size_t>(x)];
            p[0] = static_cast<unsigned char>(3 * x + y);  // blue (little-endian xRGB)
            p[1] = static_cast<unsigned char>(x + 5 * y);  // green
            p[2] = static_cast<unsigned char>(7 * x);      // red
            p[3] = 255;
        }
    }
    return im;
}

/// The still with the pixels (x, y) in `changed` painted a colour of their own.
plot::argb_image frame_over(const plot::argb_image& still, const std::vector<std::pair<int, int>>& changed) {
    plot::argb_image im = still;
    for (const auto& [x, y] : changed) {
        unsigned char* p = &im.data[static_cast<std::size_t>(y) * im.stride + 4 * static_cast<std::size_t>(x)];
        p[0] = 10;
        p[1] = 200;
        p[2] = 40;
    }
    return im;
}

/// Writes `frames` to `file`, over `still` if `keep`; returns the pixels converted.
std::uint64_t encode(const fs::path& file, const plot::argb_image& still, const std::vector<plot::argb_image>& frames,
                     bool keep) {
    auto sink = video_module().open(file, file.filename().string(), plot::mp4_video, still.width, still.height, 25, "");
    if (keep) sink->keep_against(still);
    for (const auto& f : frames) sink->add(sink->convert(f));
    sink->finish();
    return sink->pixels_converted();
}

/// The pixels converted for one frame over the still with `changed` pixels.
std::uint64_t converted_for(const std::vector<std::pair<int, int>>& changed, int width = 256, int height = 64) {
    const auto dir = temp_dir("video-cost-count");
    const plot::argb_image still = still_of(width, height);
    const std::uint64_t n = encode(dir / "v.mp4", still, {frame_over(still, changed)}, true);
    fs::remove_all(dir);
    return n;
}

}  // namespace

// The same bytes whether the frames are converted whole or only where they moved, and the
// counter tells which: every pixel of every frame without the still, the changed blocks with it.
TEST(VideoCost, KeptStillGivesTheSameBytesConvertingOnlyWhatMoved) {
    const auto dir = temp_dir("video-cost-same");
    for (const auto& [w, h] : {std::pair{320, 96}, std::pair{101, 51}}) {
        const plot::argb_image still = still_of(w, h);
        std::vector<plot::argb_image> frames;
        for (int i = 0; i < 12; ++i) frames.push_back(frame_over(still, {{(7 * i) % w, (5 * i) % h}, {w - 1, h - 1}}));
        frames.push_back(still);
        const std::uint64_t whole = encode(dir / "whole.mp4", still, frames, false);
        const std::uint64_t kept = encode(dir / "kept.mp4", still, frames, true);
        const auto [cw, ch] = plot::video_size(w, h);
        EXPECT_EQ(whole, static_cast<std::uint64_t>(cw) * ch * frames.size()) << w << "x" << h;
        EXPECT_LT(kept, whole / 4) << w << "x" << h;
        EXPECT_GT(kept, 0u);
        EXPECT_EQ(slurp(dir / "whole.mp4"), slurp(dir / "kept.mp4")) << w << "x" << h;
    }
    fs::remove_all(dir);
}

// The boundaries of a block: columns 63 and 64 are in two blocks, rows 1 and 2 in two pairs.
TEST(VideoCost, ConvertedBlocksAre64ColumnsOfAPairOfRows) {
    EXPECT_EQ(converted_for({}), 0u);                   // the still itself: all copied
    EXPECT_EQ(converted_for({{0, 0}}), 128u);           // one block of 64 x 2
    EXPECT_EQ(converted_for({{63, 1}}), 128u);          // the same block's last column and row
    EXPECT_EQ(converted_for({{64, 0}}), 128u);          // the next block
    EXPECT_EQ(converted_for({{63, 0}, {64, 0}}), 256u); // both
    EXPECT_EQ(converted_for({{0, 1}, {0, 2}}), 256u);   // two pairs of rows
    EXPECT_EQ(converted_for({{10, 5}, {200, 5}}), 256u); // two moving parts on one row, apart
    EXPECT_EQ(converted_for({{255, 63}}), 128u);        // the last block
    // Odd sides: the padded column and row go with the last pixel's block (101 -> 102: 38 columns).
    EXPECT_EQ(converted_for({{100, 50}}, 101, 51), 76u);
}

// Hostile use of the module: a still of another size, or one set after frames, is refused.
TEST(VideoCost, AStillOfAnotherSizeOrLateIsRefused) {
    const auto dir = temp_dir("video-cost-refused");
    auto sink = video_module().open(dir / "v.mp4", "v.mp4", plot::mp4_video, 64, 32, 25, "");
    try {
        sink->keep_against(still_of(64, 30));
        FAIL() << "a still of another size was taken";
    } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("64 x 30 pixels, not 64 x 32"), std::string::npos) << e.what();
    }
    const plot::argb_image still = still_of(64, 32);
    sink->add(sink->convert(still));
    EXPECT_THROW(sink->keep_against(still), std::logic_error);
    sink->finish();
    fs::remove_all(dir);
}

// The program's video: x264's options as it wrote them into the file.
TEST(VideoCost, Mp4CarriesTheChosenEncoderOptions) {
    const auto dir = temp_dir("video-cost-options");
    const auto r = run_cli("plot pendulum --theta0 1,2.5 --methods exact --apart --length 1 --duration 1 --size 640x360 "
                           "-f mp4 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string bytes = slurp(dir / "pendulum.mp4");
    const auto at = bytes.find("options: ");
    ASSERT_NE(at, std::string::npos);
    const std::string options = " " + bytes.substr(at + 9, bytes.find('\0', at) - at - 9) + " ";
    std::printf("x264 options:%s\n", options.c_str());
    for (const char* expected : {" cabac=1 ", " ref=1 ", " me=dia ", " subme=0 ", " 8x8dct=1 ", " trellis=0 ",
                                 " threads=2 ", " sliced_threads=1 ", " bframes=0 ", " mbtree=0 ", " aq=0 ",
                                 " crf=23.0 ", " keyint=50 "}) {
        EXPECT_NE(options.find(expected), std::string::npos) << expected << " not in" << options;
    }
    fs::remove_all(dir);
}
