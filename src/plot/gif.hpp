// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "plot/theme.hpp"

#include <cstddef>
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

/// The most bytes a GIF may take (the animation issue's promise for 30 periods at 720p).
inline constexpr double max_gif_bytes = 50e6;

/// The bytes a frame of the built-in animations takes, per pixel count to the power 2/3: what
/// changes between frames is lines and their anti-aliased edges, which grow with the side, not
/// the area. The worst built-in, the swing in slides-dark, took 38.55 MB for its 30 periods at
/// 1280 x 720 (3684 frames: 1.093 with gif_extra_frames) and 47.66 MB for the most frames this
/// bound accepted at 3840 x 2160 before (974: 1.146; slides takes 0.5 % more there); this is
/// 1.152 with a margin of 10 %. Over its first period the rate of its 30 periods at 720p, with
/// gif_extra_frames, is within 2.4 % of the measured bytes at 320 x 180, 640 x 360, 1280 x 720
/// and 3840 x 2160.
inline constexpr double gif_frame_bytes = 1.27;

/// The frames' worth of bytes a GIF takes beyond its frames' own: its first frame whole and the
/// cross-fade of its loop (the swing's first period, 136 frames, takes as much as 176.8 frames
/// at the rate of its 30 periods).
inline constexpr double gif_extra_frames = 41;

/// The bytes a GIF of `frames` frames of width x height pixels is bounded by:
/// (frames + gif_extra_frames) * gif_frame_bytes * (width * height)^(2/3).
double gif_bytes_bound(double frames, int width, int height);

/// The most frames of width x height pixels whose gif_bytes_bound is within max_gif_bytes.
double gif_most_frames(int width, int height);

/// Throws bad_input, before any work, if a GIF of `frames` frames of width x height pixels
/// has more than gif_most_frames, naming the frames, the size, the bytes they may take, the
/// most frames of that size and what to change.
void check_gif_size(double frames, int width, int height);

/// Throws bad_input if `bytes`, written for the first `done` of `frames` frames of width x
/// height pixels, pass max_gif_bytes: the promise holds for any spec, also one whose frames
/// change more than the built-ins' (the temporary is then removed; nothing is written).
void check_gif_written(std::size_t bytes, int done, int frames, int width, int height);

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
