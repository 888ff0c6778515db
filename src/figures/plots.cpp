// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/plots.hpp"

#include "figures/plot_builders.hpp"

#include <array>
#include <vector>

namespace figures {

namespace {

constexpr std::array<plot_row, 7> plots = {{
    {.name = "trajectory", .x = "time", .y = "theta(t)",
     .keys = "theta0 energy omega0 methods time range angle_unit data",
     .description = "the law of motion theta(t) at one amplitude, energy or state",
     .amplitudes = amplitude_policy::one_per_panel, .range = range_kind::times, .needs_motion = true,
     .drawing = false, .formulas = formula_kind::law_of_motion, .read_keys = trajectory_keys,
     .build = trajectory_panel, .add_frame = add_trajectory_frame, .describe_drawing = nullptr,
     .describe_curves = nullptr},
    {.name = "phase", .x = "theta", .y = "theta'/w0",
     .keys = "theta0 energy omega0 methods separatrix angle_unit data",
     .description = "orbits in the phase plane, one per amplitude, energy or state",
     .amplitudes = amplitude_policy::list, .range = range_kind::none, .needs_motion = true, .drawing = false,
     .formulas = formula_kind::none, .read_keys = phase_keys, .build = phase_panel, .add_frame = add_phase_frame,
     .describe_drawing = nullptr, .describe_curves = describe_phase_orbits},
    {.name = "period", .x = "theta0 or E", .y = "T/T0", .keys = "methods range y x angle_unit data residual_of",
     .description = "the period against the amplitude (value, error in %, or log |error|) or against the energy "
                    "across the separatrix",
     .amplitudes = amplitude_policy::none, .range = range_kind::amplitudes, .needs_motion = false,
     .drawing = false, .formulas = formula_kind::period, .read_keys = period_keys, .build = period_panel,
     .add_frame = nullptr, .describe_drawing = nullptr, .describe_curves = nullptr},
    {.name = "coefficient", .x = "theta0", .y = "c_{2k+1}", .keys = "harmonic methods range angle_unit data",
     .description = "one Fourier coefficient against the amplitude", .amplitudes = amplitude_policy::none,
     .range = range_kind::amplitudes, .needs_motion = true, .drawing = false, .formulas = formula_kind::none,
     .read_keys = coefficient_keys, .build = coefficient_panel, .add_frame = nullptr,
     .describe_drawing = nullptr, .describe_curves = nullptr},
    {.name = "convergence", .x = "N", .y = "|T_N/T - 1|", .keys = "theta0 orders",
     .description = "the period error of the iteration against its order N", .amplitudes = amplitude_policy::list,
     .range = range_kind::none, .needs_motion = true, .drawing = false, .formulas = formula_kind::none,
     .read_keys = convergence_keys, .build = convergence_panel, .add_frame = nullptr,
     .describe_drawing = nullptr, .describe_curves = nullptr},
    {.name = "spectrum", .x = "2k+1", .y = "|c_{2k+1}|", .keys = "theta0 methods harmonics",
     .description = "the Fourier coefficients' magnitudes, on a log axis", .amplitudes = amplitude_policy::list,
     .range = range_kind::none, .needs_motion = true, .drawing = false, .formulas = formula_kind::none,
     .read_keys = spectrum_keys, .build = spectrum_panel, .add_frame = nullptr, .describe_drawing = nullptr,
     .describe_curves = nullptr},
    {.name = "pendulum", .x = "", .y = "", .keys = "theta0 energy omega0 methods trail energy_bars arrows timer",
     .description = "rod and bob of each start and method at the frame's time, swinging or over the top, for "
                    "animations",
     .amplitudes = amplitude_policy::list, .range = range_kind::none, .needs_motion = true, .drawing = true,
     .formulas = formula_kind::none, .read_keys = pendulum_keys, .build = pendulum_panel,
     .add_frame = add_pendulum_frame, .describe_drawing = describe_pendulum_drawing, .describe_curves = nullptr},
}};

}  // namespace

std::span<const plot_row> plot_table() { return plots; }

const plot_row* find_plot(std::string_view name) {
    for (const auto& row : plots) {
        if (row.name == name) return &row;
    }
    return nullptr;
}

std::string plot_names(bool taking_amplitudes, std::string_view last_word) {
    std::vector<std::string_view> names;
    for (const auto& row : plots) {
        if (!taking_amplitudes || row.amplitudes != amplitude_policy::none) names.push_back(row.name);
    }
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0 && i + 1 == names.size() && !last_word.empty()) {
            out += ' ';
            out += last_word;
            out += ' ';
        } else if (i > 0) {
            out += ", ";
        }
        out += names[i];
    }
    return out;
}

}  // namespace figures
