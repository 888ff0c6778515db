// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "plot/theme.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace plot {

/// The frame rate nearest `fps` that a GIF plays evenly: 100/k frames per second for the whole
/// number k of hundredths of a second nearest its frame's time (a GIF counts delays in them),
/// k at least 2 (browsers slow shorter delays): 25 stays 25, 30 plays at 33.33.
double gif_playback_rate(double fps);

/// A frame rate as text, to the hundredth without trailing zeros: "25", "33.33".
std::string rate_text(double fps);

/// The most pixels the frames of one GIF may add up to. The 30-period swing at 1280 x 720
/// (3810 frames, 3.51e9 pixels) takes 38.8 MB, 11 bytes per thousand pixels, and one 4K
/// period 7.5 bytes; at 11 bytes this many pixels are 44 MB, under the 50 MB promised.
inline constexpr double max_gif_pixels = 4e9;

/// Throws bad_input, before any work, if `frames` frames of width x height pixels add up to
/// more than max_gif_pixels, naming the size and what to lower.
void check_gif_size(double frames, int width, int height);

/// An 8-bit RGB colour of a GIF palette.
struct rgb8 {
    std::uint8_t r = 0;  ///< red
    std::uint8_t g = 0;  ///< green
    std::uint8_t b = 0;  ///< blue
};

/// The palette of an animation: the background, then each ink blended over it in `shades`
/// steps (the anti-aliasing shades of lines and text), then mid-tones between inks; at most
/// 255 (the GIF encoder keeps one index for unchanged pixels).
std::vector<rgb8> gif_palette(const std::vector<rgb>& inks, const rgb& background, int shades);

/// Encodes frames of one size into an animated GIF in memory (giflib). Each frame is mapped
/// to the palette (nearest colour, no dithering, so lines stay crisp) and only the rectangle
/// that changed since the previous frame is stored, its unchanged pixels transparent.
class gif_encoder {
public:
    /// Starts a GIF of width x height pixels showing `fps` frames per second, looping forever.
    /// `first_frame` numbers the first frame added, for the delays of a part of an animation.
    gif_encoder(int width, int height, std::vector<rgb8> palette, double fps, int first_frame = 0);
    ~gif_encoder();
    gif_encoder(const gif_encoder&) = delete;
    gif_encoder& operator=(const gif_encoder&) = delete;

    /// Adds a frame given as Cairo ARGB32 pixels (premultiplied, native-endian) with `stride` bytes per row.
    void add_frame(const unsigned char* argb, int stride);

    /// Takes a frame as the one before the next, without adding it: a part of an animation
    /// encoded on its own then stores only what changed since the frame before the part.
    void prime(const unsigned char* argb, int stride);

    /// Takes the pixels that most frames share (an animation's still part; they must outlive
    /// the encoder), before any frame: the previous frame is then kept as its rows' runs of
    /// pixels that differ from them instead of a whole copy. The bytes are the same either way.
    void keep_against(const unsigned char* argb, int stride);

    /// The pixels kept of the previous frame (a whole frame's without keep_against).
    std::size_t kept_pixels() const;

    /// Ends the file and returns its bytes; the encoder is finished afterwards.
    std::string finish();

    /// The bytes of a finished file before its first frame, and those of its frames (no
    /// trailer): parts encoded apart with one palette join as head + frames... + ";".
    static std::pair<std::string, std::string> split(const std::string& file, std::size_t head_size);

    /// The size of the file's head (signature, screen, palette and loop), for split().
    std::size_t head_size() const;

    /// The number of frames added so far.
    int frames() const { return frames_; }

private:
    struct state;
    std::unique_ptr<state> state_;
    int frames_ = 0;
    int first_frame_ = 0;
};

}  // namespace plot
