// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Video files (MP4 with H.264, WebM with VP9) written through FFmpeg's libraries, which live
// in a module of their own (video_module.hpp), loaded the first time a video is written:
// every other command starts without them.

#include "plot/frames.hpp"

#include <sys/stat.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace plot {

/// A container and the codec in it, and how that codec is set up.
struct video_kind {
    const char* container;         ///< libavformat's name of the container: "mp4", "webm"
    const char* encoder;           ///< libavcodec's encoder: "libx264", "libvpx-vp9"
    const char* codec_options;     ///< the encoder's options, "key=value:key=value", but the look-ahead
    const char* lookahead_option;  ///< the encoder's option of the look-ahead: "rc-lookahead"
    int lookahead;                 ///< frames looked ahead at most (fewer for large frames: video_settings_for)
    const char* muxer_options;     ///< the container's options, the same way
    int threads;                   ///< the encoder's threads: fixed, as the bytes may depend on it
};

/// MP4 holding H.264 (High profile, yuv420p, constant quality), its index first
/// (faststart): PowerPoint, Keynote, Google Slides and every browser play it. x264's
/// ultrafast preset with CABAC and the 8x8 transform back (High profile), no B-frames, no
/// look-ahead, two sliced threads: on frames of still figures with a few moving parts it
/// took 0.66 of superfast's CPU time (one B-frame) for 1.6 times the bytes (a 30-s 1080p
/// clip of two pendulums: about 5 MB) and less memory. Accepted: SSIM >= 0.98 against the
/// drawn frames (tests/test_video_speed.cpp); README's video section has the measures.
inline constexpr video_kind mp4_video{"mp4", "libx264",
                                      "preset=ultrafast:crf=23:profile=high:coder=cabac:8x8dct=1:x264-params=sliced-threads=1",
                                      "rc-lookahead", 0, "movflags=+faststart", 2};
/// WebM holding VP9 (yuv420p, constant quality): browsers and Google Slides play it.
inline constexpr video_kind webm_video{"webm", "libvpx-vp9",
                                       "b=0:crf=34:deadline=good:cpu-used=4:row-mt=0:tile-columns=2",
                                       "lag-in-frames", 25, "", 4};  // libvpx's own lag-in-frames

/// How many threads the encoder runs and how many frames it looks ahead (x264's
/// rc-lookahead, libvpx's lag-in-frames): the frames it holds grow with both.
struct video_settings {
    int threads = 1;    ///< the encoder's threads
    int lookahead = 0;  ///< frames looked ahead
};

/// The settings for frames of width x height: the kind's own, with fewer threads and a
/// shorter look-ahead where they would take more than raster_budget_bytes (video_memory).
/// They depend on the size alone: the same frames give the same bytes on any machine.
video_settings video_settings_for(const video_kind& kind, int width, int height);

/// The memory of writing a video of width x height with `settings`, `workers` drawing
/// frames: the encoder's frames (bytes a pixel per frame held, measured with
/// /usr/bin/time -v at 1080p and 4K) and ours in flight (a drawing per worker, two
/// converted frames per worker, the still drawing and its conversion).
double video_memory(const video_kind& kind, int width, int height, video_settings settings, unsigned workers);

/// Throws plot::bad_input, before any work, if a video of width x height cannot be written
/// within raster_budget_bytes even with one worker and the encoder's least settings.
void check_video_memory(const video_kind& kind, int width, int height);

/// A frame converted for the encoder (yuv420p, BT.709, limited range); empty by default.
struct video_frame {
    /// The converted pixels, as the video module holds them.
    struct pixels {
        virtual ~pixels() = default;
    };
    std::unique_ptr<pixels> data;  ///< the pixels
};

class video_sink;

/// The even size a video of width x height pixels has: yuv420p halves the colour in both
/// directions, so an odd side gets one more row or column, a copy of its last.
inline std::pair<int, int> video_size(int width, int height) { return {width + width % 2, height + height % 2}; }

/// Encodes frames of one size, in order, into a video file at `path` (a temporary: the
/// caller renames it). Every setting is fixed, the thread counts too, and the files carry
/// no date (unless SOURCE_DATE_EPOCH gives one) and no library version: the same frames
/// give the same bytes with the same libraries. Memory does not grow with the frames.
class video_encoder {
public:
    /// Opens the file for frames of width x height pixels (any size: see video_size) shown
    /// at `fps` frames per second. Throws std::runtime_error naming `shown` (the file's
    /// name for messages) if the libraries cannot, or the video module is not installed.
    video_encoder(const std::filesystem::path& path, const std::string& shown, video_kind kind, int width,
                  int height, double fps);
    ~video_encoder();
    video_encoder(const video_encoder&) = delete;
    video_encoder& operator=(const video_encoder&) = delete;

    /// Converts a frame drawn by render_argb for the encoder; callable from several threads.
    video_frame convert(const argb_image& image) const;

    /// Frames converted afterwards are drawn over `still` (of the frames' size, kept by
    /// reference: it must outlive the encoder): only the pixels that differ from it are
    /// converted, the rest copied from its conversion, done once here. The same bytes as
    /// without. Call before the first frame, once.
    void keep_against(const argb_image& still);

    /// Pixels converted so far, the copied ones not counted.
    std::uint64_t pixels_converted() const;

    /// Encodes the next frame.
    void add(video_frame frame);

    /// Flushes the encoder and ends the file; nothing may be added afterwards.
    void finish();

private:
    std::unique_ptr<video_sink> sink_;
};

/// Where the program at `program` loads the video module from, fixed when it was built:
/// the build directory for the build's program, LIBDIR/pendulum-figures of the installation
/// (or of the Debian package, for /usr/bin/pendulum-figures) for any other. Never beside a
/// copy of the program, where a repository could have put a module of its own.
std::filesystem::path video_module_path(const std::filesystem::path& program);

/// Why a module file with `file`'s status in a directory with `dir`'s may not be loaded
/// (empty if it may): not a regular file, owned by someone other than root or this user, or
/// it or its directory writable by its group or by others.
std::string module_file_problem(const struct stat& file, const struct stat& dir);

/// The frame rate as libavformat takes it: a fraction that is fps within 1e-6.
std::pair<int, int> video_frame_rate(double fps);

}  // namespace plot
