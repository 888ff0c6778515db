// SPDX-License-Identifier: GPL-3.0-or-later
// The video module (see video_module.hpp): video through libavformat and libavcodec,
// frames converted to BT.709 yuv420p in integer arithmetic here, every handle owned, every status checked, the libraries' log kept out of the
// terminal and put into the error instead. Built as a shared object of its own; it uses
// nothing of the program but the types in video_module.hpp.
#include "plot/video_module.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/dict.h>
#include <libavutil/error.h>
#include <libavutil/log.h>
#include <libavutil/rational.h>
}

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <new>
#include <string>
#include <stdexcept>
#include <vector>

namespace plot {

namespace {

struct av_deleter {
    void operator()(AVFormatContext* p) const {
        if (p->pb && !(p->oformat->flags & AVFMT_NOFILE)) avio_closep(&p->pb);
        avformat_free_context(p);
    }
    void operator()(AVCodecContext* p) const { avcodec_free_context(&p); }
    void operator()(AVPacket* p) const { av_packet_free(&p); }
    void operator()(AVDictionary* p) const { av_dict_free(&p); }
};

using format_ptr = std::unique_ptr<AVFormatContext, av_deleter>;
using codec_ptr = std::unique_ptr<AVCodecContext, av_deleter>;
using packet_ptr = std::unique_ptr<AVPacket, av_deleter>;

/// An AVDictionary that frees itself; `get` is what the libraries' functions take.
struct dictionary {
    AVDictionary* d = nullptr;
    dictionary() = default;
    dictionary(const dictionary&) = delete;
    dictionary& operator=(const dictionary&) = delete;
    ~dictionary() { av_dict_free(&d); }
    AVDictionary** get() { return &d; }
};

/// The last error the libraries logged on this thread: their messages go into ours.
thread_local std::string last_logged;

void keep_errors(void* avcl, int level, const char* fmt, std::va_list args) {
    if (level > AV_LOG_ERROR) return;
    char line[512];
    int prefix = 0;
    av_log_format_line2(avcl, level, fmt, args, line, sizeof line, &prefix);
    std::string text = line;
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    if (!text.empty()) last_logged = text;
}

void quiet_libraries() {
    static std::once_flag once;
    std::call_once(once, [] { av_log_set_callback(keep_errors); });
}

/// "cannot write NAME: WHAT: the library's reason (its log's last error)".
[[noreturn]] void fail(const std::string& shown, const std::string& what, int code) {
    char reason[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, reason, sizeof reason);
    std::string message = "cannot write " + shown + ": " + what + ": " + reason;
    if (!last_logged.empty()) message += " (" + last_logged + ")";
    last_logged.clear();
    if (code == AVERROR(ENOMEM)) throw std::bad_alloc();
    throw std::runtime_error(message);
}

void check(int code, const std::string& shown, const std::string& what) {
    if (code < 0) fail(shown, what, code);
}

/// A converted frame: an AVFrame, freed with it.
struct av_pixels final : video_frame::pixels {
    AVFrame* frame = av_frame_alloc();
    av_pixels() {
        if (!frame) throw std::bad_alloc();
    }
    av_pixels(const av_pixels&) = delete;
    av_pixels& operator=(const av_pixels&) = delete;
    ~av_pixels() override { av_frame_free(&frame); }
};

std::pair<int, int> frame_rate(double fps) {
    const AVRational q = av_d2q(fps, 1000000);
    return {q.num, q.den};
}

/// BT.709 limited range, in 16-bit fixed point: Y = 16 + 219/255 (Kr R + Kg G + Kb B), and the
/// colour differences scaled by 224/255 around 128.
constexpr int fixed(double x) { return x >= 0 ? static_cast<int>(x * 65536 + 0.5) : -static_cast<int>(-x * 65536 + 0.5); }
constexpr double bt709_kr = 0.2126;
constexpr double bt709_kb = 0.0722;
constexpr double bt709_kg = 1 - bt709_kr - bt709_kb;
constexpr double luma_scale = 219.0 / 255;
constexpr double chroma_scale = 224.0 / 255;
constexpr int y_r = fixed(luma_scale * bt709_kr);
constexpr int y_g = fixed(luma_scale * bt709_kg);
constexpr int y_b = fixed(luma_scale * bt709_kb);
constexpr int u_r = fixed(-chroma_scale * bt709_kr / (2 * (1 - bt709_kb)));
constexpr int u_g = fixed(-chroma_scale * bt709_kg / (2 * (1 - bt709_kb)));
constexpr int u_b = fixed(chroma_scale * 0.5);
constexpr int v_r = fixed(chroma_scale * 0.5);
constexpr int v_g = fixed(-chroma_scale * bt709_kg / (2 * (1 - bt709_kr)));
constexpr int v_b = fixed(-chroma_scale * bt709_kb / (2 * (1 - bt709_kr)));

/// One row of luma from Cairo's native-endian xRGB words.
void luma_row(const std::uint32_t* __restrict pixels, std::uint8_t* __restrict out, int width) {
    for (int x = 0; x < width; ++x) {
        const std::uint32_t p = pixels[x];
        const int r = static_cast<int>((p >> 16) & 255U);
        const int g = static_cast<int>((p >> 8) & 255U);
        const int b = static_cast<int>(p & 255U);
        out[x] = static_cast<std::uint8_t>((y_r * r + y_g * g + y_b * b + (16 << 16) + (1 << 15)) >> 16);
    }
}

/// One row of each colour difference from two rows of pixels: each sample from the mean of
/// its 2 x 2 pixels (red and blue summed in one word, bits 16-25 and 0-9, green apart).
void chroma_row(const std::uint32_t* __restrict row0, const std::uint32_t* __restrict row1, std::uint8_t* __restrict u,
                std::uint8_t* __restrict v, int half_width) {
    for (int i = 0; i < half_width; ++i) {
        const std::uint32_t a = row0[2 * i];
        const std::uint32_t b = row0[2 * i + 1];
        const std::uint32_t c = row1[2 * i];
        const std::uint32_t d = row1[2 * i + 1];
        const std::uint32_t rb = (a & 0xff00ffU) + (b & 0xff00ffU) + (c & 0xff00ffU) + (d & 0xff00ffU);
        const std::uint32_t g = ((a >> 8) & 255U) + ((b >> 8) & 255U) + ((c >> 8) & 255U) + ((d >> 8) & 255U);
        const int red = static_cast<int>(rb >> 16);
        const int green = static_cast<int>(g);
        const int blue = static_cast<int>(rb & 0xffffU);
        u[i] = static_cast<std::uint8_t>((u_r * red + u_g * green + u_b * blue + (128 << 18) + (1 << 17)) >> 18);
        v[i] = static_cast<std::uint8_t>((v_r * red + v_g * green + v_b * blue + (128 << 18) + (1 << 17)) >> 18);
    }
}

/// Converts the rows y and y + 1, columns [x0, x1) (even), of pixels (Cairo's xRGB words,
/// `stride` bytes a row) into the planes of a yuv420p frame.
void convert_rows(const unsigned char* pixels, int stride, int y, int x0, int x1, AVFrame* frame) {
    const auto* row0 = reinterpret_cast<const std::uint32_t*>(pixels + static_cast<std::size_t>(y) * stride) + x0;
    const auto* row1 = reinterpret_cast<const std::uint32_t*>(pixels + static_cast<std::size_t>(y + 1) * stride) + x0;
    std::uint8_t* luma = frame->data[0] + static_cast<std::size_t>(y) * frame->linesize[0] + x0;
    luma_row(row0, luma, x1 - x0);
    luma_row(row1, luma + frame->linesize[0], x1 - x0);
    const std::size_t chroma = static_cast<std::size_t>(y / 2);
    chroma_row(row0, row1, frame->data[1] + chroma * frame->linesize[1] + x0 / 2,
               frame->data[2] + chroma * frame->linesize[2] + x0 / 2, (x1 - x0) / 2);
}

/// Copies the rows y and y + 1, columns [x0, x1) (even), of a yuv420p frame into another.
void copy_rows(const AVFrame* from, int y, int x0, int x1, AVFrame* to) {
    if (x1 <= x0) return;
    for (int k = 0; k < 2; ++k) {
        std::memcpy(to->data[0] + static_cast<std::size_t>(y + k) * to->linesize[0] + x0,
                    from->data[0] + static_cast<std::size_t>(y + k) * from->linesize[0] + x0,
                    static_cast<std::size_t>(x1 - x0));
    }
    const std::size_t chroma = static_cast<std::size_t>(y / 2);
    for (int plane = 1; plane <= 2; ++plane) {
        std::memcpy(to->data[plane] + chroma * to->linesize[plane] + x0 / 2,
                    from->data[plane] + chroma * from->linesize[plane] + x0 / 2,
                    static_cast<std::size_t>(x1 - x0) / 2);
    }
}

/// Pixels of even width and height (Cairo's xRGB words, `stride` bytes a row) into the
/// planes of a yuv420p frame: integer arithmetic, so the same bytes on every CPU. libswscale
/// gives those only on its bit-exact path, which took 2.5 times as long.
void to_yuv420p(const unsigned char* pixels, int stride, int width, int height, AVFrame* frame) {
    for (int y = 0; y < height; y += 2) convert_rows(pixels, stride, y, 0, width, frame);
}

/// A picture in Cairo's xRGB words: its first byte and its bytes a row.
struct xrgb_view {
    const unsigned char* pixels = nullptr;
    int stride = 0;
    /// The first byte of row y.
    const unsigned char* row(int y) const { return pixels + static_cast<std::size_t>(y) * stride; }
};

/// Pixels compared with the still at a time: a frame's moving parts are converted in blocks of
/// this many columns (even) of a pair of rows.
constexpr int compared_block = 64;

/// Whether the rows y and y + 1, columns [x0, x1), of `frame` are those of `still`.
bool same_block(xrgb_view frame, xrgb_view still, int y, int x0, int x1) {
    const std::size_t offset = 4 * static_cast<std::size_t>(x0);
    const std::size_t bytes = 4 * static_cast<std::size_t>(x1 - x0);
    return std::memcmp(frame.row(y) + offset, still.row(y) + offset, bytes) == 0 &&
           std::memcmp(frame.row(y + 1) + offset, still.row(y + 1) + offset, bytes) == 0;
}

/// The rows y and y + 1 of a frame drawn over `still` (converted as `still_frame`) into
/// `frame`: each block the same as the still's copied, each other converted. Returns the
/// pixels converted.
std::uint64_t convert_pair_over(xrgb_view pixels, xrgb_view still, const AVFrame* still_frame, int y, int width,
                                AVFrame* frame) {
    if (same_block(pixels, still, y, 0, width)) {
        copy_rows(still_frame, y, 0, width, frame);
        return 0;
    }
    std::uint64_t converted = 0;
    for (int x0 = 0; x0 < width; x0 += compared_block) {
        const int x1 = std::min(width, x0 + compared_block);
        if (same_block(pixels, still, y, x0, x1)) {
            copy_rows(still_frame, y, x0, x1, frame);
        } else {
            convert_rows(pixels.pixels, pixels.stride, y, x0, x1, frame);
            converted += 2 * static_cast<std::uint64_t>(x1 - x0);
        }
    }
    return converted;
}

/// As to_yuv420p, for a frame drawn over `still`, whose conversion is `still_frame`: only the
/// columns of each pair of rows that differ from the still are converted, the rest copied
/// (the same bytes as converting all). Returns the pixels converted.
std::uint64_t to_yuv420p_over(xrgb_view pixels, xrgb_view still, const AVFrame* still_frame, int width, int height,
                              AVFrame* frame) {
    std::uint64_t converted = 0;
    for (int y = 0; y < height; y += 2) converted += convert_pair_over(pixels, still, still_frame, y, width, frame);
    return converted;
}

struct state {
    std::string shown;
    int width = 0;         // of the frames drawn
    int height = 0;
    int coded_width = 0;   // of the video: even
    int coded_height = 0;
    format_ptr format;
    codec_ptr codec;
    AVStream* stream = nullptr;
    packet_ptr packet;
    std::int64_t next_pts = 0;
    bool finished = false;
    // The still every frame is drawn over (keep_against), its even-sided copy if the frames
    // are padded, and its conversion; pixels == nullptr without one.
    xrgb_view still;
    std::vector<unsigned char> still_padded;
    std::unique_ptr<av_pixels> still_frame;
    std::atomic<std::uint64_t> converted{0};  // pixels converted, not copied from the still
    // Converted frames the encoder has taken (it copies them), kept for the next ones: as
    // many as are ever in flight. Freed and allocated afresh, each frame is mapped and
    // unmapped, or glibc keeps freed ones in each thread's arena (21 MB more at 1080p).
    std::mutex pool_mutex;
    std::vector<std::unique_ptr<av_pixels>> pool;

