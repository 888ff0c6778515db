// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "plot/figure.hpp"
#include "plot/render.hpp"
#include "plot/theme.hpp"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace plot {

/// A figure drawn into pixels: Cairo's ARGB32 (opaque here), or its RGB24 as a PNG is drawn,
/// `stride` bytes per row.
struct argb_image {
    int width = 0;                    ///< pixels
    int height = 0;                   ///< pixels
    int stride = 0;                   ///< bytes per row
    std::vector<unsigned char> data;  ///< height * stride bytes
    bool rgb24 = false;               ///< Cairo's RGB24 (a PNG's pixels) rather than ARGB32
};

/// The pixel size of a figure at dpi; throws plot::bad_input naming it if it is out of range.
std::pair<int, int> pixel_size(const figure& fig, const theme& th, double dpi);

/// Draws the figure into pixels at dpi: one pass of it, over a copy of `under` if given
/// (the still pass of the same figure, so that a frame draws only what moves).
argb_image render_argb(const figure& fig, const theme& th, double dpi, draw_pass pass = draw_pass::all,
                       const argb_image* under = nullptr);

/// Draws as render_argb does into `image`, whose buffer is reused (a frame's pixels take as
/// much memory as the allocator maps afresh, and unmaps, at every frame otherwise).
void render_argb(argb_image& image, const figure& fig, const theme& th, double dpi, draw_pass pass = draw_pass::all,
                 const argb_image* under = nullptr);

/// Draws as render_argb does into `image`, in Cairo's RGB24 as render draws a PNG (whose
/// pixels these are for the pass all).
void render_rgb24(argb_image& image, const figure& fig, const theme& th, double dpi, draw_pass pass = draw_pass::all,
                  const argb_image* under = nullptr);

/// A PDF of `count` pages, page i showing frame(i), for Beamer's animate package, handed to
/// `write` piece by piece as Cairo finishes them (memory does not grow with the pages).
/// Frames must share one size. Dated by SOURCE_DATE_EPOCH like a still PDF, otherwise
/// undated. An exception from `write` stops the drawing and is thrown again.
void render_pdf_pages(int count, const std::function<figure(int)>& frame, const theme& th,
                      const std::function<void(std::string_view)>& write);

}  // namespace plot
