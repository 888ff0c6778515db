// SPDX-License-Identifier: GPL-3.0-or-later
// Each plot kind's keys, read with the shared key readers (panel_keys.hpp): the keys its
// row lists, no others.
#include "figures/panel_keys.hpp"
#include "figures/plot_builders.hpp"

namespace figures {

void trajectory_keys(key_reading& k) {
    read_amplitudes(k);
    read_methods(k);
    read_time(k);
    read_range(k);
    read_angle_unit(k);
    read_data(k);
}

void phase_keys(key_reading& k) {
    read_amplitudes(k);
    read_methods(k);
    read_separatrix(k);
    read_angle_unit(k);
    read_data(k);
}

void period_keys(key_reading& k) {
    read_period_axes(k);
    read_methods(k);
    read_range(k);
    read_residual_of(k);
    read_angle_unit(k);
    read_data(k);
}

void coefficient_keys(key_reading& k) {
    read_methods(k);
    read_range(k);
    read_harmonic(k);
    read_angle_unit(k);
    read_data(k);
}

void convergence_keys(key_reading& k) {
    read_theta0(k);
    read_orders(k);
}

void spectrum_keys(key_reading& k) {
    read_theta0(k);
    read_methods(k);
    read_harmonics(k);
}

void pendulum_keys(key_reading& k) {
    read_amplitudes(k);
    read_methods(k);
    read_trail(k);
    read_overlays(k);
}

}  // namespace figures
