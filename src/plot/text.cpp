// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/text.hpp"

#include "plot/theme.hpp"

#include "plot/errors.hpp"
#include "plot/math_layout.hpp"
#include "plot/tex_markup.hpp"

#include <fontconfig/fontconfig.h>
#include <glib.h>
#include <sys/stat.h>
#include <hb.h>
#include <pango/pangofc-fontmap.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <vector>
#include <algorithm>
#include <cstdlib>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>

namespace plot {

namespace {

/// Writes `text` as XML character data (glib's escaping).
std::string xml_escaped(const char* text) {
    const std::unique_ptr<gchar, decltype(&g_free)> escaped(g_markup_escape_text(text, -1), &g_free);
    return escaped.get();
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

/// The machine's fontconfig file (Debian's fontconfig is built with FONTCONFIG_PATH /etc/fonts).
constexpr const char* system_fonts_conf = "/etc/fonts/fonts.conf";

/// One <dir> or <include> element of a fontconfig file: its prefix attribute, its
/// attributes written out again, and its text.
struct config_element {
    std::string prefix;
    std::string attributes;  ///< ` name="value"` for each attribute, escaped again
    std::string text;
};

/// What glib's XML parser gathers from one fontconfig file: its <dir> and <include>
/// elements; `simple` is false where the file does what the scan does not follow
/// (<reset-dirs/>, an element inside <dir> or <include>).
struct config_elements {
    std::vector<config_element> dirs, includes;
    std::optional<config_element> open;  ///< the <dir> or <include> being read
    bool open_is_dir = false;
    bool simple = true;
};

void config_start(GMarkupParseContext*, const gchar* name, const gchar** names, const gchar** values, gpointer data,
                  GError**) {
    auto& c = *static_cast<config_elements*>(data);
    const std::string_view element(name);
    if (element == "reset-dirs" || c.open) c.simple = false;
    if (element != "dir" && element != "include") return;
    config_element e;
    for (std::size_t i = 0; names[i]; ++i) {
        if (std::string_view(names[i]) == "prefix") e.prefix = values[i];
        e.attributes += " " + std::string(names[i]) + "=\"" + xml_escaped(values[i]) + "\"";
    }
    c.open = std::move(e);
    c.open_is_dir = element == "dir";
}

void config_end(GMarkupParseContext*, const gchar* name, gpointer data, GError**) {
    auto& c = *static_cast<config_elements*>(data);
    const std::string_view element(name);
    if (!c.open || (element != "dir" && element != "include")) return;
    (c.open_is_dir ? c.dirs : c.includes).push_back(std::move(*c.open));
    c.open.reset();
}

void config_text(GMarkupParseContext*, const gchar* text, gsize size, gpointer data, GError**) {
    auto& c = *static_cast<config_elements*>(data);
    if (c.open) c.open->text.append(text, size);
}

/// The <dir> and <include> elements of one fontconfig file, read by glib's XML parser;
/// nothing (simple = false) where it is not well-formed XML.
config_elements read_config_elements(const std::string& xml) {
    config_elements c;
    static const GMarkupParser parser{config_start, config_end, config_text, nullptr, nullptr};
    const std::unique_ptr<GMarkupParseContext, decltype(&g_markup_parse_context_free)> ctx(
        g_markup_parse_context_new(&parser, G_MARKUP_DEFAULT_FLAGS, &c, nullptr), &g_markup_parse_context_free);
    GError* error = nullptr;
    const bool parsed = g_markup_parse_context_parse(ctx.get(), xml.data(), static_cast<gssize>(xml.size()), &error) &&
                        g_markup_parse_context_end_parse(ctx.get(), &error);
    if (error) g_error_free(error);
    if (!parsed || c.open) c.simple = false;
    return c;
}

/// $XDG_CONFIG_HOME, else ~/.config, as fontconfig takes it for prefix="xdg".
std::string xdg_config_home() {
    if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x == '/') return x;
    const char* home = std::getenv("HOME");
    return std::string(home ? home : "") + "/.config";
}

/// Where an <include> leads, as fontconfig resolves it (a relative name in its configuration
/// directory, /etc/fonts); empty where the scan does not follow (another prefix).
std::string include_path(const config_element& e) {
    if (e.prefix == "xdg") return xdg_config_home() + "/" + e.text;
    if (!e.prefix.empty()) return {};
    if (e.text.starts_with("~")) {
        const char* home = std::getenv("HOME");
        return home ? std::string(home) + e.text.substr(1) : std::string();
    }
    if (e.text.starts_with("/")) return e.text;
    const std::string conf(system_fonts_conf);
    return conf.substr(0, conf.rfind('/') + 1) + e.text;
}

/// What the scan of fontconfig's files gathers: the <dir> elements, in order; false
/// where fontconfig's own reading is needed instead.
struct config_scan {
    std::vector<std::string> dirs;  ///< each <dir ...>text</dir>, as written
    bool simple = true;
    int files = 0;
};

void scan_config_path(const std::string& path, config_scan& scan, int depth);

/// Scans one configuration file: its <dir> elements, and the files it includes.
void scan_config_file(const std::string& path, config_scan& scan, int depth) {
    std::ifstream in(path, std::ios::binary);
    std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.is_open() || in.bad()) scan.simple = false;
    const config_elements found = read_config_elements(xml);
    if (!found.simple) scan.simple = false;
    for (const auto& d : found.dirs) {
        // Paths fontconfig reads relative to the file or the working directory are its own to resolve.
        if (!(d.prefix == "xdg" || (d.prefix.empty() && (d.text.starts_with("/") || d.text.starts_with("~"))))) {
            scan.simple = false;
        }
        scan.dirs.push_back("<dir" + d.attributes + ">" + xml_escaped(d.text.c_str()) + "</dir>");
    }
    for (const auto& i : found.includes) {
        const std::string to = include_path(i);
        if (to.empty()) scan.simple = false;
        else scan_config_path(to, scan, depth + 1);
    }
}

/// Scans a configuration file, or a directory's *.conf files in name order, as fontconfig
/// reads them; one missing is skipped, as fontconfig's includes here ask.
void scan_config_path(const std::string& path, config_scan& scan, int depth) {
    struct stat st {};
    if (!scan.simple || ::stat(path.c_str(), &st) != 0) return;
    if (depth > 8 || ++scan.files > 256 || !(S_ISREG(st.st_mode) || S_ISDIR(st.st_mode)) ||
        (S_ISREG(st.st_mode) && st.st_size > max_fontconfig_file_bytes)) {
        scan.simple = false;
        return;
    }
    if (S_ISREG(st.st_mode)) return scan_config_file(path, scan, depth);
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(path, ec)) {
        const std::string name = entry.path().filename().string();
        // As fontconfig reads a directory: the files whose names start with a digit and end in .conf.
        if (name.size() > 5 && std::isdigit(static_cast<unsigned char>(name[0])) && name.ends_with(".conf")) {
            names.push_back(name);
        }
    }
    if (ec) scan.simple = false;
    std::sort(names.begin(), names.end());
    for (const auto& name : names) scan_config_path(path + "/" + name, scan, depth + 1);
}

