// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a render means once its options are read: which figures, whether their rasters
// fit, and which files each figure and animation becomes.

#include "figures/animation.hpp"
#include "figures/batch.hpp"
#include "figures/catalog.hpp"
#include "plot/output.hpp"
#include "plot/theme.hpp"

#include <deque>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace figures {

/// A built-in figure or a spec file, as load() reads it, with a bad spec or an unreadable
/// file thrown as bad_input (the user's to correct).
entry load_input(std::string_view id_or_file);

/// The figures a render names (ids, aliases or spec files), each once, after every still
/// figure with `all`; spec files are read into `loaded`, which must outlive the result.
/// Throws bad_input for none at all, or for two different figures of one id.
std::vector<const entry*> selected_figures(const std::vector<std::string>& ids, bool all,
                                           std::deque<entry>& loaded);

/// How the files of a render look: still figures with one theme and output options,
/// animations with another.
struct render_style {
    plot::theme still_theme;      ///< still figures' theme
    plot::output_options still;   ///< still figures' dpi, overlay text, force
    plot::theme moving_theme;     ///< animations' theme
    plot::output_options moving;  ///< animations' dpi, overlay text, force
};

/// Throws bad_input, naming the file, if a figure in a raster format would be larger than
/// plot's limits: checked before any work.
void check_raster_sizes(const std::vector<const entry*>& figures, const std::vector<std::string>& formats,
                        const build_options& build, const render_style& style);

/// One still figure in one format, as bytes (for standard output), its raster size checked first.
std::string render_one(const entry& e, const build_options& build, const plot::theme& theme,
                       std::string_view format, const plot::output_options& output);

/// An animation to write: frames first..last (from 0, inclusive) of its plan.
struct animation_job {
    const entry* figure = nullptr;  ///< the animation
    animation_plan plan;            ///< its frames
    int first = 0;                  ///< the first frame to write
    int last = 0;                   ///< the last frame to write
};

/// Every file a render writes, in the order written, with what writes it (for messages).
std::vector<std::pair<std::filesystem::path, std::string>> render_outputs(const std::vector<figure_file>& stills,
                                                                      const std::vector<animation_job>& animations,
                                                                      const std::vector<std::string>& formats,
                                                                      const std::filesystem::path& dir, bool at);

/// Throws bad_input, before any work, if two outputs of a render would be the same file:
/// two panels with one paper_file, a spec's paper_file equal to a built-in's, a figure's
/// overlay drawing and another figure's file, a frame of a PNG sequence and a still figure.
void check_distinct_outputs(const std::vector<figure_file>& stills, const std::vector<animation_job>& animations,
                            const std::vector<std::string>& formats, const std::filesystem::path& dir, bool at);

/// The most pixels an animation's raster frames add up to: five minutes of 1080p at 30 fps.
inline constexpr double max_animation_pixels = 2e10;

/// Throws bad_input, before any work, if the frames to write of an animation in a raster
/// format add up to more than max_animation_pixels.
void check_animation_work(const std::vector<animation_job>& animations, const std::vector<std::string>& formats,
                          const build_options& build, const render_style& style);

/// Throws bad_input, before any work, if the render of every group (its still files and its
/// animations' frames, with the group's style) is estimated to take more than a render may
/// (figures::check_cost): the seconds of computing and drawing, and the series' memory.
void check_render_cost(const std::vector<std::vector<figure_file>>& stills,
                       const std::vector<std::vector<animation_job>>& animations,
                       const std::vector<std::string>& formats, const build_options& build,
                       const std::vector<render_style>& styles, bool at);

/// Writes a render (after check_distinct_outputs and check_animation_work): the still figures' files, then each animation in each format, all its
/// frames where the format holds an animation, otherwise one frame, at t/T = `at` if given
/// (in every format) or the first frame written.
void write_render(const std::vector<figure_file>& stills, const std::vector<animation_job>& animations,
                  const std::vector<std::string>& formats, const std::filesystem::path& dir,
                  const build_options& build, const render_style& style, std::optional<double> at);

}  // namespace figures
