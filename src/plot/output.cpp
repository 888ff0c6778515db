// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/output.hpp"
#include "plot/page_buffer.hpp"

#include "plot/animation_writers.hpp"
#include "plot/frames.hpp"
#include "plot/gif.hpp"
#include "plot/handles.hpp"
#include "plot/latex_overlay.hpp"
#include "plot/render.hpp"
#include "plot/svg_text.hpp"
#include "plot/text.hpp"

#include <cairo-pdf.h>
#include <cairo-ps.h>
#include <cairo-svg.h>
#include <libdeflate.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <span>
#include <unordered_map>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace plot {

namespace {


/// SOURCE_DATE_EPOCH as a UTC time, if set and valid.
std::optional<std::tm> source_date() {
    const char* text = std::getenv("SOURCE_DATE_EPOCH");
    if (!text || !*text) return std::nullopt;
    // The reproducible-builds specification: a whole number of seconds since 1970, and an
    // error otherwise, not a silent fallback. PDF dates have four-digit years.
    const std::string value = text;
    const bool digits = value.size() <= 12 && value.find_first_not_of("0123456789") == std::string::npos;
    const long long seconds = digits ? std::stoll(value) : -1;
    constexpr long long last = 253402300799;  // 9999-12-31T23:59:59Z
    std::tm tm{};
    const std::time_t t = static_cast<std::time_t>(seconds);
    if (!digits || seconds > last || !gmtime_r(&t, &tm)) {
        std::string shown;
        for (const char c : value.substr(0, 40)) shown += static_cast<unsigned char>(c) < 0x20 ? '?' : c;
        throw bad_input("SOURCE_DATE_EPOCH '" + shown +
                                    "' must be a whole number of seconds since 1970-01-01, 0 to " +
                                    std::to_string(last));
    }
    return tm;
}

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

void check_surface(cairo_surface_t* s, std::string_view format) {
    check_cairo(cairo_surface_status(s), "render " + std::string(format));
}

void draw_on(cairo_surface_t* surface, const figure& fig, const theme& th, page_size size, double scale,
             std::string_view format, std::vector<placed_text>* texts = nullptr, bool vector = false,
             std::vector<panel_frame>* frames = nullptr) {
    check_surface(surface, format);
    context_ptr cr(cairo_create(surface));
    cairo_scale(cr.get(), scale, scale);
    draw_figure(cr.get(), fig, th, size, draw_pass::all, texts, vector, frames);
    check_cairo(cairo_status(cr.get()), "render " + std::string(format));
}

/// Draws the figure on a vector surface made by `create` (which may set it up further)
/// and returns the stream's bytes; `before_finish(surface, drawn)` is called with the
/// drawing (its layout) before the surface is finished.
template <class Create, class Finish>
std::string render_vector(const figure& fig, const theme& th, std::string_view format, Create create,
                          std::vector<placed_text>* texts, Finish before_finish) {
    const page_size size = figure_size(fig, th);
    std::string bytes;
    surface_ptr surface(create(&bytes, size));
    check_surface(surface.get(), format);
    drawing drawn{&fig, &th, false, {}};
    draw_on(surface.get(), fig, th, size, 1.0, format, texts, true, &drawn.frames);
    before_finish(surface.get(), drawn);
    cairo_surface_finish(surface.get());
    check_surface(surface.get(), format);
    return bytes;
}

/// render_vector with nothing to add before the surface is finished.
template <class Create>
std::string render_vector(const figure& fig, const theme& th, std::string_view format, Create create,
                          std::vector<placed_text>* texts = nullptr) {
    return render_vector(fig, th, format, create, texts, [](cairo_surface_t*, const drawing&) {});
}

/// The figure in words for a file's metadata, its title as drawn in place of its alt text;
/// `drawn`, the file's drawing, spares the words a layout of their own.
figure_words metadata_words(const figure& fig, const drawing& drawn) {
    figure_words words = fig.words ? fig.words(&drawn) : figure_words{};
    if (!fig.title.empty()) words.alt = markup_text(fig.title.markup);
    return words;
}

std::string render_pdf(const figure& fig, const theme& th, const output_options&, std::vector<placed_text>* texts) {
    return render_vector(
        fig, th, "pdf",
        [](std::string* bytes, page_size size) {
            cairo_surface_t* s = cairo_pdf_surface_create_for_stream(append_bytes, bytes, size.width_pt, size.height_pt);
            cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATE_DATE, pdf_creation_date().c_str());
            return s;
        },
        texts,
        [&fig](cairo_surface_t* s, const drawing& drawn) {
            // The document's information is written when the surface is finished.
            const figure_words words = metadata_words(fig, drawn);
            if (!words.alt.empty()) cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_TITLE, words.alt.c_str());
            if (!words.description.empty()) {
                cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_SUBJECT, words.description.c_str());
            }
        });
}