/// The font directories of the machine's and the user's fontconfig files, without the
/// cost of parsing their rules (a sixth of a small figure's instructions): the <dir>
/// elements of /etc/fonts/fonts.conf and the files it includes. Nothing where the
/// environment names another configuration, or the files do what the scan does not
/// follow; then fontconfig reads them itself.
std::optional<std::vector<std::string>> scanned_font_dirs() {
    for (const char* v : {"FONTCONFIG_FILE", "FONTCONFIG_PATH", "FONTCONFIG_SYSROOT"}) {
        if (const char* set = std::getenv(v); set && *set) return std::nullopt;
    }
    config_scan scan;
    scan_config_path(system_fonts_conf, scan, 0);
    if (!scan.simple || scan.files == 0) return std::nullopt;
    return scan.dirs;
}

/// The font directories fontconfig's own configuration lists, as <dir> elements.
std::vector<std::string> loaded_font_dirs() {
    std::vector<std::string> out;
    if (FcConfig* system = FcInitLoadConfig()) {
        if (FcStrList* dirs = FcConfigGetFontDirs(system)) {
            while (const FcChar8* dir = FcStrListNext(dirs)) {
                out.push_back("<dir>" + xml_escaped(reinterpret_cast<const char*>(dir)) + "</dir>");
            }
            FcStrListDone(dirs);
        }
        FcConfigDestroy(system);
    }
    return out;
}

/// Where fontconfig keeps its caches, for every configuration made here.
constexpr const char* cache_dirs =
    "<cachedir>/var/cache/fontconfig</cachedir><cachedir prefix=\"xdg\">fontconfig</cachedir>";

