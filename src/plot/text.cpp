// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/text.hpp"

#include <fontconfig/fontconfig.h>
#include <pango/pangofc-fontmap.h>

#include <stdexcept>

namespace plot {

namespace {

/// The fonts figures may use: the system's font directories with their caches, and none
/// of the machine's or the user's font configuration (substitutions, hinting, subpixel
/// order), which would otherwise change the pictures from one machine to the next.
FcConfig* private_font_config() {
    static FcConfig* const config = [] {
        FcConfig* c = FcConfigCreate();
        static const char* const xml =
            "<?xml version=\"1.0\"?><!DOCTYPE fontconfig SYSTEM \"urn:fontconfig:fonts.dtd\">"
            "<fontconfig><dir>/usr/share/fonts</dir><cachedir>/var/cache/fontconfig</cachedir>"
            "<cachedir prefix=\"xdg\">fontconfig</cachedir></fontconfig>";
        if (!c || !FcConfigParseAndLoadFromMemory(c, reinterpret_cast<const FcChar8*>(xml), FcTrue) ||
            !FcConfigBuildFonts(c)) {
            throw std::runtime_error("cannot set up the font configuration");
        }
        return c;
    }();
    return config;
}


}  // namespace

PangoFontMap* thread_font_map() {
    thread_local const gobject_ptr<PangoFontMap> map = [] {
        gobject_ptr<PangoFontMap> m(pango_cairo_font_map_new_for_font_type(CAIRO_FONT_TYPE_FT));
        if (!m.get()) throw std::runtime_error("cannot create a Pango font map");
        pango_fc_font_map_set_config(PANGO_FC_FONT_MAP(m.get()), private_font_config());
        return m;
    }();
    return map.get();
}

}  // namespace plot
