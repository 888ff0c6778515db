// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/text.hpp"

#include "plot/theme.hpp"

#include "plot/errors.hpp"
#include "plot/math_layout.hpp"
#include "plot/tex_markup.hpp"

#include <fontconfig/fontconfig.h>
#include <sys/stat.h>
#include <hb.h>
#include <pango/pangofc-fontmap.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

namespace plot {

namespace {

/// Writes `text` as XML character data.
std::string xml_escaped(const char* text) {
    std::string out;
    for (const char* c = text; *c; ++c) {
        switch (*c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            default: out += *c;
        }
    }
    return out;
}

/// The fonts figures may use: the system's font directories first, then every other font
/// directory of fontconfig's own configuration (the user's fonts, /usr/local/share/fonts),
/// with their caches; none of the machine's or the user's font settings (substitutions,
/// hinting, subpixel order), which would otherwise change the pictures from one machine to
/// the next.
/// The largest FONTCONFIG_FILE read: a fonts.conf has a few kilobytes.
constexpr off_t max_fontconfig_file_bytes = 1 << 20;

/// Refuses a FONTCONFIG_FILE that fontconfig would read without bound: a device
/// (/dev/zero), FIFO or directory, or a file of more than max_fontconfig_file_bytes. One it
/// cannot find is fontconfig's to report, as before.
void check_fontconfig_file() {
    const char* file = std::getenv("FONTCONFIG_FILE");
    struct stat st {};
    if (!file || !*file || ::stat(file, &st) != 0) return;
    const std::string named = "FONTCONFIG_FILE" + (text_problem(file).empty() ? "='" + std::string(file) + "'" : std::string());
    if (!S_ISREG(st.st_mode)) {
        throw bad_input(named + " is not a regular file (a device, FIFO or directory); unset it or name a fonts.conf");
    }
    if (st.st_size > max_fontconfig_file_bytes) {
        throw bad_input(named + " has " + std::to_string(st.st_size) + " bytes; a fontconfig file here has at most " +
                        std::to_string(max_fontconfig_file_bytes));
    }
}

FcConfig* private_font_config() {
    static FcConfig* const config = [] {
        check_fontconfig_file();  // before fontconfig reads its configuration
        std::string xml =
            "<?xml version=\"1.0\"?><!DOCTYPE fontconfig SYSTEM \"urn:fontconfig:fonts.dtd\">"
            "<fontconfig><dir>/usr/share/fonts</dir><cachedir>/var/cache/fontconfig</cachedir>"
            "<cachedir prefix=\"xdg\">fontconfig</cachedir>";
        if (FcConfig* system = FcInitLoadConfig()) {
            if (FcStrList* dirs = FcConfigGetFontDirs(system)) {
                while (const FcChar8* dir = FcStrListNext(dirs)) {
                    const char* d = reinterpret_cast<const char*>(dir);
                    if (std::string_view(d) != "/usr/share/fonts") xml += "<dir>" + xml_escaped(d) + "</dir>";
                }
                FcStrListDone(dirs);
            }
            FcConfigDestroy(system);
        }
        xml += "</fontconfig>";
        FcConfig* c = FcConfigCreate();
        if (!c || !FcConfigParseAndLoadFromMemory(c, reinterpret_cast<const FcChar8*>(xml.c_str()), FcTrue) ||
            !FcConfigBuildFonts(c)) {
            throw std::runtime_error("cannot set up the font configuration");
        }
        // Fontconfig's current configuration too: Pango's start-up (FcInit) then finds one
        // and does not read the machine's configuration and fonts a second time.
        if (!FcConfigSetCurrent(c)) throw std::runtime_error("cannot set up the font configuration");
        return c;
    }();
    return config;
}

/// A glyph's outline: its points in order, and how many contours it has.
struct outline {
    std::vector<float> points;
    int contours = 0;
    bool operator==(const outline&) const = default;
};

hb_draw_funcs_t* outline_funcs() {
    static hb_draw_funcs_t* const funcs = [] {
        hb_draw_funcs_t* f = hb_draw_funcs_create();
        hb_draw_funcs_set_move_to_func(f, [](hb_draw_funcs_t*, void* d, hb_draw_state_t*, float x, float y, void*) {
            static_cast<outline*>(d)->points.push_back(NAN);  // a contour starts
            static_cast<outline*>(d)->points.push_back(x);
            static_cast<outline*>(d)->points.push_back(y);
        }, nullptr, nullptr);
        hb_draw_funcs_set_line_to_func(f, [](hb_draw_funcs_t*, void* d, hb_draw_state_t*, float x, float y, void*) {
            static_cast<outline*>(d)->points.push_back(x);
            static_cast<outline*>(d)->points.push_back(y);
        }, nullptr, nullptr);
        hb_draw_funcs_set_quadratic_to_func(f, [](hb_draw_funcs_t*, void* d, hb_draw_state_t*, float cx, float cy, float x, float y, void*) {
            auto* o = static_cast<outline*>(d);
            o->points.insert(o->points.end(), {cx, cy, x, y});
        }, nullptr, nullptr);
        hb_draw_funcs_set_cubic_to_func(f, [](hb_draw_funcs_t*, void* d, hb_draw_state_t*, float c1x, float c1y, float c2x, float c2y, float x, float y, void*) {
            auto* o = static_cast<outline*>(d);
            o->points.insert(o->points.end(), {c1x, c1y, c2x, c2y, x, y});
        }, nullptr, nullptr);
        hb_draw_funcs_set_close_path_func(f, [](hb_draw_funcs_t*, void* d, hb_draw_state_t*, void*) {
            ++static_cast<outline*>(d)->contours;
        }, nullptr, nullptr);
        hb_draw_funcs_make_immutable(f);
        return f;
    }();
    return funcs;
}

/// The outline the font draws for a code point; empty if it has no glyph for it.
outline outline_of(hb_font_t* font, hb_codepoint_t cp) {
    outline o;
    hb_codepoint_t glyph = 0;
    if (!hb_font_get_nominal_glyph(font, cp, &glyph)) return o;
    hb_font_get_glyph_shape(font, glyph, outline_funcs(), &o);
    // NaN marks compare unequal: keep them out of the comparison.
    for (float& v : o.points) {
        if (std::isnan(v)) v = -1e30f;
    }
    return o;
}

}  // namespace

std::vector<letter_form> distinct_letter_forms(PangoContext* context, const std::string& font_family) {
    const std::string first = font_family.substr(0, font_family.find(','));
    font_description_ptr font(pango_font_description_new());
    pango_font_description_set_family(font.get(), first.c_str());
    pango_font_description_set_style(font.get(), PANGO_STYLE_ITALIC);
    pango_font_description_set_size(font.get(), 10 * PANGO_SCALE);
    gobject_ptr<PangoFont> loaded(pango_context_load_font(context, font.get()));
    if (!loaded.get()) return {};
    hb_font_t* hb = pango_font_get_hb_font(loaded.get());
    if (!hb) return {};
    const outline theta = outline_of(hb, 0x3b8);
    const outline vartheta = outline_of(hb, 0x3d1);
    if (theta.points.empty() || !(theta == vartheta)) return {};
    // One glyph for both: a closed θ has three contours (its outline and two counters), a
    // ϑ two. The letter whose shape is missing is drawn by its mathematical italic form.
    if (theta.contours >= 3) return {{"\u03d1", "<span style=\"normal\">\U0001d717</span>"}};
    return {{"\u03b8", "<span style=\"normal\">\U0001d703</span>"}};
}

std::vector<letter_form> text_font_primes(PangoContext* context, const std::string& font_family) {
    const std::string first = font_family.substr(0, font_family.find(','));
    font_description_ptr font(pango_font_description_new());
    pango_font_description_set_family(font.get(), first.c_str());
    pango_font_description_set_size(font.get(), 10 * PANGO_SCALE);
    gobject_ptr<PangoFont> loaded(pango_context_load_font(context, font.get()));
    hb_font_t* hb = loaded.get() ? pango_font_get_hb_font(loaded.get()) : nullptr;
    hb_codepoint_t glyph = 0;
    if (!hb || hb_font_get_nominal_glyph(hb, 0x2032, &glyph) || !hb_font_get_nominal_glyph(hb, 0x2b9, &glyph)) return {};
    return {{"\u2032", "\u02b9"}, {"\u2033", "\u02b9\u02b9"}, {"\u2034", "\u02b9\u02b9\u02b9"}};
}

namespace {

/// The length of the combining marks (U+0300..U+036F, U+20D0..U+20FF) at markup[pos].
std::size_t combining_marks(const std::string& markup, std::size_t pos) {
    std::size_t end = pos;
    for (;;) {
        const auto byte = [&](std::size_t k) { return end + k < markup.size() ? static_cast<unsigned char>(markup[end + k]) : 0; };
        if ((byte(0) == 0xcc && byte(1) >= 0x80) || (byte(0) == 0xcd && byte(1) <= 0xaf && byte(1) >= 0x80)) {
            end += 2;
        } else if (byte(0) == 0xe2 && byte(1) == 0x83 && byte(2) >= 0x90) {
            end += 3;
        } else {
            return end - pos;
        }
    }
}

}  // namespace

std::string with_letter_forms(std::string markup, const std::vector<letter_form>& forms) {
    for (const letter_form& f : forms) {
        // The form is a span; the letter's accents go inside it, onto the form's glyph.
        const std::size_t close = f.markup.rfind("</");
        for (std::size_t pos = 0; (pos = markup.find(f.letter, pos)) != std::string::npos;) {
            const std::size_t marks = combining_marks(markup, pos + f.letter.size());
            std::string form = f.markup;
            if (close != std::string::npos) form.insert(close, markup, pos + f.letter.size(), marks);
            markup.replace(pos, f.letter.size() + marks, form);
            pos += form.size();
        }
    }
    return markup;
}

PangoFontMap* thread_font_map() {
    thread_local const gobject_ptr<PangoFontMap> map = [] {
        FcConfig* const config = private_font_config();  // before Pango's own start-up
        gobject_ptr<PangoFontMap> m(pango_cairo_font_map_new_for_font_type(CAIRO_FONT_TYPE_FT));
        if (!m.get()) throw std::runtime_error("cannot create a Pango font map");
        pango_fc_font_map_set_config(PANGO_FC_FONT_MAP(m.get()), config);
        return m;
    }();
    return map.get();
}

text_shaper& text_shaper::for_thread(const std::string& family) {
    // Made after the font map, so destroyed before it at the thread's end.
    thread_font_map();
    thread_local std::map<std::string, std::unique_ptr<text_shaper>> shapers;
    auto it = shapers.find(family);
    if (it == shapers.end()) it = shapers.emplace(family, std::make_unique<text_shaper>(family)).first;
    return *it->second;
}

bool first_family_resolves(PangoContext* context, const std::string& font_family) {
    const std::string first = font_family.substr(0, font_family.find(','));
    if (first.empty()) return false;
    font_description_ptr font(pango_font_description_new());
    pango_font_description_set_family(font.get(), first.c_str());
    gobject_ptr<PangoFont> loaded(pango_context_load_font(context, font.get()));
    std::string got;
    if (loaded.get()) {
        font_description_ptr d(pango_font_describe(loaded.get()));
        if (const char* f = pango_font_description_get_family(d.get())) got = f;
    }
    return got == first;
}

bool font_family_installed(const std::string& font_family) {
    const gobject_ptr<PangoContext> context(pango_font_map_create_context(thread_font_map()));
    return first_family_resolves(context.get(), font_family);
}

std::string markup_text(const std::string& markup) {
    char* text = nullptr;
    const std::string in_line = inline_fractions(markup);
    if (!pango_parse_markup(in_line.c_str(), -1, 0, nullptr, &text, nullptr, nullptr) || !text) return in_line;
    std::string out(text);
    g_free(text);
    return out;
}

}  // namespace plot