std::string write_pdf(const figure& fig, const theme& th, const output_options& options) {
    return render_pdf(fig, th, options, nullptr);
}

/// Cairo numbers SVG surface ids from a process-wide counter; renumber them in order of
/// appearance so that the file does not depend on what else the process drew.
std::string renumber_svg_ids(const std::string& svg) {
    static const std::regex id("surface[0-9]+");
    std::map<std::string, int> seen;
    std::string out;
    auto last = svg.cbegin();
    for (std::sregex_iterator it(svg.begin(), svg.end(), id), end; it != end; ++it) {
        out.append(last, svg.cbegin() + it->position());
        const auto [pos, added] = seen.emplace(it->str(), static_cast<int>(seen.size()) + 1);
        out += "surface" + std::to_string(pos->second);
        last = svg.cbegin() + it->position() + it->length();
    }
    out.append(last, svg.cend());
    return out;
}

/// The ids of an SVG's definitions (glyphs, clips, surfaces), each with `prefix` before it, and
/// every reference to them (href="#...", xlink:href="#...", url(#...)) the same: the ids of
/// two figures inlined in one HTML page then never meet.
std::string prefix_svg_ids(const std::string& svg, const std::string& prefix) {
    // Each kind of place a name follows: an id attribute (after a space), a link, a url().
    struct place {
        std::string_view opening;
        char end;
    };
    static constexpr place places[] = {{" id=\"", '"'}, {"href=\"#", '"'}, {"url(#", ')'}};
    std::string out;
    out.reserve(svg.size() + svg.size() / 8);
    std::size_t from = 0;
    for (;;) {
        std::size_t at = std::string::npos;
        const place* found = nullptr;
        for (const place& p : places) {
            const std::size_t i = svg.find(p.opening, from);
            if (i < at) at = i, found = &p;
        }
        if (!found) break;
        const std::size_t name = at + found->opening.size();
        const std::size_t end = svg.find(found->end, name);
        if (end == std::string::npos) break;
        out.append(svg, from, name - from);
        out += prefix;
        from = name;
    }
    out.append(svg, from, std::string::npos);
    return out;
}

/// The prefix of an SVG's ids: "f" and 12 hex digits of a hash of its bytes (FNV-1a), so
/// that the same figure gets the same bytes and two different figures different ids.
std::string svg_id_prefix(const std::string& svg) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const char c : svg) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001b3ULL;
    }
    char prefix[24];
    std::snprintf(prefix, sizeof prefix, "f%012llx-", static_cast<unsigned long long>(h >> 16));
    return prefix;
}

/// Cairo writes the clock time as %%CreationDate with no way to set it: use
/// SOURCE_DATE_EPOCH, or drop the line (it is optional in DSC).
std::string fix_eps_date(const std::string& eps) {
    const std::string key = "%%CreationDate:";
    const auto start = eps.find(key);
    if (start == std::string::npos) return eps;
    const auto end = eps.find('\n', start);
    std::string line;
    if (const auto tm = source_date()) {
        char date[64];
        std::strftime(date, sizeof date, "%a %b %e %H:%M:%S %Y", &*tm);
        line = key + " " + date + "\n";
    }
    return eps.substr(0, start) + line + (end == std::string::npos ? "" : eps.substr(end + 1));
}

