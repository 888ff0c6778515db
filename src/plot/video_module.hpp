// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The video module: a shared object of its own (pendulum-figures-video.so) holding all that
// needs FFmpeg's libraries. They and the codecs they bring (about a hundred shared
// libraries) are loaded with it, the first time a video is written, as matplotlib imports a
// backend when it is first used: every other run starts without them.

#include "plot/video.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>

namespace plot {

/// One video file being written by the module; what video_encoder forwards to.
class video_sink {
public:
    virtual ~video_sink() = default;
    /// Converts a frame drawn by render_argb for the encoder; callable from several threads.
    virtual video_frame convert(const argb_image& image) const = 0;
    /// Frames drawn over `still` (kept by reference) convert only where they differ from it.
    virtual void keep_against(const argb_image& still) = 0;
    /// Pixels converted so far (the rest copied from the still's conversion).
    virtual std::uint64_t pixels_converted() const = 0;
    /// Encodes the next frame.
    virtual void add(video_frame frame) = 0;
    /// Flushes the encoder and ends the file.
    virtual void finish() = 0;
};

/// What the module offers the program; both come from one build.
struct video_module {
    int version;  ///< video_module_version of the module's build
    /// Opens a video file (see video_encoder); `creation_date` is ISO 8601 or empty for none.
    std::unique_ptr<video_sink> (*open)(const std::filesystem::path& path, const std::string& shown,
                                        const video_kind& kind, int width, int height, double fps,
                                        const std::string& creation_date);
    /// The frame rate as libavformat takes it (see video_frame_rate).
    std::pair<int, int> (*frame_rate)(double fps);
};

/// Changes whenever video_module, video_sink or video_kind changes: a module of another build
/// is refused.
inline constexpr int video_module_version = 3;

/// The module's file name, beside the program in a build tree and in LIBDIR/pendulum-figures/
/// when installed.
inline constexpr const char* video_module_file = "pendulum-figures-video.so";

}  // namespace plot

/// The module's one entry point, looked up by name when it is loaded.
extern "C" const plot::video_module* pendulum_figures_video_module();
