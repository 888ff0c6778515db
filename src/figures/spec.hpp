// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "figures/data_series.hpp"
#include "figures/errors.hpp"
#include "figures/plots.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/motion.hpp"
#include "plot/figure.hpp"
#include "plot/theme.hpp"

#include <array>
#include <filesystem>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace figures {

/// A place in a spec file, for messages.
struct source_position {
    std::string file;  ///< the spec's file name (or the built-in spec's id)
    int line = 0;      ///< 1-based line, 0 when unknown
    int column = 0;    ///< 1-based column, 0 when unknown
};

/// One problem in a spec.
struct spec_problem {
    source_position where;  ///< where it is
    std::string what;       ///< what is wrong, and what is allowed

    /// "FILE:LINE:COLUMN: what".
    std::string text() const;
};

/// Thrown for a spec with problems; what() lists every problem, one per line.
class spec_error : public bad_input {
public:
    /// Collects the problems; there is at least one.
    explicit spec_error(std::vector<spec_problem> problems);
    /// The problems, in the order of the file.
    const std::vector<spec_problem>& problems() const { return problems_; }

private:
    std::vector<spec_problem> problems_;
};

/// An amplitude as written in the spec and its value in radians.
struct amplitude {
    std::string text;  ///< as written: "170deg", "95pi/100"
    double value = 0;  ///< radians
    std::optional<pendulum::amplitude> exact = std::nullopt;  ///< with its distance from pi; unset for a range's ends

    /// The amplitude with its distance from pi as written ("pi - 1e-300").
    pendulum::amplitude theta0() const { return exact ? *exact : pendulum::amplitude(value); }
};

/// A start of the motion written in a spec: an energy, or a state (theta0 with omega0).
struct motion_start {
    std::string label;        ///< for the legend, Pango markup: "E = 2.5", "ϑ0 = 0, ω0 = 2.2"
    pendulum::motion motion;  ///< its exact motion
    bool energy = false;      ///< given as an energy: a phase panel draws its whole level set
};

/// A method of a panel, with the theme's style overridden where given.
struct method_spec {
    pendulum::method_choice method;            ///< the method
    std::string label;                         ///< legend label; empty for the default
    std::optional<plot::line_style> style;     ///< line style
    std::optional<plot::rgb> color;            ///< colour
    std::optional<plot::marker_style> marker;  ///< marker
};

/// A horizontal or vertical reference line with its legend label.
struct reference_line {
    std::optional<double> x;                       ///< vertical line at x
    std::optional<double> y;                       ///< horizontal line at y
    std::string label;                             ///< legend label; empty for none
    plot::line_style style = plot::line_style::dashed;  ///< line style
    std::optional<std::array<double, 2>> span;     ///< its extent along the other axis; default: the whole panel
};

/// The time axis of trajectory and phase panels.
enum class time_unit { period, small_period, seconds };

/// What a period panel's y axis shows: the period, a method's error, or the residuals of
/// measured data and methods from a reference, (T - T_ref)/T0.
enum class period_axis { value, error_percent, error_log, residual };

/// Which panels carry a legend.
enum class legend_mode { first, each, none };

/// One panel of a spec.
struct panel_spec {
    const plot_row* plot = nullptr;              ///< what it plots (a row of plot_table())
    source_position where;                       ///< the [[panel]] header
    std::vector<amplitude> theta0;               ///< amplitudes, where the plot takes them
    std::vector<motion_start> starts;            ///< or energies, or states (theta0 with omega0)
    std::vector<method_spec> methods;            ///< methods, where the plot takes them
    time_unit time = time_unit::period;          ///< trajectory and phase time unit
    std::optional<std::array<double, 2>> range;  ///< x range: times, or amplitudes in radians
    std::optional<std::array<double, 2>> y_range;  ///< y range, in the y axis' unit
    std::optional<std::array<double, 2>> paper_y_range;  ///< the paper's y range: its files (--paper-files) keep it
    std::optional<std::string> title;            ///< title; default "(a) ϑ0 = ..."
    std::optional<std::string> x_label;          ///< x axis label; default from the plot kind
    std::optional<std::string> y_label;          ///< y axis label; default from the plot kind
    std::string paper_file;                      ///< file name for --paper-files; empty for none
    period_axis y = period_axis::value;          ///< period panels: value, error in %, log |error|
    bool energy_axis = false;                    ///< period panels: x = "energy", T/T0 against E across the separatrix
    int harmonic = 1;                            ///< coefficient panels: 2k + 1
    int harmonics = 15;                          ///< spectrum panels: how many odd harmonics
    double trail = 0;                            ///< pendulum panels: fading trace, in exact periods
    bool energy_bars = false;                    ///< pendulum panels: kinetic, potential and total energy bars
    bool velocity_arrows = false;                ///< pendulum panels: the bob's velocity as an arrow
    bool acceleration_arrows = false;            ///< pendulum panels: the bob's acceleration as an arrow
    bool timer = false;                          ///< pendulum panels: a period timer
    std::array<int, 2> orders{0, 40};            ///< convergence panels: first and last N
    bool separatrix = false;                     ///< phase panels: draw the separatrix
    bool degrees = false;                        ///< angle axes in degrees
    std::vector<reference_line> lines;           ///< reference lines
    std::vector<data_series> data;               ///< measured data ([[panel.data]])
    std::optional<pendulum::method_choice> residual_of;  ///< y = "residual": the reference; default exact
};

