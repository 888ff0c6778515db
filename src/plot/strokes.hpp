// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Part of the plot layer's renderer; not a public interface.

#include "plot/geometry.hpp"
#include "plot/theme.hpp"

#include <cairo.h>

#include <vector>

namespace plot {

/// Sets the theme's foreground colour (frame, ticks, text).
void set_foreground(cairo_t* cr, const theme& th);

/// Sets a series' colour: its own, or the palette's at its index.
void set_color(cairo_t* cr, const theme& th, const series& s);

/// A stroke's width at final size: `width`, or the theme's min_line_pt where that is wider.
double line_width(const theme& th, double width);

/// Sets width, dash pattern and caps of a line style.
void set_line_style(cairo_t* cr, const theme& th, line_style style, double width_scale = 1.0);

/// Strokes the series' line clipped to `clip`: a sampled curve as it is, a polyline through
/// points with each visible run simplified.
void stroke_polyline(cairo_t* cr, const device_series& d, const rect& clip);

/// Draws the series' markers at the points within `area` (grown by the marker radius).
void draw_markers(cairo_t* cr, const theme& th, const series& s, const device_series& d, const rect& area);

/// True for the markers drawn filled.
bool filled(marker_style m);

/// Half the width of an error bar's cap: the marker's radius, so that the cap is as wide as
/// the marker.
double cap_half_width(const theme& th, const series& s);

/// Strokes the error bars with their caps in the current colour, at the theme's line width.
void draw_error_bars(cairo_t* cr, const theme& th, const series& s, const std::vector<device_bar>& bars);

/// How far from its centre a series' marker's ink reaches: its outline's farthest point (a
/// triangle's tip, a square's corner) and half the outline's stroke.
double marker_reach(const theme& th, const series& s);

/// A disc that tick marks stop short of: a drawn marker's centre and its reach.
struct keep_out {
    double x = 0;  ///< centre, device points
    double y = 0;  ///< centre, device points
    double r = 0;  ///< radius of the ink
};

/// The length of a tick mark from (x, y) in the unit direction (ux, uy), at most `length`:
/// up to where it would come within `gap` of the first disc on its way (0 where it starts
/// there), so that a tick mark is never drawn under a marker.
double tick_length_clear(double x, double y, double ux, double uy, double length, const std::vector<keep_out>& discs,
                         double gap);

/// A straight piece of a drawn line's ink: the segment from (x0, y0) to (x1, y1) and the
/// ink's half width `r` on each side of it (round caps included).
struct ink_segment {
    double x0 = 0;  ///< one end, device points
    double y0 = 0;  ///< one end, device points
    double x1 = 0;  ///< other end, device points
    double y1 = 0;  ///< other end, device points
    double r = 0;   ///< half the ink's width
};

/// The ink tick marks keep clear of: the drawn markers, and the pieces of the drawn lines
/// (curves, lines through crowded markers, error bars) near the frame.
struct tick_clearance {
    std::vector<keep_out> discs;        ///< markers
    std::vector<ink_segment> segments;  ///< lines' pieces near the frame
};

/// Adds to `out` the pieces of the polyline (x, y), half width r, whose ink comes within
/// `band` of the frame of `area` on either side (a NaN vertex breaks the line).
void add_ink_near_frame(std::vector<ink_segment>& out, const std::vector<double>& x, const std::vector<double>& y,
                        double r, const rect& area, double band);

/// tick_length_clear over markers and lines: the length up to where the tick mark would
/// come within `gap` of a disc's or a segment's ink (0 where it starts there).
double tick_length_clear(double x, double y, double ux, double uy, double length, const tick_clearance& ink,
                         double gap);

/// The least length a shortened tick mark is drawn at, as a fraction of its own length: a
/// shorter one would be a stub, and is not drawn.
inline constexpr double min_tick_fraction = 0.5;

/// The tick rules, one place for every axis, figure, theme and size: a tick mark from (x, y)
/// on a side of `area` in the direction (ux, uy) into it is drawn at the returned length,
/// which is 0 (not drawn) where its line lies within `corner` of the perpendicular side of
/// the frame (it would close a box in the corner), or where keeping `gap` clear of `ink`
/// (tick_length_clear) leaves less than min_tick_fraction of `length`.
double tick_mark_length(double x, double y, double ux, double uy, double length, const tick_clearance& ink,
                        double gap, const rect& area, double corner);

/// A tick mark as stroked, from the frame inwards, and its stroke's width.
struct tick_mark {
    double x0 = 0;     ///< on the frame
    double y0 = 0;     ///< on the frame
    double x1 = 0;     ///< inner end
    double y1 = 0;     ///< inner end
    double width = 0;  ///< stroke width
    double full = 0;   ///< its length before tick_mark_length shortened it
};

/// While one lives, the tick marks stroked on its thread are added to it (what a test
/// measures against the markers); records nest, the innermost records.
class tick_marks_record {
public:
    tick_marks_record();
    ~tick_marks_record();
    tick_marks_record(const tick_marks_record&) = delete;
    tick_marks_record& operator=(const tick_marks_record&) = delete;

    /// Adds a tick mark to the innermost record of this thread, if any.
    static void add(const tick_mark& t);

    /// The tick marks recorded so far.
    const std::vector<tick_mark>& marks() const { return marks_; }

private:
    tick_marks_record* outer_;
    std::vector<tick_mark> marks_;
};

}  // namespace plot
