// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "plot/figure.hpp"
#include "plot/theme.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace figures {

struct figure_spec;
struct panel_spec;
struct key_reading;

/// What a panel is built with besides its own spec.
struct panel_context {
    const figure_spec& spec;  ///< the figure the panel belongs to
    double width_cm;          ///< the panel's width
    bool animated;            ///< leave out what moves: each frame adds it (plot_row::add_frame)
    double frame_step;        ///< w0 t from the previous frame of an animation to this one; 0 when still
    double history = 0;       ///< w0 t before 0 that is the motion's past (a seamless loop's round before)
};

/// How a plot kind takes amplitudes, and what the command line's --theta0 does to it.
enum class amplitude_policy {
    none,           ///< none: its x axis is the amplitude
    one,            ///< one; --theta0 gives it the first
    list,           ///< a list; --theta0 replaces it
    one_per_panel,  ///< one; --theta0 makes one such panel per amplitude
};

/// What a plot kind's `range` key holds.
enum class range_kind {
    none,        ///< it takes no range
    times,       ///< two times in the panel's time unit
    amplitudes,  ///< two angles
};

/// The formulas of the user (methods formula = "EXPR") a plot kind takes.
enum class formula_kind {
    none,           ///< none
    law_of_motion,  ///< laws of motion theta(t) in t and theta0
    period,         ///< periods T/T0 in theta0
};

/// The axis names and curves a panel's description speaks of.
struct described_curves {
    const plot::panel& panel;                    ///< the built panel
    const std::vector<const plot::series*>& shown;  ///< its curves with a legend label
    const std::string& x;                        ///< the x axis' name as spoken
    const std::string& y;                        ///< the y axis' name as spoken
};

/// One plot kind: what it shows, the keys it takes, and how it is built and animated. A new
/// kind is a row here and its builder.
struct plot_row {
    std::string_view name;         ///< the spec's `plot` value
    std::string_view x;            ///< what the x axis shows
    std::string_view y;            ///< what the y axis shows
    std::string_view keys;         ///< the panel keys it takes besides the common ones, space-separated
    std::string_view description;  ///< one line for help and lists
    amplitude_policy amplitudes;   ///< the amplitudes it takes
    range_kind range;              ///< what its range is
    bool needs_motion;             ///< its methods must give a law of motion, not only a period
    bool drawing;                  ///< a drawing rather than a plot: an animation's clock goes on it
    formula_kind formulas;         ///< the user formulas its methods may be
    /// Reads the kind's own keys (those in `keys`) into the panel, reporting their problems.
    void (*read_keys)(key_reading& k);
    /// The panel, its data computed by the core library (without what moves, when animated).
    plot::panel (*build)(const panel_context& c, const panel_spec& p);
    /// Adds what moves at time w0 t to a built panel; null for a panel that stands still.
    void (*add_frame)(plot::panel& panel, const panel_context& c, const panel_spec& p, double w0_t);
    /// A drawing's description after "Panel (a)" (for alt text), in place of the general one;
    /// null for the general one.
    std::string (*describe_drawing)(const panel_spec& p, bool animated, const plot::theme& th);
    /// Sentences of its own added to the description of a plot's curves; null for none.
    std::string (*describe_curves)(const described_curves& d);
};

/// Every plot kind, in the order help and lists show them.
std::span<const plot_row> plot_table();

/// The plot kind of that name, or null.
const plot_row* find_plot(std::string_view name);

/// The plot kinds' names, "trajectory, phase, ..., spectrum", or with `taking_amplitudes`
/// only those that take amplitudes (what --theta0 applies to); `last_word` ("or", "and")
/// joins the last two.
std::string plot_names(bool taking_amplitudes = false, std::string_view last_word = "");

}  // namespace figures
