// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/animation_writers.hpp"

#include "plot/frames.hpp"
#include "plot/gif.hpp"
#include "plot/streamed_file.hpp"
#include "plot/video.hpp"
#include "plot/workers.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

namespace plot {

namespace {

/// The shared state of in_order: which index is drawn next and which used next, the
/// results drawn and not yet used (a window of them), and the first failure.
template <class Result>
class ordered_results {
public:
    ordered_results(int first, int last, int window)
        : last_(last), window_(window), ready_(static_cast<std::size_t>(window)), next_(first), consumed_(first) {}

    /// A worker's loop: draws the next index within the window until all are drawn or one failed.
    template <class Draw>
    void work(Draw& draw) {
        for (;;) {
            int i = 0;
            {
                std::unique_lock lock(mutex_);
                changed_.wait(lock, [&] { return error_ || next_ > last_ || next_ < consumed_ + window_; });
                if (error_ || next_ > last_) return;
                i = next_++;
            }
            std::optional<Result> result;
            std::exception_ptr failure;
            try {
                result.emplace(draw(i));
            } catch (...) {
                failure = std::current_exception();
            }
            std::lock_guard lock(mutex_);
            if (failure && !error_) error_ = failure;
            slot(i) = std::move(result);
            changed_.notify_all();
        }
    }

    /// The result of index i once drawn, or nothing if a worker failed.
    std::optional<Result> take(int i) {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return error_ || slot(i).has_value(); });
        if (error_) return std::nullopt;
        std::optional<Result> result = std::move(slot(i));
        slot(i).reset();
        return result;
    }

    /// Index i used: its place in the window is free.
    void used() {
        std::lock_guard lock(mutex_);
        ++consumed_;
        changed_.notify_all();
    }

    /// A failure while using a result stops the workers.
    void fail(std::exception_ptr e) {
        std::lock_guard lock(mutex_);
        if (!error_) error_ = std::move(e);
        changed_.notify_all();
    }

    /// Stops the workers; returns the first failure (a result left unused is one).
    std::exception_ptr finish() {
        std::lock_guard lock(mutex_);
        if (!error_ && consumed_ <= last_) error_ = std::make_exception_ptr(std::logic_error("frames left unused"));
        next_ = last_ + 1;
        changed_.notify_all();
        return error_;
    }

private:
    std::optional<Result>& slot(int i) { return ready_[static_cast<std::size_t>(i % window_)]; }

    const int last_;
    const int window_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<std::optional<Result>> ready_;
    int next_;      // next index to draw
    int consumed_;  // next index to use
    std::exception_ptr error_;
};

/// Runs draw(i) for every i in [first, last] on `jobs` workers (0: one per usable CPU) and
/// hands the results to use(i, result) in order, holding at most a few results at a time.
template <class Result, class Draw, class Use>
void in_order(int first, int last, unsigned jobs, Draw draw, Use use) {
    const unsigned workers = worker_count(jobs, static_cast<std::size_t>(last - first + 1));
    ordered_results<Result> results(first, last, static_cast<int>(2 * workers));
    std::vector<std::thread> threads;
    for (unsigned k = 0; k < workers; ++k) threads.emplace_back([&] { results.work(draw); });
    try {
        for (int i = first; i <= last; ++i) {
            std::optional<Result> result = results.take(i);
            if (!result) break;
            use(i, std::move(*result));
            results.used();
        }
    } catch (...) {
        results.fail(std::current_exception());
    }
    const std::exception_ptr error = results.finish();
    for (auto& t : threads) t.join();
    if (error) std::rethrow_exception(error);
}

/// Frames per part of a GIF encoded on its own: parts enough to keep every worker busy to
/// the end, each costing one frame drawn twice (the one before it), and few enough pixels
/// per part that a part's bytes stay small at any size.
int frames_per_part(int count, unsigned workers, double pixels) {
    const int most = std::max(4, static_cast<int>(32.0 * 1024 * 1024 / pixels));
    return std::clamp(count / static_cast<int>(4 * workers), 1, most);
}

