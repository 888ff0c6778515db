// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/animation_writers.hpp"

#include "plot/frames.hpp"
#include "plot/gif.hpp"
#include "plot/video.hpp"

#include <algorithm>
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

/// Runs draw(i) for every frame i in [first, last] on all cores and hands the results to
/// use(i, result) in order, holding at most a few results at a time.
template <class Result, class Draw, class Use>
void in_order(int first, int last, Draw draw, Use use) {
    const unsigned workers = std::max(1u, std::thread::hardware_concurrency());
    const int window = static_cast<int>(2 * workers);
    std::mutex mutex;
    std::condition_variable changed;
    std::deque<std::optional<Result>> ready(static_cast<std::size_t>(window));
    int next = first;       // next frame to draw
    int consumed = first;   // next frame to use
    std::exception_ptr error;
    auto worker = [&] {
        for (;;) {
            int i = 0;
            {
                std::unique_lock lock(mutex);
                changed.wait(lock, [&] { return error || next > last || next < consumed + window; });
                if (error || next > last) return;
                i = next++;
            }
            std::optional<Result> result;
            std::exception_ptr failure;
            try {
                result.emplace(draw(i));
            } catch (...) {
                failure = std::current_exception();
            }
            std::lock_guard lock(mutex);
            if (failure && !error) error = failure;
            ready[static_cast<std::size_t>(i % window)] = std::move(result);
            changed.notify_all();
        }
    };
    std::vector<std::thread> threads;
    for (unsigned k = 0; k < workers; ++k) threads.emplace_back(worker);
    try {
        for (int i = first; i <= last; ++i) {
            Result result;
            {
                std::unique_lock lock(mutex);
                changed.wait(lock, [&] { return error || ready[static_cast<std::size_t>(i % window)].has_value(); });
                if (error) break;
                result = std::move(*ready[static_cast<std::size_t>(i % window)]);
                ready[static_cast<std::size_t>(i % window)].reset();
            }
            use(i, std::move(result));
            std::lock_guard lock(mutex);
            ++consumed;
            changed.notify_all();
        }
    } catch (...) {
        std::lock_guard lock(mutex);
        if (!error) error = std::current_exception();
        changed.notify_all();
    }
    {
        std::lock_guard lock(mutex);
        if (!error && consumed <= last) error = std::make_exception_ptr(std::logic_error("frames left unused"));
        next = last + 1;
        changed.notify_all();
    }
    for (auto& t : threads) t.join();
    if (error) std::rethrow_exception(error);
}

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
    const auto draw = [&](int i) {
        return render_argb(frames.frame(i), th, dpi, draw_pass::overlay, &still_image);
    };
    // Each core encodes a run of consecutive frames on its own (starting from the frame
    // before its run); the runs join in order into one file.
    const int count = last - first + 1;
    const int runs = std::max(1, std::min(count, static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))));
    std::vector<std::string> parts(static_cast<std::size_t>(runs));
    std::string head;
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(runs));
    std::vector<std::thread> threads;
    for (int r = 0; r < runs; ++r) {
        threads.emplace_back([&, r] {
            try {
                const int from = first + static_cast<int>(static_cast<long long>(count) * r / runs);
                const int to = first + static_cast<int>(static_cast<long long>(count) * (r + 1) / runs) - 1;
                gif_encoder gif(width, height, palette, frames.fps, from - first);
                if (from > first) {
                    const auto before = draw(from - 1);
                    gif.prime(before.data.data(), before.stride);
                }
                for (int i = from; i <= to; ++i) {
                    const auto image = draw(i);
                    gif.add_frame(image.data.data(), image.stride);
                }
                const std::size_t head_size = gif.head_size();
                auto [h, body] = gif_encoder::split(gif.finish(), head_size);
                parts[static_cast<std::size_t>(r)] = std::move(body);
                if (r == 0) head = std::move(h);
            } catch (...) {
                errors[static_cast<std::size_t>(r)] = std::current_exception();
            }
        });
    }
    for (auto& t : threads) t.join();
    for (const auto& error : errors) {
        if (error) std::rethrow_exception(error);
    }
    std::size_t size = head.size() + 1;
    for (const auto& p : parts) size += p.size();
    std::string bytes = std::move(head);
    bytes.reserve(size);
    for (auto& p : parts) {
        bytes += p;
        std::string().swap(p);  // each part's memory goes as soon as it is copied
    }
    bytes += ';';
    write_atomically(dir / gif_animation_file(id, frames.first, frames.count), bytes);
}

void write_pdf_animation(const animation_frames& frames, const theme& th, const std::filesystem::path& dir,
                         const std::string& id, const output_options&) {
    const std::string bytes =
        render_pdf_pages(frames.last - frames.first + 1, [&](int i) { return frames.frame(frames.first + i); }, th);
    write_atomically(dir / pdf_animation_file(id, frames.first, frames.count), bytes);
}

void write_png_animation(const animation_frames& frames, const theme& th, const std::filesystem::path& dir,
                         const std::string& id, const output_options& options) {
    in_order<int>(frames.first, frames.last,
                  [&](int i) {
                      write_atomically(dir / png_frame_file(id, i, frames.count),
                                       render(frames.frame(i), th, "png", output_options{options.dpi}));
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
    write_atomically_by(dir / name, [&](const std::filesystem::path& file) {
        video_encoder video(file, name, kind, width, height, frames.fps);
        in_order<video_frame>(
            frames.first, frames.last,
            [&](int i) {
                return video.convert(render_argb(frames.frame(i), th, options.dpi, draw_pass::overlay, &still_image));
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
