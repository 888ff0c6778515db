// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/plots.hpp"

#include "figures/plot_builders.hpp"

#include <array>
#include <vector>

namespace figures {

namespace {

constexpr std::array<plot_row, 7> plots = {{
    {"trajectory", "time", "theta(t)", "theta0 energy omega0 methods time range angle_unit data",
     "the law of motion theta(t) at one amplitude, energy or state", amplitude_policy::one_per_panel, range_kind::times, true, false,
     trajectory_panel, add_trajectory_frame},
    {"phase", "theta", "theta'/w0", "theta0 energy omega0 methods separatrix angle_unit data",
     "orbits in the phase plane, one per amplitude, energy or state", amplitude_policy::list, range_kind::none, true, false,
     phase_panel, add_phase_frame},
    {"period", "theta0 or E", "T/T0", "methods range y x angle_unit data residual_of",
     "the period against the amplitude (value, error in %, or log |error|) or against the energy across the separatrix", amplitude_policy::none,
     range_kind::amplitudes, false, false, period_panel, nullptr},
    {"coefficient", "theta0", "c_{2k+1}", "harmonic methods range angle_unit data",
     "one Fourier coefficient against the amplitude", amplitude_policy::none, range_kind::amplitudes, true, false,
     coefficient_panel, nullptr},
    {"convergence", "N", "|T_N/T - 1|", "theta0 orders", "the period error of the iteration against its order N",
     amplitude_policy::list, range_kind::none, true, false, convergence_panel, nullptr},
    {"spectrum", "2k+1", "|c_{2k+1}|", "theta0 methods harmonics",
     "the Fourier coefficients' magnitudes, on a log axis", amplitude_policy::list, range_kind::none, true, false,
     spectrum_panel, nullptr},
    {"pendulum", "", "", "theta0 energy omega0 methods trail",
     "rod and bob of each start and method at the frame's time, swinging or over the top, for animations",
     amplitude_policy::list, range_kind::none, true, true, pendulum_panel, add_pendulum_frame},
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
