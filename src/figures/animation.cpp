// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/animation.hpp"

#include "figures/spec_build.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/exact.hpp"
#include "plot/frames.hpp"
#include "plot/gif.hpp"
#include "plot/output.hpp"

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

namespace figures {

namespace {

/// The first amplitude of the (overridden) panels: its exact period is the animation's unit.
double reference_amplitude(const std::vector<panel_spec>& panels) {
    for (const auto& p : panels) {
        if (!p.theta0.empty()) return p.theta0.front().value;
    }
    throw std::invalid_argument("an animation needs a panel with theta0 (a pendulum, trajectory or phase panel)");
}

std::string clock_text(const animation_plan& plan, double w0_t) {
    char buf[64];
    if (plan.physical) {
        std::snprintf(buf, sizeof buf, "<i>t</i> = %.2f s", w0_t * plan.seconds_per_unit);
    } else {
        std::snprintf(buf, sizeof buf, "<i>t</i> = %.2f <i>T</i>", w0_t / plan.reference_period);
    }
    return buf;
}

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

animation_plan plan_animation(const entry& e, const build_options& options) {
    if (!e.spec.animation) throw std::invalid_argument("figure '" + e.id + "' is not an animation");
    const animation_spec& a = *e.spec.animation;
    animation_plan plan;
    plan.fps = a.fps;
    plan.physical = e.spec.pendulum.has_value();
    const double length = plan.physical ? e.spec.pendulum->length_m : 1.0;
    const double g = plan.physical ? e.spec.pendulum->g : 9.80665;
    plan.seconds_per_unit = std::sqrt(length / g);
    const pendulum::exact_solution exact(reference_amplitude(panels_of(e, options)));
    plan.reference_period = 4 * exact.quarter_period();
    const double span = a.duration_s ? *a.duration_s / plan.seconds_per_unit : a.periods.value_or(1.0) * plan.reference_period;
    // Playback: `speed` seconds of the pendulum's time per second shown.
    const double shown_s = span * plan.seconds_per_unit / a.speed;
    const double frames = std::floor(shown_s * a.fps + 1e-9) + 1;
    if (frames > max_frames) {
        throw std::invalid_argument("animation '" + e.id + "' would have " + pendulum::format_double(frames) +
                                    " frames; at most " + std::to_string(max_frames) +
                                    " (lower fps, periods or duration_s, or raise speed)");
    }
    plan.frames = static_cast<int>(frames);
    plan.step = a.speed / a.fps / plan.seconds_per_unit;
    return plan;
}

plot::figure animation_frame(const entry& e, const build_options& options, const animation_plan& plan,
                             const plot::figure& base, double w0_t) {
    plot::figure f = base;
    const auto panels = panels_of(e, options);
    add_frame_state(f, e.spec, panels, w0_t);
    if (e.spec.animation && e.spec.animation->clock && !f.panels.empty()) {
        // The clock goes on the pendulum, or on the first panel.
        std::size_t at = 0;
        for (std::size_t i = 0; i < panels.size(); ++i) {
            if (panels[i].plot == plot_kind::pendulum) {
                at = i;
                break;
            }
        }
        f.panels[at].overlay_label = clock_text(plan, w0_t);
    }
    return f;
}

bool is_animation_format(std::string_view format) { return format == "gif" || format == "pdf" || format == "png"; }

void write_animation(const entry& e, const build_options& options, const plot::theme& theme, std::string_view format,
                     const std::filesystem::path& dir, double dpi, int first, int last) {
    const animation_plan plan = plan_animation(e, options);
    if (first < 0 || last >= plan.frames || first > last) {
        throw std::invalid_argument("frames " + std::to_string(first + 1) + ".." + std::to_string(last + 1) +
                                    " are outside animation '" + e.id + "', which has frames 1.." +
                                    std::to_string(plan.frames));
    }
    build_options still = options;
    still.animated = true;
    still.panel_width_cm = theme.panel_width_cm;
    still.panel_aspect = theme.panel_aspect;
    const plot::figure base = build(e, still);
    const auto frame = [&](int i) { return animation_frame(e, still, plan, base, plan.time(i)); };
    if (format == "pdf") {
        const std::string bytes =
            plot::render_pdf_pages(last - first + 1, [&](int i) { return frame(first + i); }, theme);
        plot::write_atomically(dir / (e.id + ".pdf"), bytes);
        return;
    }
    if (format == "png") {
        const int digits = std::max(4, static_cast<int>(std::to_string(plan.frames).size()));
        in_order<int>(first, last,
                      [&](int i) {
                          char number[16];
                          std::snprintf(number, sizeof number, "-%0*d.png", digits, i + 1);
                          plot::write_atomically(dir / (e.id + number),
                                                 plot::render(frame(i), theme, "png", plot::output_options{dpi}));
                          return i;
                      },
                      [](int, int) {});
        return;
    }
    if (format != "gif") throw std::invalid_argument("an animation is written as gif, pdf or png");
    // The palette: the theme's colours and their anti-aliasing shades over the background.
    std::vector<plot::rgb> inks = theme.palette;
    inks.push_back(theme.foreground);
    // Variables, not a structured binding: the writers below capture them, which clang
    // before 16 does not allow of a binding.
    const std::pair<int, int> pixels = plot::pixel_size(base, theme, dpi);
    const int width = pixels.first;
    const int height = pixels.second;
    const auto palette = plot::gif_palette(inks, theme.background, 16);
    // What stays is drawn once; each frame draws what moves over a copy of it.
    const plot::argb_image still_image = plot::render_argb(frame(first), theme, dpi, plot::draw_pass::still);
    const auto draw = [&](int i) {
        return plot::render_argb(frame(i), theme, dpi, plot::draw_pass::overlay, &still_image);
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
                plot::gif_encoder gif(width, height, palette, plan.fps, from - first);
                if (from > first) {
                    const auto before = draw(from - 1);
                    gif.prime(before.data.data(), before.stride);
                }
                for (int i = from; i <= to; ++i) {
                    const auto image = draw(i);
                    gif.add_frame(image.data.data(), image.stride);
                }
                const std::size_t head_size = gif.head_size();
                auto [h, frames] = plot::gif_encoder::split(gif.finish(), head_size);
                parts[static_cast<std::size_t>(r)] = std::move(frames);
                if (r == 0) head = std::move(h);
            } catch (...) {
                errors[static_cast<std::size_t>(r)] = std::current_exception();
            }
        });
    }
    for (auto& t : threads) t.join();
    for (const auto& e : errors) {
        if (e) std::rethrow_exception(e);
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
    plot::write_atomically(dir / (e.id + ".gif"), bytes);
}

}  // namespace figures