/// libdeflate's compressor, freed at the thread's end.
struct deflate_compressor_free {
    void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

/// The calling thread's compressor (made once a thread: it holds its tables). Level 1: on
/// the figures' line art it makes PNGs 12-25 % smaller than zlib's run-length deflate did,
/// in about half its instructions; level 6 is 4-9 % smaller again in twice level 1's
/// instructions. Rows are not filtered: its matches find a coloured background's runs of
/// three-byte pixels (Sub filtering them made the dark theme's PNGs 22 % larger). Measured
/// again on the paper's 7 figures (grey) and 3 slides figures (RGB) at 300 dpi: Up makes
/// them 13 and 18 % larger, Sub 15 and 21 %, Up only on rows equal to the one above the
/// same (within 0.1 %); none of them saves deflate's instructions (libdeflate hashes every
/// byte, matched or not), and levels 2 and 4 take 1.9 times level 1's for under 0.4 %.
libdeflate_compressor* thread_compressor() {
    thread_local const std::unique_ptr<libdeflate_compressor, deflate_compressor_free> c(libdeflate_alloc_compressor(1));
    if (!c) throw std::bad_alloc();
    return c.get();
}

/// Appends `v` as four big-endian bytes.
void append_be32(std::string& out, std::uint32_t v) {
    const char b[4] = {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
                       static_cast<char>(v)};
    out.append(b, 4);
}

/// Appends a PNG chunk: its length, type, data and the CRC of type and data.
void append_chunk(std::string& out, const char (&type)[5], const unsigned char* data, std::size_t size) {
    append_be32(out, static_cast<std::uint32_t>(size));
    const std::size_t start = out.size();
    out.append(type, 4);
    if (size) out.append(reinterpret_cast<const char*>(data), size);
    append_be32(out, libdeflate_crc32(0, out.data() + start, 4 + size));
}

/// The most bytes a PNG chunk holds.
constexpr std::size_t max_chunk_bytes = 0x7fffffff;

/// Cairo's RGB24 pixels, `stride` bytes a row, as the PNG passes read them.
struct rgb24_pixels {
    const unsigned char* data;
    int stride;
    int width;
    int height;
    const std::uint32_t* row(int y) const {
        return reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    }
    std::uint32_t pixel(int x, int y) const { return row(y)[x] & 0xffffffu; }
};

/// PNG's rows as they are compressed: each a filter byte, then `row_bytes` of pixels.
struct png_rows {
    unsigned char* bytes;
    std::size_t row_bytes;
    /// Row y's pixels (its filter byte, None, is set here).
    unsigned char* row(int y) const {
        unsigned char* r = bytes + static_cast<std::size_t>(y) * (row_bytes + 1);
        r[0] = 0;
        return r + 1;
    }
};

/// The grey pass: each pixel's blue byte into `out`; false at the first row with a pixel
/// that is not grey.
bool grey_pass(const rgb24_pixels& im, png_rows out) {
    // The width in a local: a byte store may alias a member, and a bound read again after
    // every store keeps the compiler from vectorising the loop (4 instructions a pixel, not 1).
    const int width = im.width;
    for (int y = 0; y < im.height; ++y) {
        // A whole row at a time, without a branch per pixel. A pixel is grey when its red
        // equals its green and its green its blue: the low 16 bits of p ^ (p >> 8) are zero.
        const std::uint32_t* src = im.row(y);
        unsigned char* dst = out.row(y);
        std::uint32_t off_grey = 0;
        for (int x = 0; x < width; ++x) {
            const std::uint32_t p = src[x];
            off_grey |= (p ^ (p >> 8)) & 0xffffu;
            dst[x] = static_cast<unsigned char>(p);
        }
        if (off_grey != 0) return false;
    }
    return true;
}

/// The palette pass: each pixel's index into `out` and its colour (three bytes) into
/// `palette`; false at the first pixel past 256 colours.
bool palette_pass(const rgb24_pixels& im, png_rows out, std::vector<unsigned char>& palette) {
    std::unordered_map<std::uint32_t, unsigned char> index;
    // Line art is runs of one colour: a pixel like the one before needs no lookup
    // (`last` starts as no pixel: pixels have 24 bits).
    std::uint32_t last = 0xffffffffu;
    unsigned char last_index = 0;
    for (int y = 0; y < im.height; ++y) {
        unsigned char* dst = out.row(y);
        for (int x = 0; x < im.width; ++x) {
            const std::uint32_t p = im.pixel(x, y);
            if (p != last) {
                auto it = index.find(p);
                if (it == index.end()) {
                    if (index.size() == 256) return false;
                    it = index.emplace(p, static_cast<unsigned char>(index.size())).first;
                    palette.insert(palette.end(), {static_cast<unsigned char>(p >> 16),
                                                   static_cast<unsigned char>((p >> 8) & 0xff),
                                                   static_cast<unsigned char>(p & 0xff)});
                }
                last = p;
                last_index = it->second;
            }
            dst[x] = last_index;
        }
    }
    return true;
}

/// The RGB pass: three bytes a pixel into `out`.
void rgb_pass(const rgb24_pixels& im, png_rows out) {
    // A pixel's three bytes are stored as four, the fourth (zero) overwritten by the next
    // pixel, or the next row's filter byte (None, zero), or the byte after the last row
    // (png_rows_bytes has it).
    const int width = im.width;  // a local: see grey_pass
    for (int y = 0; y < im.height; ++y) {
        const std::uint32_t* src = im.row(y);
        unsigned char* dst = out.row(y);
        for (int x = 0; x < width; ++x) {
            const std::uint32_t p = src[x];
            // R, G, B and a zero in memory order: the bytes of 0xXXRRGGBB reversed (one
            // instruction) and shifted on a little-endian machine.
            const std::uint32_t rgb0 = std::endian::native == std::endian::little ? __builtin_bswap32(p) >> 8 : p << 8;
            std::memcpy(dst + 3 * static_cast<std::ptrdiff_t>(x), &rgb0, 4);
        }
    }
}

/// The PNG file: signature, IHDR, PLTE (if any), pHYs, the rows deflated (a zlib stream,
/// libdeflate's) in one IDAT chunk, IEND. A worker holds the raster, the rows, and the
/// deflated rows twice (raster_bytes_per_pixel: deflated line art is small).
std::string png_file(std::span<const unsigned char> rows, int width, int height, int color_type,
                     const std::vector<unsigned char>& palette, std::uint32_t pixels_per_metre) {
    libdeflate_compressor* const compressor = thread_compressor();
    std::string out("\x89PNG\r\n\x1a\n", 8);
    std::string header;
    append_be32(header, static_cast<std::uint32_t>(width));
    append_be32(header, static_cast<std::uint32_t>(height));
    header += {8, static_cast<char>(color_type), 0, 0, 0};  // 8 bits, deflate, adaptive filters, no interlace
    append_chunk(out, "IHDR", reinterpret_cast<const unsigned char*>(header.data()), header.size());
    if (!palette.empty()) append_chunk(out, "PLTE", palette.data(), palette.size());
    std::string phys;
    append_be32(phys, pixels_per_metre);
    append_be32(phys, pixels_per_metre);
    phys += '\1';  // the metre
    append_chunk(out, "pHYs", reinterpret_cast<const unsigned char*>(phys.data()), phys.size());
    const std::size_t bound = libdeflate_zlib_compress_bound(compressor, rows.size());
    // Not zeroed: only the pages the deflated bytes reach are touched.
    const auto idat = std::make_unique_for_overwrite<unsigned char[]>(bound);
    const std::size_t deflated = libdeflate_zlib_compress(compressor, rows.data(), rows.size(), idat.get(), bound);
    // A chunk has less than 2^31 bytes: the largest raster (max_raster_pixels, RGB) deflates to less.
    if (deflated == 0 || deflated > max_chunk_bytes) throw std::runtime_error("cannot encode PNG");
    append_chunk(out, "IDAT", idat.get(), deflated);
    append_chunk(out, "IEND", nullptr, 0);
    return out;
}

/// PNG's colour types.
constexpr int png_grey = 0, png_rgb = 2, png_palette = 3;

/// The bytes png_of writes its rows into at most: RGB's, and one (rgb_pass).
std::size_t png_rows_bytes(int width, int height) {
    return static_cast<std::size_t>(height) * (3 * static_cast<std::size_t>(width) + 1) + 1;
}

/// The PNG of width x height pixels of Cairo's RGB24, `stride` bytes a row, drawn at dpi;
/// `rows` (png_rows_bytes(width, height) bytes, whatever they hold) takes the rows to encode.
std::string png_of(const unsigned char* data, int stride, int width, int height, double dpi, unsigned char* rows) {
    // The smallest exact pixel format: grey (the paper theme), a palette of at most 256
    // colours, or RGB. Each attempt is one pass that stops at the first pixel (the grey
    // one: row) it cannot hold.
    const rgb24_pixels im{data, stride, width, height};
    const auto w = static_cast<std::size_t>(width);
    std::size_t row_bytes = w;
    int color_type = png_grey;
    std::vector<unsigned char> palette;
    if (!grey_pass(im, {rows, w})) {
        color_type = png_palette;
        if (!palette_pass(im, {rows, w}, palette)) {
            color_type = png_rgb;
            palette.clear();
            row_bytes = 3 * w;
            rgb_pass(im, {rows, row_bytes});
        }
    }
    return png_file({rows, static_cast<std::size_t>(height) * (row_bytes + 1)}, width, height, color_type, palette,
                    static_cast<std::uint32_t>(std::lround(dpi / 0.0254)));
}

std::string render_png(const figure& fig, const theme& th, double dpi) {
    check_raster_size(fig, th, dpi);
    const page_size size = figure_size(fig, th);
    const double scale = dpi / 72.0;
    const int width = static_cast<int>(std::lround(size.width_pt * scale));
    const int height = static_cast<int>(std::lround(size.height_pt * scale));
    const int stride = cairo_format_stride_for_width(CAIRO_FORMAT_RGB24, width);
    const page_buffer memory(static_cast<std::size_t>(stride) * static_cast<std::size_t>(height));
    surface_ptr surface(
        cairo_image_surface_create_for_data(memory.data(), CAIRO_FORMAT_RGB24, width, height, stride));
    draw_on(surface.get(), fig, th, size, scale, "png");
    cairo_surface_flush(surface.get());
    // The rows in pages of their own: no pass over them to zero them first (a vector's), and
    // the pages an RGB image would need beyond a grey one's are never touched.
    const page_buffer rows(png_rows_bytes(width, height));
    return png_of(memory.data(), stride, width, height, dpi, rows.data());
}

/// The SVG with a <title> and a <desc> first in its root element, as SVG's accessibility
/// rules ask.
std::string with_svg_words(std::string svg, const std::string& title, const std::string& description) {
    std::string words;
    // Markup's escapes are XML's.
    if (!title.empty()) words += "\n<title>" + escape_markup(title) + "</title>";
    if (!description.empty()) words += "\n<desc>" + escape_markup(description) + "</desc>";
    if (words.empty()) return svg;
    const auto root = svg.find("<svg");
    const auto end = root == std::string::npos ? root : svg.find('>', root);
    if (end == std::string::npos) throw std::runtime_error("Cairo wrote an SVG without a root element");
    svg.insert(end + 1, words);
    return svg;
}

/// The root element's size as the theme asks: points (as Cairo writes it), CSS pixels
/// (96 to the inch), or none, the viewBox alone (Cairo's), so that the drawing fills the
/// width a page gives it.
std::string with_svg_size(std::string svg, page_size size, svg_size_unit unit) {
    if (unit == svg_size_unit::pt) return svg;  // as Cairo writes it
    const auto root = svg.find("<svg");
    const auto end = root == std::string::npos ? root : svg.find('>', root);
    if (end == std::string::npos) throw std::runtime_error("Cairo wrote an SVG without a root element");
    std::string head = svg.substr(root, end - root);
    for (const char* attribute : {" width=\"", " height=\""}) {
        const auto at = head.find(attribute);
        if (at == std::string::npos) throw std::runtime_error("Cairo wrote an SVG without a size");
        const auto close = head.find('"', at + std::strlen(attribute));
        head.erase(at, close + 1 - at);
    }
    const double px = 96.0 / 72.0;
    std::string sized;
    if (unit == svg_size_unit::px) {
        sized = " width=\"" + svg_number(size.width_pt * px) + "\" height=\"" + svg_number(size.height_pt * px) + "\"";
    }
    if (head.find(" viewBox=\"") == std::string::npos) {
        sized += " viewBox=\"0 0 " + svg_number(size.width_pt) + " " + svg_number(size.height_pt) + "\"";
    }
    const auto name_end = std::string("<svg").size();
    head.insert(name_end, sized);
    svg.replace(root, end - root, head);
    return svg;
}

std::string write_svg(const figure& fig, const theme& th, const output_options&) {
    const bool as_text = th.svg_text == svg_text_mode::text;
    std::vector<placed_text> texts;
    figure_words words;
    std::string svg = renumber_svg_ids(render_vector(
        fig, th, "svg",
        [](std::string* bytes, page_size size) {
            cairo_surface_t* s = cairo_svg_surface_create_for_stream(append_bytes, bytes, size.width_pt, size.height_pt);
            cairo_svg_surface_set_document_unit(s, CAIRO_SVG_UNIT_PT);
            return s;
        },
        as_text ? &texts : nullptr,
        [&fig, &words](cairo_surface_t*, const drawing& drawn) { words = metadata_words(fig, drawn); }));
    if (as_text) {
        const auto close = svg.rfind("</svg>");
        if (close == std::string::npos) throw std::runtime_error("Cairo wrote an SVG without an end");
        svg.insert(close, svg_text_elements(texts, th));
    }
    svg = with_svg_size(std::move(svg), figure_size(fig, th), th.svg_size);
    svg = with_svg_words(std::move(svg), words.alt, words.description);
    return prefix_svg_ids(svg, svg_id_prefix(svg));
}

/// Cairo gives an EPS the bounding box of its ink; a page without a background would shrink
/// to its drawing, and be placed and scaled otherwise than the PDF and SVG of the figure.
/// The box is the page, as it is with a background, in whole points rounded up; cairo puts
/// the page's top at the rounded height, so the exact box (%%HiResBoundingBox, which
/// ghostscript's EPSCrop and graphicx's hiresbb read) is the page's size below that.
std::string eps_page_box(const std::string& eps, page_size size) {
    const double w = std::ceil(size.width_pt - 1e-6);
    const double h = std::ceil(size.height_pt - 1e-6);
    char box[64];
    std::snprintf(box, sizeof box, " 0 0 %.0f %.0f", w, h);
    char exact[96];
    std::snprintf(exact, sizeof exact, "%%%%HiResBoundingBox: 0 %.3f %.3f %.0f\n", h - size.height_pt, size.width_pt, h);
    std::string out = eps;
    for (const std::string key : {"%%BoundingBox:", "%%PageBoundingBox:"}) {
        const auto start = out.find("\n" + key);
        if (start == std::string::npos) continue;
        const auto from = start + 1 + key.size();
        const auto end = out.find('\n', from);
        out.replace(from, end == std::string::npos ? std::string::npos : end - from, box);
        if (key == "%%BoundingBox:" && out.find("\n%%HiResBoundingBox:") == std::string::npos) {
            const auto line_end = out.find('\n', from);
            if (line_end != std::string::npos) out.insert(line_end + 1, exact);
        }
    }
    return out;
}

std::string render_eps(const figure& fig, const theme& th, const output_options&, std::vector<placed_text>* texts) {
    return eps_page_box(fix_eps_date(render_vector(
        fig, th, "eps",
        [](std::string* bytes, page_size size) {
            cairo_surface_t* s = cairo_ps_surface_create_for_stream(append_bytes, bytes, size.width_pt, size.height_pt);
            cairo_ps_surface_set_eps(s, 1);
            return s;
        },
        texts)), figure_size(fig, th));
}

std::string write_eps(const figure& fig, const theme& th, const output_options& options) {
    return render_eps(fig, th, options, nullptr);
}

/// Overlay formats write two files; standard output can take only one.
std::string refuse_one_stream(const figure&, const theme&, const output_options&) {
    throw bad_input(format_names([](const format_row& f) { return !f.graphics.empty(); }, " and ") +
                    " write two files (the drawing and its LaTeX text); give an output directory, not -o -");
}

std::string render_gif(const figure& fig, const theme& th, const output_options& options) {
    if (!(options.dpi >= min_dpi && options.dpi <= max_dpi)) {
        throw bad_input("dpi must be between 10 and 2400");
    }
    const argb_image image = render_argb(fig, th, options.dpi);
    std::vector<rgb> inks = th.palette;
    inks.push_back(th.foreground);
    gif_encoder gif(image.width, image.height, gif_palette(inks, th.background, 16), 1);
    gif.add_frame(image.data.data(), image.stride);
    return gif.finish();
}

std::string render_raster(const figure& fig, const theme& th, const output_options& options) {
    if (!(options.dpi >= min_dpi && options.dpi <= max_dpi)) {
        throw bad_input("dpi must be between 10 and 2400");
    }
    return render_png(fig, th, options.dpi);
}

/// A GIF's frame delays are whole hundredths of a second, and browsers play a delay below
/// 2/100 s as 1/10 s: above 50 frames per second some frames would crawl. Below it, a rate
/// is played at the nearest that gives every frame the same delay (gif_playback_rate).
void check_gif_frame_rate(double fps) {
    if (fps <= 50) return;
    const auto rate = [](int k) { return rate_text(100.0 / k); };
    const int k = std::max(2, static_cast<int>(std::floor(100 / fps)));
    char given[32];
    std::snprintf(given, sizeof given, "%g", fps);
    throw bad_input("fps = " + std::string(given) +
                    ": a GIF plays 100/k frames per second (k whole, at least 2), at most 50; nearest: " + rate(k) +
                    " or " + rate(k + 1));
}

// Every output format: one row each, with all that the format means. A format is written
// by its row's functions, so a format without a writer cannot be listed.
//  name, description,
//  still writer, overlay's graphics format, writer under an overlay, raster, animation writer, what it animates as,
//  the file of an animation's frame, the check of its frame rate, the rate it plays
// Videos play at any rate the specs allow (1 to 120 frames per second): the frame rate is
// a fraction that H.264 and MP4 keep exactly, and WebM's millisecond times within 0.5 ms.
constexpr format_row formats[] = {
    {"png", "raster at --dpi",
     render_raster, {}, nullptr, true, write_png_animation, "numbered PNG frames (ID-0001.png, ...)", png_frame_file, nullptr, false, nullptr},
    {"pdf", "vector, fonts embedded",
     write_pdf, {}, render_pdf, false, write_pdf_animation, "a PDF of one page per frame", pdf_animation_file, nullptr, false, nullptr},
    {"svg", "vector, for the web",
     write_svg, {}, nullptr, false, nullptr, {}, nullptr, nullptr, false, nullptr},
    {"eps", "vector, for latex and dvips",
     write_eps, {}, render_eps, false, nullptr, {}, nullptr, nullptr, false, nullptr},
    {"gif", "animation that loops; one frame for a still figure",
     render_gif, {}, nullptr, true, write_gif_animation, "a looping GIF", gif_animation_file, check_gif_frame_rate, true, gif_playback_rate},
    {"mp4", "video (H.264) for slides and browsers; animations only",
     nullptr, {}, nullptr, true, write_mp4_animation, "an MP4 video (H.264)", mp4_animation_file, nullptr, true, nullptr},
    {"webm", "video (VP9) for browsers; animations only",
     nullptr, {}, nullptr, true, write_webm_animation, "a WebM video (VP9)", webm_animation_file, nullptr, true, nullptr},
    {"pdf_tex", "ID.pdf without text and ID.pdf_tex setting the text in the document's fonts (pdflatex)",
     refuse_one_stream, "pdf", nullptr, false, nullptr, {}, nullptr, nullptr, false, nullptr},
    {"eps_tex", "ID.eps without text and ID.eps_tex setting the text in the document's fonts (latex, dvips)",
     refuse_one_stream, "eps", nullptr, false, nullptr, {}, nullptr, nullptr, false, nullptr},
};

}  // namespace

