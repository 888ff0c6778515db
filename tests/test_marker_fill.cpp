// SPDX-License-Identifier: GPL-3.0-or-later
// A translucent filled marker is one fill out to where an opaque one's outline ends: no
// ring where an outline stroked over the fill would blend the rim twice, and the same reach.
#include "figures/themes.hpp"
#include "plot/figure.hpp"
#include "plot/frames.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace {

using plot::marker_style;

/// A drawing with one marker of `style` at its centre, in red at `alpha`.
plot::figure one_marker(marker_style style, double alpha) {
    plot::figure fig;
    fig.panel_width_cm = 4;
    fig.panel_aspect = 1;
    plot::panel p;
    p.frameless = true;
    p.x.min = -1;
    p.x.max = 1;
    p.y.min = -1;
    p.y.max = 1;
    plot::series s;
    s.line = plot::line_style::none;
    s.marker = style;
    s.marker_scale = 6;
    s.alpha = alpha;
    s.rgb_color = plot::rgb{1, 0, 0};
    s.x = {0};
    s.y = {0};
    p.data.push_back(s);
    fig.panels.push_back(p);
    return fig;
}

/// The green channel of the pixels along the row through the marker's centre (255 is the
/// paper's white; the marker's red takes green away).
std::vector<int> centre_row(const plot::argb_image& image) {
    // The marker is the only ink: its rows are those with green below 255.
    int top = image.height, bottom = -1;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (image.data[static_cast<std::size_t>(y * image.stride + 4 * x + 1)] < 250) {
                top = std::min(top, y);
                bottom = std::max(bottom, y);
            }
        }
    }
    std::vector<int> row;
    if (bottom < 0) return row;
    const int y = (top + bottom) / 2;
    for (int x = 0; x < image.width; ++x) row.push_back(image.data[static_cast<std::size_t>(y * image.stride + 4 * x + 1)]);
    return row;
}

/// The first and last pixel of the row with any ink.
std::pair<int, int> ink_ends(const std::vector<int>& row) {
    int first = -1, last = -1;
    for (int x = 0; x < static_cast<int>(row.size()); ++x) {
        if (row[static_cast<std::size_t>(x)] < 250) {
            if (first < 0) first = x;
            last = x;
        }
    }
    return {first, last};
}

}  // namespace

TEST(MarkerFill, TranslucentFilledMarkersHaveNoRingAndAnOpaqueOnesReach) {
    const plot::theme theme = figures::load_theme("paper");
    for (const marker_style style : {marker_style::filled_circle, marker_style::filled_square,
                                     marker_style::filled_triangle, marker_style::filled_diamond}) {
        SCOPED_TRACE(static_cast<int>(style));
        const auto opaque = centre_row(plot::render_argb(one_marker(style, 1.0), theme, 600));
        const auto faint = centre_row(plot::render_argb(one_marker(style, 0.4), theme, 600));
        ASSERT_FALSE(opaque.empty());
        ASSERT_FALSE(faint.empty());
        const auto [o0, o1] = ink_ends(opaque);
        const auto [f0, f1] = ink_ends(faint);
        // The same reach, to a pixel (at 600 dpi a pixel is 0.12 pt).
        EXPECT_LE(std::abs(o0 - f0), 1) << o0 << " " << f0;
        EXPECT_LE(std::abs(o1 - f1), 1) << o1 << " " << f1;
        // No ring: nothing inside is darker than the centre (one level of rounding).
        const int centre = faint[static_cast<std::size_t>((f0 + f1) / 2)];
        const int darkest = *std::min_element(faint.begin() + f0, faint.begin() + f1 + 1);
        EXPECT_GE(darkest, centre - 1) << "centre " << centre << ", darkest " << darkest;
        // 40 % of red over white: green 255 * 0.6 at the centre.
        EXPECT_NEAR(centre, 153, 1);
    }
}
