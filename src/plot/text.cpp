// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/text.hpp"

#include "plot/theme.hpp"

#include <fontconfig/fontconfig.h>
#include <pango/pangofc-fontmap.h>

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
FcConfig* private_font_config() {
    static FcConfig* const config = [] {
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

}  // namespace

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
    if (!pango_parse_markup(markup.c_str(), -1, 0, nullptr, &text, nullptr, nullptr) || !text) return markup;
    std::string out(text);
    g_free(text);
    return out;
}

}  // namespace plot