/// The physical pendulum, when a spec gives one.
struct pendulum_spec {
    double length_m = 1.0;  ///< length in metres
    double g = 9.80665;     ///< gravity in m/s^2
};

/// The largest number of frames of an animation.
inline constexpr int max_frames = 10000;

/// How an animation's end meets its start when it loops.
enum class loop_mode {
    periods,    ///< whole periods of every drawn motion: the end runs on into the start
    crossfade,  ///< the motion runs on while its start fades in over it
    hold,       ///< the last frame is held, then the animation starts again
};

/// One choice of [animation] loop: its name, what it does, for help, man and messages.
struct loop_row {
    std::string_view name;         ///< as written in a spec
    loop_mode mode;                ///< what it means
    std::string_view description;  ///< one line
};

/// Every choice of [animation] loop, the default first.
inline constexpr std::array<loop_row, 3> loop_rows = {{
    {"periods", loop_mode::periods,
     "a whole number of periods of every drawn motion, so that the last frame runs on into the first"},
    {"crossfade", loop_mode::crossfade, "the motion runs on for half a second while the first frame fades in over it"},
    {"hold", loop_mode::hold, "the last frame stays for a second, then the animation starts again"},
}};

/// How an animation plays: every panel is drawn once per frame at time t.
struct animation_spec {
    double fps = 25;                 ///< frames per second, 1 to 120
    std::optional<double> periods;   ///< length in exact periods of the first amplitude; neither: a common loop
    std::optional<double> duration_s;  ///< or length in seconds (with [pendulum])
    double speed = 1.0;              ///< playback speed relative to real time
    bool clock = false;              ///< show "t = 1.25 T" (or seconds) in the first panel's title
    std::optional<loop_mode> loop;   ///< how the end meets the start; default: periods where they fit, else crossfade
};

/// A figure described as data.
struct figure_spec {
    std::string id;                             ///< file name without .toml, or the built-in id
    std::optional<int> columns;                 ///< panels per row
    std::optional<double> panel_width_cm;       ///< default: the theme's
    std::optional<double> panel_aspect;         ///< height / width; default: the theme's
    legend_mode legend = legend_mode::first;    ///< which panels carry a legend
    std::string title;                          ///< TeX label drawn above the panels, and the documents' title
    std::string description;                    ///< one line of plain text for lists and alt text
    std::string style;                          ///< its style file, relative to the working directory; empty for none
    std::optional<pendulum_spec> pendulum;      ///< physical units
    std::optional<animation_spec> animation;    ///< present: the figure is an animation
    std::vector<panel_spec> panels;             ///< at least one
};

/// Reads a spec from TOML text; `file` names it in messages and gives the id (its stem),
/// and its directory is the tree its style file must be in (symbolic links resolved).
/// Throws spec_error listing every problem found.
figure_spec parse_spec(std::string_view text, const std::string& file);

/// Reads a spec file; throws spec_error for a bad spec, std::runtime_error if unreadable.
figure_spec load_spec(const std::filesystem::path& path);

/// The most panels of a figure, (a) to (z).
inline constexpr int max_panels = 26;
/// The most amplitudes a panel takes (theta0, or --theta0 on the command line).
inline constexpr std::size_t max_amplitudes_per_panel = 32;
/// The most methods a panel takes.
inline constexpr std::size_t max_methods_per_panel = 12;
/// On an amplitude axis (period, coefficient), the most that the N of its order:N methods add up to.
inline constexpr int max_iteration_orders_per_panel = 400;
/// The most periods a trajectory panel's time range holds.
inline constexpr int max_periods_per_panel = 100;

/// The longest file name a spec may give (paper_file), in bytes.
inline constexpr std::size_t max_file_name_bytes = 100;

/// Why `name` is not a file name a spec may give (empty if it is): letters, digits and
/// . _ + - only, no directory, not starting with . or -, no "..", at most max_file_name_bytes.
std::string file_name_problem(std::string_view name);

/// Why `file` (a spec's input) is not inside the directory `tree` once both are resolved
/// through symbolic links (empty if it is inside).
std::string outside_problem(const std::filesystem::path& tree, const std::filesystem::path& file);

/// The closest of `names` to `word` when it is a likely misspelling, else empty.
std::string suggest(std::string_view word, const std::vector<std::string>& names);

}  // namespace figures
