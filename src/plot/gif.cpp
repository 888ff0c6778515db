// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/gif.hpp"

#include "plot/errors.hpp"

#include <gif_lib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace plot {

namespace {

std::uint8_t to_byte(double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

rgb8 blend(const rgb& ink, const rgb& bg, double a) {
    return {to_byte(ink.r * a + bg.r * (1 - a)), to_byte(ink.g * a + bg.g * (1 - a)), to_byte(ink.b * a + bg.b * (1 - a))};
}

bool same(const rgb8& a, const rgb8& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

/// Deleter for a giflib colour map.
struct color_map_deleter {
    void operator()(ColorMapObject* m) const { GifFreeMapObject(m); }
};

[[noreturn]] void fail(const char* what, int error) {
    throw std::runtime_error(std::string("GIF encoding failed (") + what + "): " +
                             (GifErrorString(error) ? GifErrorString(error) : "unknown error"));
}

/// The first x in [from, to) where rows a and b differ, or `to`: whole blocks compared at a
/// time first, as most pixels of a frame are those of the still part.
int first_difference(const std::uint32_t* a, const std::uint32_t* b, int from, int to) {
    constexpr int block = 16;
    while (to - from >= block && std::memcmp(a + from, b + from, block * 4) == 0) from += block;
    while (from < to && a[from] == b[from]) ++from;
    return from;
}

/// The last x in [0, to) where rows a and b differ, which they must somewhere.
int last_difference(const std::uint32_t* a, const std::uint32_t* b, int to) {
    constexpr int block = 16;
    while (to >= block && std::memcmp(a + to - block, b + to - block, block * 4) == 0) to -= block;
    do --to;
    while (a[to] == b[to]);
    return to;
}

/// The palette index nearest to each colour of 5 bits per channel.
using nearest_colours = std::array<std::uint8_t, 32768>;

nearest_colours nearest_of(const std::vector<rgb8>& palette) {
    nearest_colours nearest{};
    for (std::uint32_t key = 0; key < nearest.size(); ++key) {
        // The centre of the 5-bit cell: a palette colour is always nearest to itself.
        const int r = static_cast<int>((key >> 10) << 3 | 4);
        const int g = static_cast<int>(((key >> 5) & 31) << 3 | 4);
        const int b = static_cast<int>((key & 31) << 3 | 4);
        int best = 0;
        int best_d = std::numeric_limits<int>::max();
        for (std::size_t i = 0; i < palette.size(); ++i) {
            const int dr = r - palette[i].r;
            const int dg = g - palette[i].g;
            const int db = b - palette[i].b;
            // Weighted towards green, as the eye is.
            const int d = 2 * dr * dr + 4 * dg * dg + 3 * db * db;
            if (d < best_d) {
                best_d = d;
                best = static_cast<int>(i);
            }
        }
        nearest[key] = static_cast<std::uint8_t>(best);
    }
    return nearest;
}

/// The table of the palette, made once for the encoders of one animation (each part of it
/// has an encoder of its own, all with one palette).
std::shared_ptr<const nearest_colours> nearest_table(const std::vector<rgb8>& palette) {
    static std::mutex mutex;
    static std::vector<rgb8> last_palette;
    static std::shared_ptr<const nearest_colours> last;
    std::lock_guard lock(mutex);
    const auto equal = [](const rgb8& a, const rgb8& b) { return same(a, b); };
    if (!last || !std::equal(palette.begin(), palette.end(), last_palette.begin(), last_palette.end(), equal)) {
        last = std::make_shared<const nearest_colours>(nearest_of(palette));
        last_palette = palette;
    }
    return last;
}

}  // namespace

std::vector<rgb8> gif_palette(const std::vector<rgb>& inks, const rgb& background, int shades) {
    std::vector<rgb8> palette{blend(background, background, 1.0)};
    auto add = [&](const rgb8& c) {
        if (palette.size() < 255 && std::none_of(palette.begin(), palette.end(), [&](const rgb8& p) { return same(p, c); })) {
            palette.push_back(c);
        }
    };
    for (const auto& ink : inks) add(blend(ink, background, 1.0));
    for (int s = 1; s < shades; ++s) {
        for (const auto& ink : inks) add(blend(ink, background, static_cast<double>(s) / shades));
    }
    // Where two inks cross, their anti-aliased edges mix.
    for (std::size_t i = 0; i < inks.size(); ++i) {
        for (std::size_t j = i + 1; j < inks.size(); ++j) add(blend(inks[i], inks[j], 0.5));
    }
    return palette;
}

struct gif_encoder::state {
    int width = 0;
    int height = 0;
    double fps = 30;
    std::vector<rgb8> palette;
    std::shared_ptr<const nearest_colours> nearest;  // 5 bits per channel -> palette index
    const std::uint32_t* reference = nullptr;  // pixels most frames share, or none
    std::ptrdiff_t reference_stride = 0;        // its pixels per row
    bool has_previous = false;                  // whether a frame was added or primed
    // The previous frame, to find what changed: per row its runs of pixels that differ from
    // the reference, each as its start, its length and its pixels (the whole row as one run
    // without a reference), so that a still background is not kept twice.
    std::vector<std::vector<std::uint32_t>> kept;
    std::vector<std::uint32_t> scratch;  // a previous row put together
    std::vector<GifPixelType> line;      // a row of the changed rectangle, as palette indices
    int transparent = -1;                  // the index that keeps the previous frame's pixel
    std::size_t head = 0;                  // bytes before the first frame
    std::string bytes;
    GifFileType* gif = nullptr;

    static int write(GifFileType* g, const GifByteType* data, int n) {
        static_cast<state*>(g->UserData)->bytes.append(reinterpret_cast<const char*>(data), static_cast<std::size_t>(n));
        return n;
    }

    std::uint8_t index_of(std::uint32_t pixel) const {
        // Cairo's ARGB32 is premultiplied; frames are opaque, so alpha is 255 and the
        // channels are the colour.
        const std::uint32_t r = (pixel >> 16) & 0xff;
        const std::uint32_t g = (pixel >> 8) & 0xff;
        const std::uint32_t b = pixel & 0xff;
        return (*nearest)[(r >> 3) << 10 | (g >> 3) << 5 | (b >> 3)];
    }

    /// Whether a pixel shows as the previous frame's did: its colour or its palette index
    /// is the same (the screen holds the index of every pixel's colour).
    bool shown_alike(std::uint32_t pixel, std::uint32_t before) const {
        return pixel == before || index_of(pixel) == index_of(before);
    }

    /// Row y of the previous frame.
    const std::uint32_t* previous_row(int y) {
        const auto& runs = kept[static_cast<std::size_t>(y)];
        if (!reference) return runs.data() + 2;
        const std::uint32_t* under = reference + y * reference_stride;
        if (runs.empty()) return under;
        std::memcpy(scratch.data(), under, static_cast<std::size_t>(width) * 4);
        for (std::size_t k = 0; k < runs.size(); k += 2 + runs[k + 1]) {
            std::memcpy(scratch.data() + runs[k], runs.data() + k + 2, runs[k + 1] * std::size_t{4});
        }
        return scratch.data();
    }

    /// Keeps row y of a frame as the previous frame's.
    void keep(int y, const std::uint32_t* pixels) {
        auto& runs = kept[static_cast<std::size_t>(y)];
        runs.clear();
        if (!reference) {
            runs.push_back(0);
            runs.push_back(static_cast<std::uint32_t>(width));
            runs.insert(runs.end(), pixels, pixels + width);
            return;
        }
        // Runs that differ, joined across fewer equal pixels than a run's start and length take.
        const std::uint32_t* under = reference + y * reference_stride;
        int x = 0;
        for (;;) {
            x = first_difference(pixels, under, x, width);
            if (x == width) break;
            const int start = x;
            int end = x;  // one past the last pixel that differs
            while (x < width) {
                if (pixels[x] != under[x]) {
                    end = ++x;
                } else if (x - end >= 2) {
                    break;
                } else {
                    ++x;
                }
            }
            runs.push_back(static_cast<std::uint32_t>(start));
            runs.push_back(static_cast<std::uint32_t>(end - start));
            runs.insert(runs.end(), pixels + start, pixels + end);
            x = end;
        }
        // What is kept stays what differs now: a row's memory does not stay at its largest.
        if (runs.capacity() > 2 * runs.size() + 64) runs.shrink_to_fit();
    }

    /// Makes room for a previous frame.
    void start_keeping() {
        kept.resize(static_cast<std::size_t>(height));
        if (reference) scratch.resize(static_cast<std::size_t>(width));
        has_previous = true;
    }

    /// A frame's pixels, `stride` bytes a row.
    struct frame {
        const unsigned char* argb;
        int stride;
        const std::uint32_t* row(int y) const {
            return reinterpret_cast<const std::uint32_t*>(argb + static_cast<std::ptrdiff_t>(y) * stride);
        }
    };

    /// A rectangle of pixels, its corners included.
    struct rect {
        int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    };

    /// The rectangle of a frame that shows differently from the previous frame (the whole
    /// frame at first; one pixel if nothing changed, which keeps the frame's delay).
    rect changed(const frame& f) {
        if (!has_previous) return {0, 0, width - 1, height - 1};
        rect r{width, height, -1, -1};
        for (int y = 0; y < height; ++y) {
            const auto* a = f.row(y);
            const auto* b = previous_row(y);
            if (std::memcmp(a, b, static_cast<std::size_t>(width) * 4) == 0) continue;
            // What changed on screen: pixels whose colour index changed.
            int left = first_difference(a, b, 0, width);
            int right = last_difference(a, b, width);
            while (left <= right && shown_alike(a[left], b[left])) ++left;
            while (right > left && shown_alike(a[right], b[right])) --right;
            if (left > right) continue;
            r.y0 = std::min(r.y0, y);
            r.y1 = y;
            r.x0 = std::min(r.x0, left);
            r.x1 = std::max(r.x1, right);
        }
        if (r.x1 < 0) return {0, 0, 0, 0};
        return r;
    }

    /// The graphics control block of frame n: its delay in hundredths of a second, rounded
    /// so that the delays add up to the true time, and the transparent index after the first.
    void put_control(int n, bool first) {
        const auto centiseconds = [&](int k) { return static_cast<int>(std::lround(100.0 * k / fps)); };
        GraphicsControlBlock gcb{};
        gcb.DisposalMode = DISPOSE_DO_NOT;
        gcb.UserInputFlag = false;
        gcb.DelayTime = centiseconds(n + 1) - centiseconds(n);
        gcb.TransparentColor = first ? NO_TRANSPARENT_COLOR : transparent;
        GifByteType ext[4];
        EGifGCBToExtension(&gcb, ext);
        if (EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, sizeof ext, ext) == GIF_ERROR) fail("delay", gif->Error);
    }

    /// Palette indices of the rectangle, a row at a time; a pixel equal to the previous
    /// frame's is transparent, which keeps it, so runs of them compress to almost nothing.
    void put_pixels(const frame& f, const rect& r, bool first) {
        const int rw = r.x1 - r.x0 + 1;
        line.resize(static_cast<std::size_t>(rw));
        for (int y = r.y0; y <= r.y1; ++y) {
            const auto* a = f.row(y);
            const auto* b = first ? nullptr : previous_row(y);
            GifPixelType* out = line.data();
            std::uint32_t last_pixel = a[r.x0] + 1;
            GifPixelType last_index = 0;
            for (int x = r.x0; x <= r.x1; ++x) {
                if (b && shown_alike(a[x], b[x])) {
                    out[x - r.x0] = static_cast<GifPixelType>(transparent);
                    continue;
                }
                if (a[x] != last_pixel) {
                    last_pixel = a[x];
                    last_index = index_of(last_pixel);
                }
                out[x - r.x0] = last_index;
            }
            if (EGifPutLine(gif, out, rw) == GIF_ERROR) fail("pixels", gif->Error);
        }
    }
};

namespace {

/// The bytes a frame of width x height pixels may take: gif_frame_bytes * (width * height)^(2/3).
double frame_bytes_bound(int width, int height) {
    const double pixels = static_cast<double>(width) * static_cast<double>(height);
    return gif_frame_bytes * std::cbrt(pixels * pixels);
}

/// What to change where a GIF would take more than max_gif_bytes, as both refusals say it.
constexpr const char* smaller_gif_advice =
    "lower --size or --dpi, the fps, or the periods or duration_s (or --frames); or write -f mp4 or webm";

}  // namespace

double gif_bytes_bound(double frames, int width, int height) {
    return (frames + gif_extra_frames) * frame_bytes_bound(width, height);
}

double gif_most_frames(int width, int height) {
    return std::max(0.0, std::floor(max_gif_bytes / frame_bytes_bound(width, height) - gif_extra_frames));
}

void check_gif_size(double frames, int width, int height) {
    const double most = gif_most_frames(width, height);
    if (frames <= most) return;
    char text[400];
    std::snprintf(text, sizeof text,
                  "%.0f frames of %d x %d pixels may take %.0f MB as a GIF, more than the %.0f MB a GIF may take "
                  "(at most %.0f frames of this size): %s",
                  frames, width, height, std::ceil(gif_bytes_bound(frames, width, height) / 1e6), max_gif_bytes / 1e6,
                  most, smaller_gif_advice);
    throw bad_input(text);
}

void check_gif_written(std::size_t bytes, int done, int frames, int width, int height) {
    if (static_cast<double>(bytes) <= max_gif_bytes) return;
    char text[400];
    std::snprintf(text, sizeof text,
                  "%d frames of %d x %d pixels: the GIF passed the %.0f MB a GIF may take after %d of them (its frames "
                  "change more than the estimate foresaw; nothing is written): %s",
                  frames, width, height, max_gif_bytes / 1e6, done, smaller_gif_advice);
    throw bad_input(text);
}

double gif_playback_rate(double fps) {
    if (!(fps > 0)) throw std::invalid_argument("a frame rate is above 0");
    const long k = std::max(2L, std::lround(100.0 / fps));
    return 100.0 / static_cast<double>(k);
}

std::string rate_text(double fps) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", fps);
    std::string s = text;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
}

