// SPDX-License-Identifier: GPL-3.0-or-later
// A GIF's bytes are bounded before work: gif_bytes_bound holds for every built-in animation in
// every theme (measured here at 1280 x 720 over one period), the most frames of a size are
// accepted and one more refused with the frames, the size, the bytes and what to change.
#include "plot/errors.hpp"
#include "plot/gif.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

using namespace test_support;

namespace {

/// The message check_gif_size throws, or "" if the GIF is accepted.
std::string refusal(double frames, int width, int height) {
    try {
        plot::check_gif_size(frames, width, height);
    } catch (const plot::bad_input& e) {
        return e.what();
    }
    return "";
}

/// The number of images in a GIF's bytes, found by walking its blocks.
int frames_of(const std::string& gif) {
    const auto at = [&](std::size_t i) { return static_cast<unsigned char>(gif.at(i)); };
    const auto skip_blocks = [&](std::size_t i) {
        while (at(i) != 0) i += at(i) + 1U;
        return i + 1;
    };
    std::size_t i = 13;
    if (at(10) & 0x80U) i += 3U * (2U << (at(10) & 7U));
    int frames = 0;
    while (at(i) != ';') {
        if (at(i) == '!') {
            i = skip_blocks(i + 2);
            continue;
        }
        EXPECT_EQ(at(i), ',') << "at byte " << i;
        if (at(i) != ',') return -1;
        const unsigned flags = at(i + 9);
        i += 10;
        if (flags & 0x80U) i += 3U * (2U << (flags & 7U));
        i = skip_blocks(i + 1);
        ++frames;
    }
    return frames;
}

/// A built-in animation's spec with `periods` periods.
std::string spec_of(const std::string& id, int periods) {
    const auto shown = run_cli("show " + id);
    EXPECT_EQ(shown.status, 0) << shown.err;
    std::string spec = shown.out;
    const std::size_t at = spec.find("\nperiods = ");
    EXPECT_NE(at, std::string::npos) << id;
    if (at == std::string::npos) return spec;
    const std::size_t end = spec.find('\n', at + 1);
    spec.replace(at, end - at, "\nperiods = " + std::to_string(periods));
    return spec;
}

const std::pair<int, int> sizes[] = {{320, 180}, {640, 360}, {1280, 720}, {1920, 1080}, {3840, 2160}};

}  // namespace

// At each size the most frames whose bound is within 50 MB are accepted, one more refused
// with the frames, the size, the bytes they may take, the most frames and what to change.
TEST(GifBytes, MostFramesAcceptedOneMoreRefused) {
    for (const auto& [w, h] : sizes) {
        const double most = plot::gif_most_frames(w, h);
        ASSERT_GT(most, 0) << w << "x" << h;
        EXPECT_LE(plot::gif_bytes_bound(most, w, h), plot::max_gif_bytes) << w << "x" << h;
        EXPECT_GT(plot::gif_bytes_bound(most + 1, w, h), plot::max_gif_bytes) << w << "x" << h;
        EXPECT_EQ(refusal(most, w, h), "") << w << "x" << h;
        const std::string message = refusal(most + 1, w, h);
        const std::string size = std::to_string(w) + " x " + std::to_string(h) + " pixels";
        EXPECT_NE(message.find(std::to_string(static_cast<long>(most + 1)) + " frames of " + size), std::string::npos)
            << message;
        EXPECT_NE(message.find("more than the 50 MB a GIF may take"), std::string::npos) << message;
        EXPECT_NE(message.find("at most " + std::to_string(static_cast<long>(most)) + " frames of this size"),
                  std::string::npos)
            << message;
        for (const char* what : {"--size", "--dpi", "the fps", "periods", "--frames", "-f mp4"}) {
            EXPECT_NE(message.find(what), std::string::npos) << what << ": " << message;
        }
        std::printf("%dx%d: at most %.0f frames\n", w, h, most);
    }
    // The 30-period swing (3684 frames) fits at 1280 x 720, not at 1920 x 1080.
    EXPECT_GE(plot::gif_most_frames(1280, 720), 3684);
    EXPECT_LT(plot::gif_most_frames(1920, 1080), 3684);
}

