// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The render command's options and work, which the plot command shares.

#include "figures/catalog.hpp"

#include <optional>
#include <string>
#include <vector>

namespace pendulum::cli {

/// The options of render (and of plot, which renders one figure).
struct render_options {
    std::vector<std::string> ids;  // figure ids, aliases or spec files
    bool all = false;               // every built-in still figure
    std::string dir = ".";
    std::string formats = "pdf,png";
    std::string theme;  // empty: paper for still figures, slides for animations
    std::vector<std::string> sets;
    std::optional<double> dpi;  // the theme's when not given
    std::string size;           // WIDTHxHEIGHT in pixels: the style key size_px
    std::string theta0;
    bool paper_files = false;
    bool force = false;  // rewrite files that would not change
    std::string frames;  // a..b, 1-based, of an animation
    std::string at;      // t/T of one frame of an animation
    std::optional<double> tex_font_size;  // the document's font size, for pdf_tex and eps_tex
    std::string tex_sizes = "relative";  // how pdf_tex and eps_tex size their text
    std::optional<int> jobs;              // worker threads; PENDULUM_FIGURES_JOBS or the usable CPUs when not given
    std::string depfile;         // where to write the Make rule of the run's outputs and inputs; empty for none
    std::string depfile_target;  // the rule's target instead of the outputs (a stamp file)
    std::string check;           // a journal (aps, aps:1, ...): measure the figures against its rules, write nothing
};

/// Checks the options of `o` other than the ids and renders the chosen figures; returns the exit code.
int render_figures(const std::vector<const figures::entry*>& chosen, const render_options& o);

}  // namespace pendulum::cli