gif_encoder::gif_encoder(int width, int height, std::vector<rgb8> palette, double fps, int first_frame)
    : state_(std::make_unique<state>()), first_frame_(first_frame) {
    if (width < 1 || height < 1 || width > 65535 || height > 65535) {
        throw std::invalid_argument("GIF size must be 1 to 65535 pixels each way");
    }
    if (palette.empty() || palette.size() > 255) throw std::invalid_argument("a GIF palette has 1 to 255 colours");
    if (!(fps > 0 && fps <= 100)) throw std::invalid_argument("GIF frame rate must be above 0 and at most 100");
    auto& s = *state_;
    s.width = width;
    s.height = height;
    s.fps = fps;
    s.palette = std::move(palette);
    s.nearest = nearest_table(s.palette);
    int error = 0;
    s.gif = EGifOpen(&s, &state::write, &error);
    if (!s.gif) fail("open", error);
    EGifSetGifVersion(s.gif, true);
    // One index more than the palette: the transparent one, for pixels that did not change.
    s.transparent = static_cast<int>(s.palette.size());
    int bits = 1;
    while ((1 << bits) < s.transparent + 1) ++bits;
    std::unique_ptr<ColorMapObject, color_map_deleter> map(GifMakeMapObject(1 << bits, nullptr));
    if (!map) throw std::bad_alloc();
    for (std::size_t i = 0; i < s.palette.size(); ++i) {
        map->Colors[i] = GifColorType{s.palette[i].r, s.palette[i].g, s.palette[i].b};
    }
    if (EGifPutScreenDesc(s.gif, width, height, bits, 0, map.get()) == GIF_ERROR) fail("screen", s.gif->Error);
    // NETSCAPE2.0: loop forever.
    const GifByteType app[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
    const GifByteType loop[] = {1, 0, 0};
    if (EGifPutExtensionLeader(s.gif, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
        EGifPutExtensionBlock(s.gif, sizeof app, app) == GIF_ERROR ||
        EGifPutExtensionBlock(s.gif, sizeof loop, loop) == GIF_ERROR || EGifPutExtensionTrailer(s.gif) == GIF_ERROR) {
        fail("loop", s.gif->Error);
    }
    s.head = s.bytes.size();
}

gif_encoder::~gif_encoder() {
    if (state_ && state_->gif) {
        int error = 0;
        EGifCloseFile(state_->gif, &error);
    }
}

void gif_encoder::add_frame(const unsigned char* argb, int stride) {
    auto& s = *state_;
    if (!s.gif) throw std::logic_error("GIF already finished");
    const state::frame f{argb, stride};
    const bool first = !s.has_previous;
    const state::rect r = s.changed(f);
    s.put_control(first_frame_ + frames_, first);
    if (EGifPutImageDesc(s.gif, r.x0, r.y0, r.x1 - r.x0 + 1, r.y1 - r.y0 + 1, false, nullptr) == GIF_ERROR) {
        fail("frame", s.gif->Error);
    }
    s.put_pixels(f, r, first);
    // Keep this frame's pixels (only the changed rows differ from the previous ones).
    if (first) s.start_keeping();
    for (int y = r.y0; y <= r.y1; ++y) s.keep(y, f.row(y));
    ++frames_;
}

void gif_encoder::prime(const unsigned char* argb, int stride) {
    auto& s = *state_;
    s.start_keeping();
    for (int y = 0; y < s.height; ++y) {
        s.keep(y, reinterpret_cast<const std::uint32_t*>(argb + static_cast<std::ptrdiff_t>(y) * stride));
    }
}

void gif_encoder::keep_against(const unsigned char* argb, int stride) {
    auto& s = *state_;
    if (s.has_previous) throw std::logic_error("keep_against comes before the first frame");
    if (stride < s.width * 4 || stride % 4 != 0) throw std::invalid_argument("a row of the shared pixels is too short");
    s.reference = reinterpret_cast<const std::uint32_t*>(argb);
    s.reference_stride = stride / 4;
}

std::size_t gif_encoder::kept_pixels() const {
    std::size_t n = 0;
    for (const auto& runs : state_->kept) {
        for (std::size_t k = 0; k < runs.size(); k += 2 + runs[k + 1]) n += runs[k + 1];
    }
    return n;
}

std::size_t gif_encoder::head_size() const { return state_->head; }

std::pair<std::string, std::string> gif_encoder::split(const std::string& file, std::size_t head_size) {
    if (file.size() < head_size + 1 || file.back() != ';') throw std::invalid_argument("not a finished GIF");
    return {file.substr(0, head_size), file.substr(head_size, file.size() - head_size - 1)};
}

std::string gif_encoder::finish() {
    auto& s = *state_;
    if (!s.gif) throw std::logic_error("GIF already finished");
    int error = 0;
    const int status = EGifCloseFile(s.gif, &error);
    s.gif = nullptr;
    if (status == GIF_ERROR) fail("close", error);
    return std::move(s.bytes);
}

}  // namespace plot