// Every built-in animation in every theme writes at most its bound, over one period at
// 1280 x 720 (its first frame whole and its cross-fade included: the costliest frames).
TEST(GifBytes, BuiltinsWithinTheBoundInEveryTheme) {
    const auto dir = temp_dir("gif-bytes-builtins");
    for (const std::string id : {"swing", "separatrix", "over-the-top"}) {
        std::ofstream(dir / (id + ".toml")) << spec_of(id, 1);
        for (const std::string theme : {"paper", "slides", "slides-dark"}) {
            const auto r = run_cli("render " + id + ".toml --theme " + theme + " --size 1280x720 -f gif --force -o .", dir);
            ASSERT_EQ(r.status, 0) << id << " " << theme << ": " << r.err;
            const std::string gif = slurp(dir / (id + ".gif"));
            const int frames = frames_of(gif);
            const double bound = plot::gif_bytes_bound(frames, 1280, 720);
            std::printf("%s, %s: %d frames, %zu bytes, %.0f%% of the bound\n", id.c_str(), theme.c_str(), frames,
                        gif.size(), 100.0 * static_cast<double>(gif.size()) / bound);
            EXPECT_GT(frames, 1) << id << " " << theme;
            EXPECT_LE(static_cast<double>(gif.size()), bound) << id << " " << theme;
        }
    }
    std::filesystem::remove_all(dir);
}

// Hostile: 30 periods of the swing at 1920 x 1080 are refused before any work with exit 2 and
// the GIF's message, and at 4K with every animation's (its pixels pass that bound first);
// nothing is written either way.
TEST(GifBytes, RefusedBeforeWorkNothingWritten) {
    const auto dir = temp_dir("gif-bytes-refused");
    std::ofstream(dir / "swing30.toml") << spec_of("swing", 30);
    for (const std::string size : {"1920x1080", "3840x2160"}) {
        const auto r = run_cli("render swing30.toml --theme slides --size " + size + " -f gif -o .", dir);
        EXPECT_EQ(r.status, 2) << size << ": " << r.err;
        EXPECT_NE(r.err.find("swing30.gif: 3684 frames of " + size.substr(0, size.find('x')) + " x "),
                  std::string::npos)
            << r.err;
        if (size == "1920x1080") {
            EXPECT_NE(r.err.find("MB as a GIF"), std::string::npos) << r.err;
        }
        EXPECT_EQ(files_in(dir).size(), 1U) << size;
    }
    std::filesystem::remove_all(dir);
}

// Hostile: a frame so large that even one may pass 50 MB (65535 x 65535, the most a GIF's
// side holds) is refused alone, the message saying that no frame of that size fits; the
// smallest frame is accepted by the hundred thousand.
TEST(GifBytes, ExtremeSizes) {
    EXPECT_EQ(plot::gif_most_frames(65535, 65535), 0);
    const std::string message = refusal(1, 65535, 65535);
    EXPECT_NE(message.find("1 frames of 65535 x 65535 pixels may take "), std::string::npos) << message;
    EXPECT_NE(message.find("at most 0 frames of this size"), std::string::npos) << message;
    EXPECT_GT(plot::gif_most_frames(1, 1), 1e5);
    EXPECT_EQ(refusal(plot::gif_most_frames(1, 1), 1, 1), "");
}

// The bound before the work is an estimate from the built-ins' rates; the bytes themselves
// are held to 50 MB as the parts are written, for any spec: 50,000,000 bytes pass, one more is
// refused with the frames written so far, the size and what to change.
TEST(GifBytes, WrittenBytesAreHeldToTheBoundAtAnyRate) {
    EXPECT_NO_THROW(plot::check_gif_written(50'000'000, 900, 1000, 1280, 720));
    try {
        plot::check_gif_written(50'000'001, 901, 1000, 1280, 720);
        ADD_FAILURE() << "50,000,001 bytes accepted";
    } catch (const plot::bad_input& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("1000 frames of 1280 x 720 pixels: the GIF passed the 50 MB a GIF may take after 901 of them"),
                  std::string::npos)
            << what;
        EXPECT_NE(what.find("nothing is written"), std::string::npos) << what;
        EXPECT_NE(what.find("-f mp4 or webm"), std::string::npos) << what;
    }
}