    /// A frame of the coded size, from the pool if it holds one.
    std::unique_ptr<av_pixels> reused_frame() {
        {
            std::lock_guard lock(pool_mutex);
            while (!pool.empty()) {
                std::unique_ptr<av_pixels> frame = std::move(pool.back());
                pool.pop_back();
                // Only a frame no one else refers to may take new pixels.
                if (av_frame_is_writable(frame->frame)) return frame;
            }
        }
        auto frame = std::make_unique<av_pixels>();
        AVFrame* f = frame->frame;
        f->format = AV_PIX_FMT_YUV420P;
        f->width = coded_width;
        f->height = coded_height;
        check(av_frame_get_buffer(f, 0), shown, "cannot hold a frame");
        return frame;
    }

    /// The pixels of `image` with even sides (padded: an odd side gets a copy of its last row
    /// or column, in `padded`); throws std::logic_error if it is not of the frames' size.
    xrgb_view coded_pixels(const argb_image& image, std::vector<unsigned char>& padded) const {
        if (image.width != width || image.height != height) {
            throw std::logic_error("a video frame of " + std::to_string(image.width) + " x " +
                                   std::to_string(image.height) + " pixels, not " + std::to_string(width) + " x " +
                                   std::to_string(height));
        }
        if (coded_width == width && coded_height == height) return {image.data.data(), image.stride};
        const int stride = 4 * coded_width;
        padded.resize(static_cast<std::size_t>(stride) * static_cast<std::size_t>(coded_height));
        for (int y = 0; y < coded_height; ++y) {
            const unsigned char* from = image.data.data() + static_cast<std::size_t>(std::min(y, height - 1)) * image.stride;
            unsigned char* to = padded.data() + static_cast<std::size_t>(y) * stride;
            std::memcpy(to, from, 4 * static_cast<std::size_t>(width));
            if (coded_width != width) std::memcpy(to + 4 * width, from + 4 * (width - 1), 4);
        }
        return {padded.data(), stride};
    }