std::string png_of_pixels(const argb_image& image, double dpi, std::vector<unsigned char>& scratch) {
    if (!image.rgb24) throw std::invalid_argument("a PNG is made of RGB24 pixels");
    const std::size_t size = png_rows_bytes(image.width, image.height);
    if (scratch.size() < size) scratch.resize(size);  // frames of one size: zeroed once
    return png_of(image.data.data(), image.stride, image.width, image.height, dpi, scratch.data());
}

std::span<const format_row> format_table() { return formats; }

void check_raster_size(const figure& fig, const theme& th, double dpi) {
    const page_size size = figure_size(fig, th);
    const double w = std::round(size.width_pt * dpi / 72.0);
    const double h = std::round(size.height_pt * dpi / 72.0);
    if (w >= 1 && h >= 1 && w <= max_raster_side && h <= max_raster_side && w * h <= max_raster_pixels) return;
    const auto whole = [](double v) {
        char text[32];
        std::snprintf(text, sizeof text, "%.0f", v);
        return std::string(text);
    };
    const std::string raster = "a raster of " + whole(w) + " x " + whole(h) + " pixels";
    const std::string dpis = "--dpi " + whole(min_dpi) + " to " + whole(max_dpi);
    const std::string sizes = "figure_width_cm and figure_height_cm, or panel_width_cm";
    if (!(w >= 1 && h >= 1)) {
        // The least dpi at which the shorter side is a pixel at least.
        double least = std::ceil(0.5 * 72.0 / std::min(size.width_pt, size.height_pt));
        if (std::isfinite(least) && std::round(std::min(size.width_pt, size.height_pt) * least / 72.0) < 1) ++least;
        if (!(least <= max_dpi)) {
            throw bad_input(raster + " is too small at any resolution (" + dpis + "): make the figure larger (" +
                            sizes + ")");
        }
        throw bad_input(raster + " is too small (at least 1 a side); --dpi " + whole(std::max(least, min_dpi)) +
                        " is the least for this figure");
    }
    // The largest dpi that fits both limits.
    const double by_side = max_raster_side * 72.0 / std::max(size.width_pt, size.height_pt);
    const double by_area = std::sqrt(max_raster_pixels / (size.width_pt * size.height_pt)) * 72.0;
    const double most = std::floor(std::min(by_side, by_area));
    const std::string limits = " (at most " + std::to_string(max_raster_side) + " a side and 100 million in all)";
    if (!(most >= min_dpi)) {
        throw bad_input(raster + " is too large" + limits + ", and too large at any resolution (" + dpis +
                        "): make the figure smaller (" + sizes + "), or give it fewer panels");
    }
    throw bad_input(raster + " is too large" + limits + "; --dpi " + whole(std::min(most, max_dpi)) +
                    " is the most for this figure");
}

