// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Part of the plot layer's renderer; not a public interface.

#include "plot/output.hpp"
#include "plot/render.hpp"
#include "plot/text.hpp"
#include "plot/theme.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace plot {

/// The theme with, for relative sizes, each text size (meant for a 10 pt document) moved to
/// the size of the nearest LaTeX command (\scriptsize, \footnotesize, \small, ...) in a
/// document set at options.tex_font_pt, so that the layout, measured with Computer Modern's
/// metrics, makes room for the text the document sets. Absolute sizes keep the theme's.
theme latex_sized_theme(const theme& th, const output_options& options);

/// The text sizes the layout decides a figure's contents at (which tick labels stay,
/// where the legend goes, whether there is room for one): the largest of the theme's own and
/// those its LaTeX overlay sets in a document of tex_agree_pt (relative sizes), so that the
/// PDF and the overlays up to that size keep the same; a theme made by latex_sized_theme
/// decides at those of the theme it was made from, or its own where they are larger.
text_sizes decided_sizes(const theme& th);

/// What sets text of size_pt (a size of the sized theme): the LaTeX size command of that size
/// in the document, or \fontsize for absolute sizes.
std::string latex_size_command(double size_pt, const output_options& options);

/// True for the bytes a file name may hold wherever it reaches LaTeX, Make or XML as it is:
/// ASCII letters and digits and . _ + -.
bool plain_file_name_character(char c);

/// Throws bad_input for a drawing's file name that an overlay cannot write into LaTeX as it
/// is (\includegraphics, \typeout, a comment): anything but ASCII letters, digits and . _ + -.
void check_latex_file_name(std::string_view name);

/// A picture environment (as Inkscape's pdf_tex files) that includes graphics_name at the
/// figure's size, or at \figurewidth if the document defines it (the text keeps its size),
/// and puts each text at its anchor as LaTeX, sized as options say.
std::string latex_picture(const std::vector<placed_text>& texts, page_size size, const theme& th,
                          const std::string& graphics_name, const output_options& options);

}  // namespace plot