/// A worker's frame buffer, reused from part to part: a new one per frame is mapped and
/// unmapped by the allocator when it is large, and the frame it holds last is the one before
/// the next part when that part goes to the same worker.
struct worker_frame {
    argb_image image;
    unsigned long animation = 0;  // whose frame it holds (a number per animation, from 1)
    int frame = -1;               // which
};

thread_local worker_frame gif_worker_frame;
std::atomic<unsigned long> gif_animations{0};

}  // namespace

void write_gif_animation(const animation_frames& frames, const theme& th, const std::filesystem::path& dir,
                         const std::string& id, const output_options& options) {
    const int first = frames.first;
    const int last = frames.last;
    const double dpi = options.dpi;
    // The palette: the theme's colours and their anti-aliasing shades over the background.
    std::vector<rgb> inks = th.palette;
    inks.push_back(th.foreground);
    const figure first_frame = frames.frame(first);
    // Plain variables, not a structured binding: the threads below capture them.
    const std::pair<int, int> pixels = pixel_size(first_frame, th, dpi);
    const int width = pixels.first;
    const int height = pixels.second;
    const auto palette = gif_palette(inks, th.background, 16);
    // What stays is drawn once; each frame draws what moves over a copy of it.
    const argb_image still_image = render_argb(first_frame, th, dpi, draw_pass::still);
    // The frames are encoded in parts of consecutive frames, each part on its own from the
    // frame before it (a frame stores what changed since that one, so the bytes are those of
    // one encoder doing all), several parts at a time; finished parts go to the file in
    // order, so memory stays the same at any length.
    const int count = last - first + 1;
    const unsigned workers =
        workers_for_frames(worker_count(options.jobs, static_cast<std::size_t>(count)), still_image.data.size());
    const int part_frames = frames_per_part(count, workers, static_cast<double>(width) * height);
    const int parts = (count + part_frames - 1) / part_frames;
    streamed_file file(dir / gif_animation_file(id, frames.first, frames.count));
    const unsigned long animation = ++gif_animations;
    std::size_t written = 0;
    struct part {
        std::string head;  // the file's head, kept from the first part only
        std::string body;  // the part's frames
    };
    in_order<part>(0, parts - 1, workers,
                   [&](int p) {
                       const int from = first + p * part_frames;
                       const int to = std::min(last, from + part_frames - 1);
                       worker_frame& mine = gif_worker_frame;
                       if (mine.animation != animation) mine.frame = -1;
                       mine.animation = animation;
                       const auto draw = [&](int i) {
                           if (mine.frame != i) {
                               mine.frame = -1;  // until it is drawn
                               render_argb(mine.image, frames.frame(i), th, dpi, draw_pass::overlay, &still_image);
                               mine.frame = i;
                           }
                       };
                       gif_encoder gif(width, height, palette, frames.fps, from - first);
                       gif.keep_against(still_image.data.data(), still_image.stride);
                       if (from > first) {
                           draw(from - 1);
                           gif.prime(mine.image.data.data(), mine.image.stride);
                       }
                       for (int i = from; i <= to; ++i) {
                           draw(i);
                           gif.add_frame(mine.image.data.data(), mine.image.stride);
                       }
                       const std::size_t head_size = gif.head_size();
                       auto [head, body] = gif_encoder::split(gif.finish(), head_size);
                       return part{p == 0 ? std::move(head) : std::string(), std::move(body)};
                   },
                   [&](int p, part done) {
                       // The bound checked before the work is an estimate from the built-ins'
                       // rates: the bytes themselves are held to it as they are written.
                       written += done.head.size() + done.body.size();
                       check_gif_written(written + 1, std::min(last, first + (p + 1) * part_frames - 1) - first + 1,
                                         count, width, height);
                       file.write(done.head);
                       file.write(done.body);
                   });
    file.write(";");
    file.commit();
}

void write_pdf_animation(const animation_frames& frames, const theme& th, const std::filesystem::path& dir,
                         const std::string& id, const output_options&) {
    // Page by page into the file, as a GIF's parts are: memory stays the same at any length.
    streamed_file file(dir / pdf_animation_file(id, frames.first, frames.count));
    render_pdf_pages(
        frames.last - frames.first + 1, [&](int i) { return frames.frame(frames.first + i); }, th,
        [&](std::string_view bytes) { file.write(bytes); });
    file.commit();
}

