// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Part of the plot layer's renderer; not a public interface.

#include "plot/render.hpp"
#include "plot/text.hpp"
#include "plot/theme.hpp"

#include <string>
#include <vector>

namespace plot {

/// The theme with its text sizes moved to the nearest of LaTeX's sizes (\scriptsize,
/// \footnotesize, \small, ...) in a document set at document_pt, so that the layout,
/// measured with Computer Modern's metrics, makes room for the text the document sets.
theme latex_sized_theme(const theme& th, double document_pt);

/// The LaTeX size command nearest to size_pt in a document set at document_pt.
std::string latex_size_command(double size_pt, double document_pt);

/// A picture environment (as Inkscape's pdf_tex files) that includes graphics_name at the
/// figure's size, or at \figurewidth if the document defines it (the text keeps its size),
/// and puts each text at its anchor as LaTeX, relative to the document's font size.
std::string latex_picture(const std::vector<placed_text>& texts, page_size size, const theme& th,
                          const std::string& graphics_name, double document_pt);

}  // namespace plot
