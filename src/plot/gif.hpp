#pragma once

#include "plot/theme.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace plot {

/// An 8-bit RGB colour of a GIF palette.
struct rgb8 {
    std::uint8_t r = 0;  ///< red
    std::uint8_t g = 0;  ///< green
    std::uint8_t b = 0;  ///< blue
};

/// The palette of an animation: the background, then each ink blended over it in `shades`
/// steps (the anti-aliasing shades of lines and text), then mid-tones between inks; at most 256.
std::vector<rgb8> gif_palette(const std::vector<rgb>& inks, const rgb& background, int shades);

/// Encodes frames of one size into an animated GIF in memory (giflib). Each frame is mapped
/// to the palette (nearest colour, no dithering, so lines stay crisp) and only the rectangle
/// that changed since the previous frame is stored.
class gif_encoder {
public:
    /// Starts a GIF of width x height pixels showing `fps` frames per second, looping forever.
    gif_encoder(int width, int height, std::vector<rgb8> palette, double fps);
    ~gif_encoder();
    gif_encoder(const gif_encoder&) = delete;
    gif_encoder& operator=(const gif_encoder&) = delete;

    /// Adds a frame given as Cairo ARGB32 pixels (premultiplied, native-endian) with `stride` bytes per row.
    void add_frame(const unsigned char* argb, int stride);

    /// Ends the file and returns its bytes; the encoder is finished afterwards.
    std::string finish();

    /// The number of frames added so far.
    int frames() const { return frames_; }

private:
    struct state;
    std::unique_ptr<state> state_;
    int frames_ = 0;
};

}  // namespace plot
