// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Owning handles for the C objects of Cairo and Pango.

#include <cairo.h>
#include <pango/pangocairo.h>

#include <memory>
#include <string_view>
#include <string>
#include <stdexcept>
#include <new>

namespace plot {

/// Deleters for Cairo and Pango objects.
struct cairo_deleter {
    /// Releases a cairo_t.
    void operator()(cairo_t* p) const { cairo_destroy(p); }
    /// Releases a surface.
    void operator()(cairo_surface_t* p) const { cairo_surface_destroy(p); }
    /// Releases font options.
    void operator()(cairo_font_options_t* p) const { cairo_font_options_destroy(p); }
    /// Releases a GObject (PangoContext, PangoLayout, PangoFont).
    void operator()(GObject* p) const { g_object_unref(p); }
    /// Releases a font description.
    void operator()(PangoFontDescription* p) const { pango_font_description_free(p); }
};

/// An owned cairo_t.
using context_ptr = std::unique_ptr<cairo_t, cairo_deleter>;
/// An owned cairo surface.
using surface_ptr = std::unique_ptr<cairo_surface_t, cairo_deleter>;
/// Owned cairo font options.
using font_options_ptr = std::unique_ptr<cairo_font_options_t, cairo_deleter>;
/// An owned Pango font description.
using font_description_ptr = std::unique_ptr<PangoFontDescription, cairo_deleter>;

/// An owned GObject of type T (PangoContext, PangoLayout, PangoFont).
template <typename T>
struct gobject_ptr {
    std::unique_ptr<GObject, cairo_deleter> ptr;  ///< the owned object
    /// Takes ownership of p.
    explicit gobject_ptr(T* p = nullptr) : ptr(G_OBJECT(p)) {}
    /// The raw pointer.
    T* get() const { return reinterpret_cast<T*>(ptr.get()); }
};

/// Throws for a Cairo status other than success: std::bad_alloc when Cairo ran out of
/// memory (the program's one message for that), else std::runtime_error naming `what`.
inline void check_cairo(cairo_status_t status, std::string_view what) {
    if (status == CAIRO_STATUS_SUCCESS) return;
    if (status == CAIRO_STATUS_NO_MEMORY) throw std::bad_alloc();
    throw std::runtime_error("cannot " + std::string(what) + ": " + cairo_status_to_string(status));
}

}  // namespace plot
