// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What help and lists say about the output formats, read from plot's format table.

#include "plot/output.hpp"

#include <string>

namespace pendulum::cli {

/// True for a LaTeX overlay format (its row names the format of the drawing beside it).
bool is_overlay(const plot::format_row& f);

/// Every format's name: "png, pdf, svg, ...".
std::string format_list();

/// Every format with what it is: "png (raster at --dpi), pdf (...), ...".
std::string format_help();

/// The raster formats: "png and gif".
std::string raster_formats();

/// The LaTeX overlay formats: "pdf_tex, eps_tex".
std::string overlay_formats();

/// How an animation is written in each format: "numbered PNG frames ..., or a looping GIF;
/// svg, ... get one frame".
std::string animation_help();

}  // namespace pendulum::cli