std::string pdf_creation_date() {
    const auto tm = source_date();
    if (!tm) return "";
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &*tm);
    return date;
}

std::vector<std::string> format_names() {
    std::vector<std::string> names;
    for (const auto& f : formats) names.emplace_back(f.name);
    return names;
}

std::string format_names(bool (*keep)(const format_row&), std::string_view last) {
    std::vector<std::string_view> names;
    for (const auto& f : formats) {
        if (keep(f)) names.push_back(f.name);
    }
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) out += i + 1 == names.size() ? last : ", ";
        out += names[i];
    }
    return out;
}

const format_row& find_format(std::string_view format) {
    for (const auto& f : formats) {
        if (f.name == format) return f;
    }
    std::string list;
    for (const auto& f : formats) list += (list.empty() ? "" : ", ") + std::string(f.name);
    throw bad_input("unknown format '" + std::string(format) + "'; formats: " + list);
}

void check_format(std::string_view format) { find_format(format); }

void check_still_format(std::string_view format) {
    const format_row& row = find_format(format);
    if (row.write) return;
    throw bad_input(std::string(format) + " holds animations only; a still figure, or one frame of an animation (--at): " +
                    format_names([](const format_row& f) { return f.write != nullptr; }, " or "));
}

std::string render(const figure& fig, const theme& th, std::string_view format, const output_options& options) {
    check_still_format(format);
    return find_format(format).write(fig, th, options);
}

