#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace plot {

/// An RGB colour with components in [0, 1].
struct rgb {
    double r = 0;  ///< red
    double g = 0;  ///< green
    double b = 0;  ///< blue
};

/// How figures look: fonts, sizes in points, line widths, colours, figure size.
struct theme {
    std::string name;                 ///< theme name
    std::string font_family;          ///< Pango font families, the first preferred, comma-separated
    double tick_font_pt = 7.5;        ///< tick labels
    double label_font_pt = 8.5;       ///< axis labels and panel labels
    double legend_font_pt = 7.0;      ///< legend entries
    double line_width_pt = 0.8;       ///< series lines
    double frame_width_pt = 0.5;      ///< axes frame and ticks
    double marker_radius_pt = 1.6;    ///< open circles
    double tick_length_pt = 3.0;      ///< major ticks (minor: 60 %)
    double padding_pt = 3.0;          ///< space around text
    std::vector<rgb> palette;         ///< series colours by index
    double fixed_width_cm = 0;        ///< whole-figure width, or 0 to size by panels
    double fixed_height_cm = 0;       ///< whole-figure height, or 0 to size by panels
};

/// Black and white, paper line styles, Computer Modern (CMU Serif) text.
theme paper_theme();

/// 16:9 slides: large sans-serif text, thick lines, Okabe-Ito colour-blind-safe palette.
theme slides_theme();

/// The names of the themes, for messages.
std::vector<std::string> theme_names();

/// The theme of that name; throws std::invalid_argument listing the valid names otherwise.
theme theme_by_name(std::string_view name);

}  // namespace plot
