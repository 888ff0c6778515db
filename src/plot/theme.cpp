#include "plot/theme.hpp"

#include <stdexcept>

namespace plot {

theme paper_theme() {
    theme t;
    t.name = "paper";
    // Computer Modern Unicode lacks a few symbols (the prime); they come from the next family.
    t.font_family = "CMU Serif, DejaVu Math TeX Gyre";
    t.palette = {{0, 0, 0}};
    return t;
}

theme slides_theme() {
    theme t;
    t.name = "slides";
    t.font_family = "CMU Sans Serif, DejaVu Sans";
    t.tick_font_pt = 14;
    t.label_font_pt = 16;
    t.legend_font_pt = 13;
    t.line_width_pt = 2.2;
    t.frame_width_pt = 1.0;
    t.marker_radius_pt = 3.6;
    t.tick_length_pt = 6;
    t.padding_pt = 6;
    // Okabe-Ito: black, blue, vermillion, bluish green, orange, reddish purple, sky blue.
    t.palette = {{0, 0, 0},
                 {0.0, 0.447, 0.698},
                 {0.835, 0.369, 0.0},
                 {0.0, 0.620, 0.451},
                 {0.902, 0.624, 0.0},
                 {0.800, 0.475, 0.655},
                 {0.337, 0.706, 0.914}};
    t.fixed_width_cm = 25.4;
    t.fixed_height_cm = 14.2875;
    return t;
}

std::vector<std::string> theme_names() { return {"paper", "slides"}; }

theme theme_by_name(std::string_view name) {
    if (name == "paper") return paper_theme();
    if (name == "slides") return slides_theme();
    throw std::invalid_argument("unknown theme '" + std::string(name) + "'; themes: paper, slides");
}

}  // namespace plot
