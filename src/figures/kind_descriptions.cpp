// SPDX-License-Identifier: GPL-3.0-or-later
// The plot kinds' own parts of a figure's description (their rows' describe_drawing and
// describe_curves).
#include "figures/describe_support.hpp"
#include "figures/panel_support.hpp"
#include "figures/plot_builders.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace figures {

namespace {

/// Each pendulum of the drawing as it is drawn (pendulum_glyphs): "exact (solid rod, filled
/// bob)", "E = 2 mgL (dashed rod, filled bob)".
std::vector<std::string> pendulum_styles(const panel_spec& spec, const plot::theme& th) {
    static const char* const lines[] = {"solid", "solid", "dashed", "dotted", "dash-dot", "dash-dot-dot"};
    std::vector<std::string> who;
    for (const pendulum_glyph& g : pendulum_glyphs(spec, th)) {
        who.push_back(spoken_label(g.label) + " (" + lines[static_cast<int>(g.rod)] + " rod, " +
                      (g.bob == plot::marker_style::filled_circle ? "filled" : "open") + " bob)");
    }
    return who;
}

/// The orbits of a phase plot sorted by shape: closed around the origin, touching the axis
/// (the separatrix), open (rotations).
struct orbit_shapes {
    std::vector<std::string> closed;    ///< librations
    std::vector<std::string> touching;  ///< meeting y = 0 at its ends
    std::vector<std::string> open;      ///< never reaching y = 0
};

/// Sorts one orbit into its shape, with how far it reaches.
void add_orbit(orbit_shapes& shapes, const described_curves& d, const plot::series& s) {
    const plot::panel& p = d.panel;
    auto points = dense(s);
    if (points.empty()) return;
    std::sort(points.begin(), points.end());
    double y0 = INFINITY, y1 = -INFINITY, peak_x = 0;
    for (const auto& [px, py] : points) {
        y0 = std::min(y0, py);
        if (py > y1) peak_x = px;
        y1 = std::max(y1, py);
    }
    const double x0 = points.front().first, x1 = points.back().first;
    const std::string name = spoken_label(s.label.markup);
    const double near = 1e-3 * std::max(std::fabs(y0), std::fabs(y1));
    const std::string& x = d.x;
    const std::string& y = d.y;
    if (y0 < -near && y1 > near) {
        shapes.closed.push_back(name + ": " + x + " " + extent(x0, x1, p.x.ticks) + ", " + y + " " +
                                extent(y0, y1, p.y.ticks));
    } else if (std::min(std::fabs(y0), std::fabs(y1)) <= near) {
        const bool above = y1 > near;
        shapes.touching.push_back(name + " meets " + y + " = 0 at " + x + " = " + spoken(x0, p.x.ticks) + " and " +
                                  spoken(x1, p.x.ticks) + " and reaches " + spoken(above ? y1 : y0, p.y.ticks) +
                                  " at " + x + " = " + spoken(above ? peak_x : x0, p.x.ticks) +
                                  (name == "separatrix" ? ", with its mirror image below: the boundary between "
                                                          "swinging and going over the top"
                                                        : ""));
    } else {
        shapes.open.push_back(name + ": " + y + " " + extent(y0, y1, p.y.ticks) + ", " + (y0 > 0 ? "above" : "below") +
                              " the axis");
    }
}

}  // namespace

std::string describe_pendulum_drawing(const panel_spec& spec, bool animated, const plot::theme& th) {
    const std::vector<std::string> who = pendulum_styles(spec, th);
    const std::size_t n = who.size();
    std::string out = " is a drawing, seen from the side, of " +
                      (n == 1 ? std::string("a pendulum") : std::to_string(n) + " pendulums of one length") +
                      " hanging from one pivot: " + join(who) + ".";
    if (!spec.theta0.empty()) {
        std::vector<std::string> amplitudes;
        for (const auto& a : spec.theta0) amplitudes.push_back(spoken_amplitude(a));
        out += std::string(n == 1 ? " It is" : " They are") + " released from rest at theta0 = " + join(amplitudes) +
               " from the vertical; dotted lines mark that angle on either side, and a faint circle the path of "
               "the bobs.";
    }
    if (spec.trail > 0) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", spec.trail);
        out += " Each bob leaves a fading trail of its last " + std::string(buf) + " periods.";
    }
    // The teaching overlays (pendulum_overlays.cpp), in words.
    if (spec.energy_bars) {
        out += " Bars on the right show each pendulum's kinetic, potential and total energy in units of m g L; "
               "the first two trade places as it swings and always add up to the total.";
    }
    if (spec.velocity_arrows || spec.acceleration_arrows) {
        out += std::string(" Arrows on each bob show its ") +
               (spec.velocity_arrows && spec.acceleration_arrows ? "velocity and acceleration"
                : spec.velocity_arrows                             ? "velocity"
                                                                   : "acceleration") +
               ".";
    }
    if (spec.timer) out += " A period timer at the top left shows the measured period once a swing is complete.";
    out += start_motions(spec);
    if (animated && spec.methods.size() > 1) {
        out += " They swing side by side, the approximations drifting from the exact pendulum.";
    }
    return out;
}

std::string describe_phase_orbits(const described_curves& d) {
    orbit_shapes shapes;
    for (const auto* s : d.shown) add_orbit(shapes, d, *s);
    const std::string& x = d.x;
    const std::string& y = d.y;
    std::string out;
    if (!shapes.closed.empty()) {
        const bool one = shapes.closed.size() == 1;
        out += std::string(one ? " A closed curve" : " Closed curves") + " around the origin (" + y +
               " is largest at " + x + " = 0 and zero at the turning points)" + (one ? ": " : ", nested by size: ") +
               join(shapes.closed) + ".";
    }
    if (!shapes.touching.empty()) {
        std::string who = join(shapes.touching);
        who[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(who[0])));
        out += " " + who + ".";
    }
    if (!shapes.open.empty()) {
        out += std::string(shapes.open.size() == 1 ? " A curve" : " Curves") + " across the whole width, never reaching " +
               y + " = 0 (rotations): " + join(shapes.open) + ".";
    }
    return out;
}

}  // namespace figures
