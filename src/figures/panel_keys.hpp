// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The readers of a panel's keys: one per key (or pair of keys read together), shared by the
// plot kinds, whose rows (plots.cpp) each read their own keys with them (kind_keys.cpp).

#include "figures/spec.hpp"
#include "figures/toml_reader.hpp"

#include <toml++/toml.h>

#include <optional>

namespace figures {

/// A panel being read: its table, its figure, the panel so far and the reader collecting
/// the problems.
struct key_reading {
    reader& r;                                ///< collects the problems
    const toml::table& t;                     ///< the [[panel]] table
    const figure_spec& f;                     ///< the figure it belongs to (read before its panels)
    panel_spec& p;                            ///< the panel, its plot row already set
    std::optional<bool> x_axis{};             ///< x = "amplitude" (false) or "energy" (true), where read and valid
    std::optional<period_axis> y_axis{};      ///< y = ..., where read and valid
};

/// theta0, energy and omega0: one amplitude or a list, as the kind takes them, or starts
/// (energies, or states theta0 with omega0).
void read_amplitudes(key_reading& k);
/// theta0 = one amplitude or a list, as the kind takes them.
void read_theta0(key_reading& k);
/// methods = [...]: the panel's methods; the exact motion by default where the panel starts
/// from energies or states, or draws against the energy or the residuals.
void read_methods(key_reading& k);
/// time = "t/T" | "t/T0" | "t/s".
void read_time(key_reading& k);
/// range = [from, to]: times in the time unit, energies on an energy axis, else angles.
void read_range(key_reading& k);
/// x = "amplitude" | "energy" and y = "value" | ...: a period panel's axes; energy = ... is
/// refused there with what to write instead.
void read_period_axes(key_reading& k);
/// residual_of = "METHOD": the reference of a residual panel (after read_period_axes).
void read_residual_of(key_reading& k);
/// harmonic = 2k+1, odd, 1 to 99.
void read_harmonic(key_reading& k);
/// harmonics = N, 1 to 100.
void read_harmonics(key_reading& k);
/// orders = [first, last].
void read_orders(key_reading& k);
/// separatrix = true | false.
void read_separatrix(key_reading& k);
/// trail = periods, 0 to 10.
void read_trail(key_reading& k);
/// energy_bars = true | false, arrows = ["velocity", "acceleration"], timer = true | false:
/// the pendulum panel's teaching overlays.
void read_overlays(key_reading& k);
/// angle_unit = "rad" | "deg".
void read_angle_unit(key_reading& k);
/// [[panel.data]]: measured data.
void read_data(key_reading& k);

/// The checks of a whole panel once its keys are read: the work it asks for is bounded,
/// its starts fit its methods and time unit, an energy axis draws the exact period.
void check_panel(key_reading& k);

/// The plot kinds' names (", " and `last_word` between them) whose rows take user formulas
/// of that sort.
std::string kinds_taking(formula_kind formulas, std::string_view last_word = "or");

}  // namespace figures
