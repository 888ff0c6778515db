// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/render_plan.hpp"

#include "figures/render_cost.hpp"
#include "figures/spec_build.hpp"
#include "pendulum/amplitude.hpp"
#include "plot/frames.hpp"
#include "plot/gif.hpp"
#include "plot/streamed_file.hpp"
#include "plot/video.hpp"
#include "plot/workers.hpp"

#include <algorithm>
#include <exception>
#include <map>
#include <stdexcept>

namespace figures {

entry load_input(std::string_view id_or_file) {
    entry e;
    try {
        e = load(id_or_file);
    } catch (const spec_error& err) {
        throw bad_input(std::string("bad figure spec:\n") + err.what());
    }
    // Built once, as data and describe build it: refused before any work if too costly.
    check_cost({costed_figure{&e, 0, {"svg"}, 0}}, {});
    return e;
}

std::vector<const entry*> selected_figures(const std::vector<std::string>& ids, bool all,
                                           std::deque<entry>& loaded) {
    if (!all && ids.empty()) throw bad_input("name the figures to render, or use --all (see 'list')");
    std::vector<const entry*> chosen;
    if (all) {
        // Every still figure; animations are rendered by name.
        for (const auto& e : catalog()) {
            if (!e.spec.animation) chosen.push_back(&e);
        }
    }
    for (const auto& id : ids) {
        const entry* e = id.ends_with(".toml") ? &loaded.emplace_back(load_input(id)) : &find(id);
        const auto same = std::find_if(chosen.begin(), chosen.end(), [&](const auto* c) { return c->id == e->id; });
        if (same != chosen.end()) {
            // The same figure twice is drawn once; two different ones cannot share file names.
            if ((*same)->source != e->source) {
                throw bad_input("two different figures are named '" + e->id + "' and would write the same files");
            }
            continue;
        }
        chosen.push_back(e);
    }
    return chosen;
}

void check_raster_sizes(const std::vector<const entry*>& figures, const std::vector<std::string>& formats,
                        const build_options& build, const render_style& style) {
    for (const auto* e : figures) {
        const bool moving = e->spec.animation.has_value();
        const plot::theme& th = moving ? style.moving_theme : style.still_theme;
        const build_options grid = sized_by(build, th);
        for (const auto& f : formats) {
            if (!plot::find_format(f).raster) continue;
            // Outside the try: the figure's own bad input is not one of the format's.
            const plot::figure layout = figure_grid(e->spec, grid);
            try {
                const double dpi = moving ? style.moving.dpi : style.still.dpi;
                plot::check_raster_size(layout, th, dpi);
                const auto [w, h] = plot::pixel_size(layout, th, dpi);
                plot::check_worker_memory(plot::raster_bytes_per_pixel * w * h, "a raster of " + std::to_string(w) +
                                          " x " + std::to_string(h) + " pixels", "lower --dpi or size_px");
            } catch (const plot::bad_input& err) {
                throw bad_input(e->id + "." + f + ": " + err.what());
            }
        }
    }
}

namespace {

/// The pixels of one raster of the figure, 0 if no format is a raster.
double raster_pixels(const entry& e, const std::vector<std::string>& formats, const build_options& build,
                     const plot::theme& theme, double dpi) {
    if (std::none_of(formats.begin(), formats.end(), [](const auto& f) { return plot::find_format(f).raster; })) {
        return 0;
    }
    const auto [w, h] = plot::pixel_size(figure_grid(e.spec, sized_by(build, theme)), theme, dpi);
    return static_cast<double>(w) * h;
}

/// A group's figures as the cost estimate takes them: each still figure with its files, each
/// animation with its frames (one with --at) in every format.
std::vector<costed_figure> costed(const std::vector<figure_file>& stills, const std::vector<animation_job>& animations,
                                  const std::vector<std::string>& formats, const build_options& build,
                                  const render_style& style, bool at) {
    std::vector<costed_figure> out;
    for (const auto& f : stills) {
        auto same = std::find_if(out.begin(), out.end(), [&](const auto& c) { return c.figure == f.figure; });
        if (same == out.end()) {
            out.push_back({f.figure, 0, {}, raster_pixels(*f.figure, formats, build, style.still_theme, style.still.dpi)});
            same = out.end() - 1;
        }
        std::string ext = f.path.extension().string();
        same->formats.push_back(ext.empty() ? ext : ext.substr(1));
    }
    for (const auto& m : animations) {
        const double pixels = raster_pixels(*m.figure, formats, build, style.moving_theme, style.moving.dpi);
        out.push_back({m.figure, at ? 1 : m.last - m.first + 1, formats, pixels});
    }
    return out;
}

}  // namespace

void check_render_cost(const std::vector<std::vector<figure_file>>& stills,
                       const std::vector<std::vector<animation_job>>& animations,
                       const std::vector<std::string>& formats, const build_options& build,
                       const std::vector<render_style>& styles, bool at) {
    // The specific limits first (an animation's pixels, a video's memory), then the whole.
    if (!at) {
        for (std::size_t g = 0; g < styles.size() && g < animations.size(); ++g) {
            check_animation_work(animations[g], formats, build, styles[g]);
        }
    }
    std::vector<costed_figure> all;
    for (std::size_t g = 0; g < styles.size(); ++g) {
        const auto group = costed(g < stills.size() ? stills[g] : std::vector<figure_file>{},
                                  g < animations.size() ? animations[g] : std::vector<animation_job>{}, formats, build,
                                  styles[g], at);
        all.insert(all.end(), group.begin(), group.end());
    }
    check_cost(all, build);
}

std::string render_one(const entry& e, const build_options& build, const plot::theme& theme,
                       std::string_view format, const plot::output_options& output) {
    const build_options one = sized_by(build, theme);
    plot::check_raster_size(figure_grid(e.spec, one), theme, output.dpi);
    check_cost({costed_figure{&e, 0, {std::string(format)}, raster_pixels(e, {std::string(format)}, build, theme, output.dpi)}},
               build);
    return plot::render(figures::build(e, one), theme, format, output);
}

namespace {

/// A list of output files, each with what writes it.
using output_list = std::vector<std::pair<std::filesystem::path, std::string>>;

/// A still file, and its drawing under the drawing format's name for an overlay format.
void add_still_outputs(output_list& outputs, const figure_file& f) {
    const std::string what = f.panel < 0 ? "figure '" + f.figure->id + "'"
                                         : "figure '" + f.figure->id + "' panel " + std::to_string(f.panel + 1);
    outputs.emplace_back(f.path, what);
    std::string ext = f.path.extension().string();
    if (!ext.empty()) ext.erase(0, 1);
    const plot::format_row& row = plot::find_format(ext);
    if (!row.graphics.empty()) {
        auto drawing = f.path;
        outputs.emplace_back(drawing.replace_extension(row.graphics), what + " (the drawing under its " + ext + ")");
    }
}

/// An animation's files in one format: its frame files (each once), or one file (with its
/// drawing for an overlay format) for a moving format or one frame (--at).
void add_animation_outputs(output_list& outputs, const animation_job& m, const std::string& f,
                           const std::filesystem::path& dir, bool at) {
    const plot::format_row& row = plot::find_format(f);
    const std::string what = "animation '" + m.figure->id + "' as " + f;
    if (!at && row.animate) {
        std::string previous;
        for (int i = m.first; i <= m.last; ++i) {
            const std::string name = row.frame_file(m.figure->id, i, m.plan.frames);
            if (name != previous) outputs.emplace_back(dir / name, what);
            previous = name;
        }
        return;
    }
    outputs.emplace_back(dir / (m.figure->id + "." + f), what);
    if (!row.graphics.empty()) outputs.emplace_back(dir / (m.figure->id + "." + std::string(row.graphics)), what);
}

}  // namespace

std::vector<std::pair<std::filesystem::path, std::string>> render_outputs(const std::vector<figure_file>& stills,
                                                                      const std::vector<animation_job>& animations,
                                                                      const std::vector<std::string>& formats,
                                                                      const std::filesystem::path& dir, bool at) {
    output_list outputs;
    for (const auto& f : stills) add_still_outputs(outputs, f);
    for (const auto& m : animations) {
        for (const auto& f : formats) add_animation_outputs(outputs, m, f, dir, at);
    }
    return outputs;
}

void check_distinct_outputs(const std::vector<figure_file>& stills, const std::vector<animation_job>& animations,
                            const std::vector<std::string>& formats, const std::filesystem::path& dir, bool at) {
    std::map<std::filesystem::path, std::string> seen;
    for (const auto& [path, what] : render_outputs(stills, animations, formats, dir, at)) {
        const auto [it, fresh] = seen.emplace(path.lexically_normal(), what);
        if (!fresh) {
            throw bad_input("two outputs of this render are " + path.string() + ": " + it->second + " and " + what +
                            "; give them different names (paper_file, or the spec file's name)");
        }
    }
}

void check_animation_work(const std::vector<animation_job>& animations, const std::vector<std::string>& formats,
                          const build_options& build, const render_style& style) {
    for (const auto& m : animations) {
        const build_options grid = sized_by(build, style.moving_theme);
        const auto [w, h] = plot::pixel_size(figure_grid(m.figure->spec, grid), style.moving_theme, style.moving.dpi);
        const double frames = m.last - m.first + 1;
        const double pixels = frames * w * h;
        for (const auto& f : formats) {
            const plot::format_row& row = plot::find_format(f);
            try {
                if (f == "mp4") plot::check_video_memory(plot::mp4_video, w, h);
                if (f == "webm") plot::check_video_memory(plot::webm_video, w, h);
                // Beyond every animation's bound, that bound's message.
                if (f == "gif" && pixels <= max_animation_pixels) plot::check_gif_size(frames, w, h);
            } catch (const plot::bad_input& err) {
                throw bad_input(m.figure->id + "." + f + ": " + err.what());
            }
            if (!row.raster || !row.animate || pixels <= max_animation_pixels) continue;
            throw bad_input(m.figure->id + "." + f + ": " + pendulum::format_double(frames) + " frames of " +
                            std::to_string(w) + " x " + std::to_string(h) + " pixels are " +
                            pendulum::format_double(pixels) + " pixels; an animation has at most " +
                            pendulum::format_double(max_animation_pixels) +
                            " (lower --dpi, fewer frames with --frames, or a lower fps or duration)");
        }
    }
}

/// Throws bad_input if a format cannot play an animation at its frame rate.
void check_frame_rates(const std::vector<animation_job>& animations, const std::vector<std::string>& formats) {
    for (const auto& m : animations) {
        for (const auto& f : formats) {
            const plot::format_row& row = plot::find_format(f);
            if (!row.animate || !row.check_frame_rate) continue;
            try {
                row.check_frame_rate(m.plan.fps);
            } catch (const plot::bad_input& err) {
                throw bad_input(m.figure->id + "." + f + ": " + err.what());
            }
        }
    }
}

/// Throws bad_input, before any file is written, if a still figure or one frame of an
/// animation (--at) is asked for in a format that holds animations only (a video).
void check_still_formats(const std::vector<figure_file>& stills, const std::vector<animation_job>& animations,
                         const std::vector<std::string>& formats, bool at) {
    const auto check = [](const std::string& id, const std::string& format) {
        try {
            plot::check_still_format(format);
        } catch (const plot::bad_input& err) {
            throw bad_input(id + "." + format + ": " + err.what());
        }
    };
    for (const auto& f : stills) {
        std::string ext = f.path.extension().string();
        if (!ext.empty()) ext.erase(0, 1);
        check(f.figure->id, ext);
    }
    for (const auto& m : animations) {
        for (const auto& f : formats) {
            if (at || !plot::find_format(f).animate) check(m.figure->id, f);
        }
    }
}

namespace {

/// write_render's files, each as it is finished.
void write_files(const std::vector<figure_file>& stills, const std::vector<animation_job>& animations,
                 const std::vector<std::string>& formats, const std::filesystem::path& dir,
                 const build_options& build, const render_style& style, std::optional<double> at) {
    if (!stills.empty()) write_figures(stills, build, style.still_theme, style.still);
    for (const auto& m : animations) {
        for (const auto& f : formats) {
            const plot::format_row& row = plot::find_format(f);
            if (!at && row.animate) {
                write_animation(*m.figure, build, style.moving_theme, row, dir, style.moving, m.first, m.last);
                continue;
            }
            // A format that holds no animation, or --at: one frame.
            build_options still = sized_by(build, style.moving_theme);
            still.animated = true;
            const double w0_t = at ? *at * m.plan.reference_period : m.plan.time(m.first);
            const auto frame = animation_frame(*m.figure, still, m.plan, figures::build(*m.figure, still), w0_t);
            plot::save(frame, style.moving_theme, dir / (m.figure->id + "." + f), style.moving);
        }
    }
}

}  // namespace

void write_render(const std::vector<figure_file>& stills, const std::vector<animation_job>& animations,
                  const std::vector<std::string>& formats, const std::filesystem::path& dir,
                  const build_options& build, const render_style& style, std::optional<double> at) {
    check_still_formats(stills, animations, formats, at.has_value());
    check_distinct_outputs(stills, animations, formats, dir, at.has_value());
    if (!at) {
        check_frame_rates(animations, formats);
        check_animation_work(animations, formats, build, style);
    }
    check_render_cost({stills}, {animations}, formats, build, {style}, at.has_value());
    // The files are synced together and then renamed, when all are written; on a failure,
    // those finished before it are kept, as they would have been one by one, and the
    // failure is what is reported.
    plot::durable_batch batch;
    try {
        write_files(stills, animations, formats, dir, build, style, at);
    } catch (...) {
        const auto error = std::current_exception();
        try {
            batch.commit();
        } catch (...) {  // the first failure is the one to report
        }
        std::rethrow_exception(error);
    }
    batch.commit();
}

}  // namespace figures