    /// A frame the encoder has taken, back into the pool.
    void recycle(std::unique_ptr<av_pixels> frame) {
        std::lock_guard lock(pool_mutex);
        pool.push_back(std::move(frame));
    }

    /// Sends a frame (null: the end) and writes the packets that come out.
    void encode(AVFrame* frame) {
        check(avcodec_send_frame(codec.get(), frame), shown, "cannot encode a frame");
        for (;;) {
            const int r = avcodec_receive_packet(codec.get(), packet.get());
            if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
            check(r, shown, "cannot encode a frame");
            // Every frame shows for one frame's time, the last one too.
            if (packet->duration == 0) packet->duration = 1;
            av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            check(av_interleaved_write_frame(format.get(), packet.get()), shown, "write error");
        }
    }
};

/// A video file being written.
class av_sink final : public video_sink {
public:
    av_sink(const std::filesystem::path& path, const std::string& shown, const video_kind& kind, int width,
            int height, double fps, const std::string& creation_date);
    video_frame convert(const argb_image& image) const override;
    void keep_against(const argb_image& still) override;
    std::uint64_t pixels_converted() const override;
    void add(video_frame frame) override;
    void finish() override;

private:
    std::unique_ptr<state> state_ = std::make_unique<state>();
};

av_sink::av_sink(const std::filesystem::path& path, const std::string& shown, const video_kind& kind, int width,
                 int height, double fps, const std::string& creation_date) {
    quiet_libraries();
    last_logged.clear();
    state& s = *state_;
    s.shown = shown;
    s.width = width;
    s.height = height;
    std::tie(s.coded_width, s.coded_height) = video_size(width, height);
    AVFormatContext* raw = nullptr;
    check(avformat_alloc_output_context2(&raw, nullptr, kind.container, path.c_str()), shown,
          std::string("libavformat cannot write ") + kind.container);
    s.format.reset(raw);
    // No library version, no random ids: the same frames, the same bytes.
    s.format->flags |= AVFMT_FLAG_BITEXACT;
    const AVCodec* encoder = avcodec_find_encoder_by_name(kind.encoder);
    if (!encoder) {
        throw std::runtime_error("cannot write " + shown + ": libavcodec has no " + kind.encoder +
                                 " encoder (Debian's libavcodec59 has it)");
    }
    s.stream = avformat_new_stream(s.format.get(), nullptr);
    s.codec.reset(avcodec_alloc_context3(encoder));
    s.packet.reset(av_packet_alloc());
    if (!s.stream || !s.codec || !s.packet) throw std::bad_alloc();
    AVCodecContext* c = s.codec.get();
    c->width = s.coded_width;
    c->height = s.coded_height;
    c->pix_fmt = AV_PIX_FMT_YUV420P;
    const auto [num, den] = frame_rate(fps);
    c->time_base = AVRational{den, num};
    c->framerate = AVRational{num, den};
    // A key frame every two seconds: players seek and loop without decoding much.
    c->gop_size = std::max(1, static_cast<int>(std::lround(2 * fps)));
    // BT.709 in limited range, said in the stream so that players convert it back alike.
    c->color_primaries = AVCOL_PRI_BT709;
    c->color_trc = AVCOL_TRC_BT709;
    c->colorspace = AVCOL_SPC_BT709;
    c->color_range = AVCOL_RANGE_MPEG;
    c->chroma_sample_location = AVCHROMA_LOC_LEFT;
    c->thread_count = kind.threads;
    c->flags |= AV_CODEC_FLAG_BITEXACT;
    if (s.format->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    dictionary codec_options;
    check(av_dict_parse_string(codec_options.get(), kind.codec_options, "=", ":", 0), shown, "bad encoder options");
    check(avcodec_open2(c, encoder, codec_options.get()), shown, std::string("cannot open ") + kind.encoder);
    if (av_dict_count(codec_options.d) > 0) {
        throw std::logic_error(std::string(kind.encoder) + " took not every option of " + kind.codec_options);
    }
    check(avcodec_parameters_from_context(s.stream->codecpar, c), shown, "cannot set up the stream");
    s.stream->time_base = c->time_base;
    s.stream->avg_frame_rate = c->framerate;
    if (!creation_date.empty()) av_dict_set(&s.format->metadata, "creation_time", creation_date.c_str(), 0);
    check(avio_open(&s.format->pb, path.c_str(), AVIO_FLAG_WRITE), shown, "cannot open");
    dictionary muxer_options;
    check(av_dict_parse_string(muxer_options.get(), kind.muxer_options, "=", ":", 0), shown, "bad muxer options");
    check(avformat_write_header(s.format.get(), muxer_options.get()), shown, "cannot start the file");
    if (av_dict_count(muxer_options.d) > 0) {
        throw std::logic_error(std::string(kind.container) + " took not every option of " + kind.muxer_options);
    }
}

video_frame av_sink::convert(const argb_image& image) const {
    state& s = *state_;
    std::vector<unsigned char> padded;
    const xrgb_view pixels = s.coded_pixels(image, padded);
    std::unique_ptr<av_pixels> converted = s.reused_frame();
    AVFrame* f = converted->frame;
    if (s.still.pixels) {
        s.converted += to_yuv420p_over(pixels, s.still, s.still_frame->frame, s.coded_width, s.coded_height, f);
    } else {
        to_yuv420p(pixels.pixels, pixels.stride, s.coded_width, s.coded_height, f);
        s.converted += static_cast<std::uint64_t>(s.coded_width) * static_cast<std::uint64_t>(s.coded_height);
    }
    video_frame out;
    out.data = std::move(converted);
    return out;
}

void av_sink::keep_against(const argb_image& still) {
    state& s = *state_;
    if (s.next_pts > 0 || s.still.pixels) throw std::logic_error("a video's still set after its first frame or twice");
    const xrgb_view pixels = s.coded_pixels(still, s.still_padded);
    s.still_frame = s.reused_frame();
    to_yuv420p(pixels.pixels, pixels.stride, s.coded_width, s.coded_height, s.still_frame->frame);
    s.still = pixels;
}

std::uint64_t av_sink::pixels_converted() const { return state_->converted; }

void av_sink::add(video_frame frame) {
    state& s = *state_;
    if (s.finished) throw std::logic_error("a frame added to a finished video");
    auto* pixels = dynamic_cast<av_pixels*>(frame.data.get());
    if (!pixels) throw std::logic_error("a video frame not converted by the video module");
    pixels->frame->pts = s.next_pts++;
    s.encode(pixels->frame);
    // The encoder copied the pixels (libx264 and libvpx do): the frame may hold the next ones.
    frame.data.release();
    s.recycle(std::unique_ptr<av_pixels>(pixels));
}

void av_sink::finish() {
    state& s = *state_;
    if (s.finished) return;
    s.finished = true;
    s.encode(nullptr);
    check(av_write_trailer(s.format.get()), s.shown, "cannot end the file");
    check(avio_closep(&s.format->pb), s.shown, "write error");
}

std::unique_ptr<video_sink> open(const std::filesystem::path& path, const std::string& shown, const video_kind& kind,
                                 int width, int height, double fps, const std::string& creation_date) {
    return std::make_unique<av_sink>(path, shown, kind, width, height, fps, creation_date);
}

constexpr video_module module{video_module_version, open, frame_rate};

}  // namespace
}  // namespace plot

extern "C" const plot::video_module* pendulum_figures_video_module() { return &plot::module; }
