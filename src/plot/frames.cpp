// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/frames.hpp"

#include "plot/handles.hpp"
#include "plot/output.hpp"
#include "plot/render.hpp"

#include <cairo-pdf.h>

#include <cmath>
#include <exception>
#include <stdexcept>

namespace plot {

namespace {

void check(cairo_surface_t* s) { check_cairo(cairo_surface_status(s), "draw a frame"); }

/// Where Cairo's PDF bytes go, and the first failure of writing them (Cairo's callback
/// must not throw: the failure is kept, and thrown once Cairo has stopped).
struct pdf_sink {
    const std::function<void(std::string_view)>* write;
    std::exception_ptr error;
};

cairo_status_t pass_on(void* closure, const unsigned char* data, unsigned int length) {
    auto* sink = static_cast<pdf_sink*>(closure);
    if (sink->error) return CAIRO_STATUS_WRITE_ERROR;
    try {
        (*sink->write)(std::string_view(reinterpret_cast<const char*>(data), length));
    } catch (...) {
        sink->error = std::current_exception();
        return CAIRO_STATUS_WRITE_ERROR;
    }
    return CAIRO_STATUS_SUCCESS;
}

}  // namespace

std::pair<int, int> pixel_size(const figure& fig, const theme& th, double dpi) {
    check_raster_size(fig, th, dpi);
    const page_size size = figure_size(fig, th);
    const int width = static_cast<int>(std::lround(size.width_pt * dpi / 72.0));
    const int height = static_cast<int>(std::lround(size.height_pt * dpi / 72.0));
    if (width < 1 || height < 1 || width > 32767 || height > 32767) {
        throw bad_input("a frame of " + std::to_string(width) + " x " + std::to_string(height) +
                                    " pixels is out of range; choose another --dpi");
    }
    return {width, height};
}

argb_image render_argb(const figure& fig, const theme& th, double dpi, draw_pass pass, const argb_image* under) {
    argb_image image;
    render_argb(image, fig, th, dpi, pass, under);
    return image;
}

namespace {

void render_pixels(argb_image& image, const figure& fig, const theme& th, double dpi, draw_pass pass,
                   const argb_image* under, bool rgb24) {
    const auto [width, height] = pixel_size(fig, th, dpi);
    const cairo_format_t format = rgb24 ? CAIRO_FORMAT_RGB24 : CAIRO_FORMAT_ARGB32;
    image.rgb24 = rgb24;
    if (under) {
        if (under->width != width || under->height != height) throw std::invalid_argument("frames differ in size");
        if (under->rgb24 != rgb24) throw std::invalid_argument("frames differ in pixel format");
        image.width = under->width;
        image.height = under->height;
        image.stride = under->stride;
        image.data.assign(under->data.begin(), under->data.end());  // into the buffer it has
    } else {
        image.width = width;
        image.height = height;
        image.stride = cairo_format_stride_for_width(format, width);
        image.data.assign(static_cast<std::size_t>(image.stride) * static_cast<std::size_t>(height), 0);
    }
    surface_ptr surface(
        cairo_image_surface_create_for_data(image.data.data(), format, width, height, image.stride));
    check(surface.get());
    {
        context_ptr cr(cairo_create(surface.get()));
        cairo_scale(cr.get(), dpi / 72.0, dpi / 72.0);
        draw_figure(cr.get(), fig, th, figure_size(fig, th), pass);
        check_cairo(cairo_status(cr.get()), "draw a frame");
    }
    cairo_surface_flush(surface.get());
}

}  // namespace

void render_argb(argb_image& image, const figure& fig, const theme& th, double dpi, draw_pass pass,
                 const argb_image* under) {
    render_pixels(image, fig, th, dpi, pass, under, false);
}

void render_rgb24(argb_image& image, const figure& fig, const theme& th, double dpi, draw_pass pass,
                  const argb_image* under) {
    render_pixels(image, fig, th, dpi, pass, under, true);
}

void render_pdf_pages(int count, const std::function<figure(int)>& frame, const theme& th,
                      const std::function<void(std::string_view)>& write) {
    if (count < 1) throw std::invalid_argument("a PDF of frames needs at least one frame");
    pdf_sink sink{&write, nullptr};
    const figure first = frame(0);
    const page_size size = figure_size(first, th);
    surface_ptr surface(cairo_pdf_surface_create_for_stream(pass_on, &sink, size.width_pt, size.height_pt));
    check(surface.get());
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATE_DATE, pdf_creation_date().c_str());
    context_ptr cr(cairo_create(surface.get()));
    for (int i = 0; i < count && !sink.error; ++i) {
        draw_figure(cr.get(), i == 0 ? first : frame(i), th, size, draw_pass::all, nullptr, true);
        cairo_show_page(cr.get());
    }
    cr.reset();
    cairo_surface_finish(surface.get());
    if (sink.error) std::rethrow_exception(sink.error);
    check(surface.get());
}

}  // namespace plot