FcConfig* private_font_config() {
    static FcConfig* const config = [] {
        check_fontconfig_file();  // before fontconfig reads its configuration
        std::string xml =
            "<?xml version=\"1.0\"?><!DOCTYPE fontconfig SYSTEM \"urn:fontconfig:fonts.dtd\">"
            "<fontconfig><dir>/usr/share/fonts</dir>" +
            std::string(cache_dirs);
        const std::string first = "<dir>/usr/share/fonts</dir>";
        auto dirs = scanned_font_dirs();
        if (!dirs) dirs = loaded_font_dirs();
        for (const std::string& d : *dirs) {
            if (d != first) xml += d;
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

}  // namespace

std::vector<std::string> private_font_directories() {
    std::vector<std::string> out;
    if (FcStrList* dirs = FcConfigGetFontDirs(private_font_config())) {
        while (const FcChar8* dir = FcStrListNext(dirs)) out.emplace_back(reinterpret_cast<const char*>(dir));
        FcStrListDone(dirs);
    }
    return out;
}

namespace {

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

namespace {

/// The families of a comma-separated font family, split as Pango splits it (blanks kept:
/// fontconfig ignores them when it compares names).
std::vector<std::string> family_names(const std::string& font_family) {
    std::vector<std::string> out;
    for (std::size_t from = 0;;) {
        const std::size_t comma = font_family.find(',', from);
        out.push_back(font_family.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
        if (comma == std::string::npos) return out;
        from = comma + 1;
    }
}

/// A family name as fontconfig compares names made of printable ASCII: blanks left out,
/// in lower case; nothing for a name with other characters (whose case folding and
/// blanks are fontconfig's own).
std::optional<std::string> compared_name(const char* name) {
    std::string out;
    for (const char* p = name; *p; ++p) {
        const auto c = static_cast<unsigned char>(*p);
        if (c == ' ') continue;
        if (c < 0x21 || c > 0x7e) return std::nullopt;
        out += static_cast<char>(std::tolower(c));
    }
    return out;
}

/// Whether a font is of one of the families `names` (compared names): surely, surely not,
/// or perhaps (a family name this comparison does not decide).
enum class named { no, yes, perhaps };

named of_named_family(FcPattern* font, const std::vector<std::string>& names) {
    named found = named::no;
    FcChar8* family = nullptr;
    for (int i = 0; FcPatternGetString(font, FC_FAMILY, i, &family) == FcResultMatch; ++i) {
        const auto name = compared_name(reinterpret_cast<const char*>(family));
        if (!name) found = named::perhaps;
        else if (std::find(names.begin(), names.end(), *name) != names.end()) return named::yes;
    }
    return found;
}

/// True if Pango draws with the font: a file, in an OpenType format (Pango leaves out the
/// others, Type 1 among them).
bool pango_draws_with(FcPattern* font) {
    FcChar8* file = nullptr;
    FcChar8* format = nullptr;
    if (FcPatternGetString(font, FC_FILE, 0, &file) != FcResultMatch ||
        FcPatternGetString(font, FC_FONTFORMAT, 0, &format) != FcResultMatch) {
        return false;
    }
    const std::string_view f(reinterpret_cast<const char*>(format));
    return f == "TrueType" || f == "CFF";
}

/// The faces of the families a font family names, in a configuration of their own, and the
/// characters they cover together.
struct named_fonts {
    FcConfig* config = nullptr;   ///< null: none installed (the private configuration serves)
    FcCharSet* covered = nullptr; ///< the union of their character sets
};

/// The faces of the private configuration whose family `names` has (and those it perhaps
/// has), in its order, and the characters the surely named ones cover.
std::vector<FcPattern*> faces_named(const std::vector<std::string>& names, FcCharSet* covered) {
    std::vector<FcPattern*> faces;
    for (const FcSetName which : {FcSetSystem, FcSetApplication}) {
        const FcFontSet* set = FcConfigGetFonts(private_font_config(), which);
        for (int i = 0; set && i < set->nfont; ++i) {
            FcPattern* font = set->fonts[i];
            const named n = of_named_family(font, names);
            if (n == named::no) continue;
            faces.push_back(font);
            FcCharSet* chars = nullptr;
            if (n == named::yes && pango_draws_with(font) &&
                FcPatternGetCharSet(font, FC_CHARSET, 0, &chars) == FcResultMatch) {
                FcCharSetMerge(covered, chars, nullptr);
            }
        }
    }
    return faces;
}

/// A configuration holding the faces of the families `font_family` names and no other:
/// their directories, read from the same caches, every other file refused. Fontconfig
/// ranks a family the pattern names above every family it does not name, so for a text
/// these faces cover Pango picks the very faces it picks among all fonts, after sorting a
/// handful of faces instead of every installed font for each new size and style.
named_fonts make_named_fonts(const std::string& font_family) {
    named_fonts made;
    std::vector<std::string> names;
    for (const std::string& f : family_names(font_family)) {
        const auto name = compared_name(f.c_str());
        if (!name) return made;  // compared by fontconfig alone: all fonts serve
        names.push_back(*name);
    }
    const std::unique_ptr<FcCharSet, decltype(&FcCharSetDestroy)> covered(FcCharSetCreate(), &FcCharSetDestroy);
    if (!covered) throw std::bad_alloc();
    const std::vector<FcPattern*> faces = faces_named(names, covered.get());
    if (faces.empty()) return made;
    std::vector<std::string> dirs;
    std::string accepted;
    for (FcPattern* font : faces) {
        FcChar8* file = nullptr;
        if (FcPatternGetString(font, FC_FILE, 0, &file) != FcResultMatch) continue;
        const std::string path(reinterpret_cast<const char*>(file));
        const std::string dir = path.substr(0, path.rfind('/'));
        if (std::find(dirs.begin(), dirs.end(), dir) == dirs.end()) dirs.push_back(dir);
        // A name with * or ? takes in more files of its directory, which is harmless.
        accepted += "<glob>" + xml_escaped(path.c_str()) + "</glob>";
    }
    std::string xml = "<?xml version=\"1.0\"?><!DOCTYPE fontconfig SYSTEM \"urn:fontconfig:fonts.dtd\"><fontconfig>" +
                      std::string(cache_dirs);
    for (const std::string& d : dirs) xml += "<dir>" + xml_escaped(d.c_str()) + "</dir>";
    xml += "<selectfont><rejectfont><glob>*</glob></rejectfont><acceptfont>" + accepted +
           "</acceptfont></selectfont></fontconfig>";
    std::unique_ptr<FcConfig, decltype(&FcConfigDestroy)> c(FcConfigCreate(), &FcConfigDestroy);
    if (!c || !FcConfigParseAndLoadFromMemory(c.get(), reinterpret_cast<const FcChar8*>(xml.c_str()), FcTrue) ||
        !FcConfigBuildFonts(c.get())) {
        throw std::runtime_error("cannot set up the font configuration of " + font_family);
    }
    made.config = c.release();
    made.covered = FcCharSetCopy(covered.get());
    return made;
}

/// The named faces of a font family, made once a process (as the private configuration,
/// they live as long as it does).
const named_fonts& named_fonts_of(const std::string& font_family) {
    static std::mutex mutex;
    // Never destroyed, as the configurations it holds are not: they stay reachable.
    static auto* const made = new std::map<std::string, named_fonts>;
    const std::lock_guard lock(mutex);
    auto it = made->find(font_family);
    if (it == made->end()) it = made->emplace(font_family, make_named_fonts(font_family)).first;
    return it->second;
}

/// True if an attribute sets a font family of its own.
gboolean names_a_family(PangoAttribute* a, gpointer) {
    if (a->klass->type == PANGO_ATTR_FAMILY) return TRUE;
    if (a->klass->type != PANGO_ATTR_FONT_DESC) return FALSE;
    const PangoFontDescription* d = reinterpret_cast<PangoAttrFontDesc*>(a)->desc;
    return (pango_font_description_get_set_fields(d) & PANGO_FONT_MASK_FAMILY) != 0;
}

}  // namespace

bool named_fonts_cover(const std::string& font_family, const char* text, PangoAttrList* attrs) {
    const named_fonts& named = named_fonts_of(font_family);
    if (!named.config || !text) return false;
    if (attrs) {
        PangoAttrList* found = pango_attr_list_filter(attrs, names_a_family, nullptr);
        if (found) {
            pango_attr_list_unref(found);
            return false;
        }
    }
    for (const char* p = text; *p; p = g_utf8_next_char(p)) {
        if (!FcCharSetHasChar(named.covered, g_utf8_get_char(p))) return false;
    }
    return true;
}

PangoFontMap* named_font_map(const std::string& font_family) {
    FcConfig* const config = named_fonts_of(font_family).config;
    if (!config) return thread_font_map();
    thread_local std::map<std::string, gobject_ptr<PangoFontMap>> maps;
    auto it = maps.find(font_family);
    if (it == maps.end()) {
        thread_font_map();  // made first, so destroyed after these at the thread's end
        gobject_ptr<PangoFontMap> m(pango_cairo_font_map_new_for_font_type(CAIRO_FONT_TYPE_FT));
        if (!m.get()) throw std::runtime_error("cannot create a Pango font map");
        pango_fc_font_map_set_config(PANGO_FC_FONT_MAP(m.get()), config);
        it = maps.emplace(font_family, std::move(m)).first;
    }
    return it->second.get();
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
    const gobject_ptr<PangoContext> context(pango_font_map_create_context(named_font_map(font_family)));
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
