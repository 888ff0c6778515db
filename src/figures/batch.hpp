// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "figures/catalog.hpp"
#include "plot/output.hpp"
#include "plot/theme.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace figures {

/// One file to write: a figure of the catalog, or one of its panels alone, in the format
/// of the path's extension.
struct figure_file {
    const entry* figure = nullptr;  ///< the catalog entry
    int panel = -1;                 ///< -1 for the whole figure, else the panel alone at the paper's width
    std::filesystem::path path;     ///< where to write it
};

/// The files for figures in formats (file extensions) under dir: DIR/ID.EXT, or with
/// paper_files one per panel under the panels' paper_file names (figures without any are
/// left out). Throws std::invalid_argument, before any work, if only some panels have one.
std::vector<figure_file> files_for(const std::vector<const entry*>& figures, const std::vector<std::string>& formats,
                                   const std::filesystem::path& dir, bool paper_files,
                                   const build_options& options = {});

/// Every series of the figure as CSV with the header panel,series,x,y,id; panels are a, b,
/// ..., series are named by their legend text without markup and by their id (each
/// series' own points: `data` writes a curve's samples, see figure_data.hpp).
std::string figure_csv(const plot::figure& f);

/// A figure's panel on its own, sized as the paper's LaTeX includes it, with the same frame
/// as the figure's other panels on their own, in the paper's y range where the spec gives one
/// (paper_y_range); the first panel alone carries the legend.
plot::figure single_panel(const plot::figure& f, int panel, double width_cm);

/// Builds each figure once and writes every file, on all cores. Each file is complete or
/// absent (see plot::write_atomically); after all work stops, the first error is thrown.
void write_figures(const std::vector<figure_file>& files, const build_options& options, const plot::theme& theme,
                   const plot::output_options& output);

}  // namespace figures