namespace {

/// True if path is a regular file (not a link to one) that holds exactly these bytes.
bool holds(const std::filesystem::path& path, const std::string& bytes) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(std::filesystem::symlink_status(path, ec)) ||
        std::filesystem::file_size(path, ec) != bytes.size() || ec) {
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    std::string old(bytes.size(), '\0');
    return in.read(old.data(), static_cast<std::streamsize>(old.size())) && old == bytes;
}

}  // namespace

bool write_if_changed(const std::filesystem::path& path, const std::string& bytes) {
    if (holds(path, bytes)) return false;
    write_atomically(path, bytes);
    return true;
}

overlay_files render_overlay(const figure& fig, const theme& th, std::string_view graphics_format,
                             const std::string& graphics_name, const output_options& options) {
    const theme sized = latex_sized_theme(th, options);
    std::vector<placed_text> texts;
    overlay_files files;
    const format_row& graphics = find_format(graphics_format);
    if (!graphics.write_without_text) {
        throw std::logic_error("format " + std::string(graphics_format) + " cannot be drawn under an overlay");
    }
    files.graphics = graphics.write_without_text(fig, sized, options, &texts);
    files.tex = latex_picture(texts, figure_size(fig, sized), sized, graphics_name, options);
    return files;
}

namespace {

/// save, without the file's name in layout errors.
void save_unnamed(const figure& fig, const theme& th, const std::filesystem::path& path, const output_options& options) {
    std::string ext = path.extension().string();
    if (!ext.empty()) ext.erase(0, 1);
    const auto write = [&](const std::filesystem::path& p, const std::string& bytes) {
        if (options.force) {
            write_atomically(p, bytes);
        } else {
            write_if_changed(p, bytes);
        }
    };
    check_still_format(ext);
    const format_row& row = find_format(ext);
    if (!row.graphics.empty()) {
        auto graphics = path;
        graphics.replace_extension(row.graphics);
        const overlay_files files = render_overlay(fig, th, row.graphics, graphics.filename().string(), options);
        // The pair changes together: both on disk before either is renamed, the drawing
        // first, so that the text never refers to a missing file; and both are written if
        // either changed, so that a pair another run renamed meanwhile is replaced whole.
        if (options.force || !holds(graphics, files.graphics) || !holds(path, files.tex)) {
            write_atomically({{graphics, files.graphics}, {path, files.tex}});
        }
        return;
    }
    write(path, row.write(fig, th, options));
}

}  // namespace

void save(const figure& fig, const theme& th, const std::filesystem::path& path, const output_options& options) {
    try {
        save_unnamed(fig, th, path, options);
    } catch (const layout_error& e) {
        throw layout_error(path.filename().string() + ": " + e.what());
    }
}

}  // namespace plot