void write_png_animation(const animation_frames& frames, const theme& th, const std::filesystem::path& dir,
                         const std::string& id, const output_options& options) {
    // Each frame is drawn whole, as the still PNG of that figure is, into a worker's buffers:
    // as many workers as the memory budget holds.
    const auto [width, height] = pixel_size(frames.frame(frames.first), th, options.dpi);
    const unsigned jobs =
        workers_within_budget(worker_count(options.jobs, static_cast<std::size_t>(frames.last - frames.first + 1)),
                              raster_bytes_per_pixel * width * height);
    in_order<int>(frames.first, frames.last, jobs,
                  [&](int i) {
                      // A worker's buffers, reused: a large one is mapped and unmapped by the
                      // allocator at every frame otherwise.
                      thread_local argb_image image;
                      thread_local std::vector<unsigned char> rows;
                      render_rgb24(image, frames.frame(i), th, options.dpi);
                      write_atomically(dir / png_frame_file(id, i, frames.count), png_of_pixels(image, options.dpi, rows));
                      return i;
                  },
                  [](int, int) {});
}

namespace {

/// DIR/ID.EXT as a video of the kind: frames drawn on every core, at most a few at a time
/// waiting, converted where they are drawn and encoded in order.
void write_video_animation(const animation_frames& frames, const theme& th, const std::filesystem::path& dir,
                           const std::string& id, const output_options& options, video_kind kind) {
    const figure first_frame = frames.frame(frames.first);
    // Plain variables, not a structured binding: the lambda below captures them.
    const std::pair<int, int> pixels = pixel_size(first_frame, th, options.dpi);
    const int width = pixels.first;
    const int height = pixels.second;
    // What stays is drawn once; each frame draws what moves over a copy of it.
    const argb_image still_image = render_argb(first_frame, th, options.dpi, draw_pass::still);
    const std::string name = id + "." + kind.container;
    // As many workers as the encoder's memory leaves room for (check_video_memory: one at least).
    const video_settings settings = video_settings_for(kind, width, height);
    unsigned workers = worker_count(options.jobs, static_cast<std::size_t>(frames.last - frames.first + 1));
    while (workers > 1 && video_memory(kind, width, height, settings, workers) > raster_budget_bytes) --workers;
    write_atomically_by(dir / name, [&](const std::filesystem::path& file) {
        video_encoder video(file, name, kind, width, height, frames.fps);
        // Frames are the still with what moves over it: only what moved is converted.
        video.keep_against(still_image);
        in_order<video_frame>(
            frames.first, frames.last, workers,
            [&](int i) {
                // A worker's frame buffer, reused: a large one is mapped and unmapped by the
                // allocator at every frame otherwise.
                thread_local argb_image image;
                render_argb(image, frames.frame(i), th, options.dpi, draw_pass::overlay, &still_image);
                return video.convert(image);
            },
            [&](int, video_frame frame) { video.add(std::move(frame)); });
        video.finish();
    });
}

}  // namespace

void write_mp4_animation(const animation_frames& frames, const theme& th, const std::filesystem::path& dir,
                         const std::string& id, const output_options& options) {
    write_video_animation(frames, th, dir, id, options, mp4_video);
}

void write_webm_animation(const animation_frames& frames, const theme& th, const std::filesystem::path& dir,
                          const std::string& id, const output_options& options) {
    write_video_animation(frames, th, dir, id, options, webm_video);
}

std::string mp4_animation_file(const std::string& id, int, int) { return id + ".mp4"; }

std::string webm_animation_file(const std::string& id, int, int) { return id + ".webm"; }

std::string gif_animation_file(const std::string& id, int, int) { return id + ".gif"; }

std::string pdf_animation_file(const std::string& id, int, int) { return id + ".pdf"; }

std::string png_frame_file(const std::string& id, int frame, int count) {
    const std::size_t digits = std::max<std::size_t>(4, std::to_string(count).size());
    std::string number = std::to_string(frame + 1);
    if (number.size() < digits) number.insert(0, digits - number.size(), '0');
    return id + "-" + number + ".png";
}

}  // namespace plot
