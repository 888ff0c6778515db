// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading [[panel.data]] tables of a spec (see data_series.hpp).

#include "figures/data_series.hpp"
#include "figures/spec.hpp"
#include "figures/toml_reader.hpp"

#include <string_view>

namespace figures {

/// Reads the panel's [[panel.data]] tables into p.data (a file is read relative to the
/// spec's directory and must stay inside it, symbolic links resolved) and checks their
/// units against the panel's axes; every problem goes to `r`, with FILE:LINE:COLUMN in the
/// data file for a problem there.
void read_panel_data(reader& r, const toml::table& panel, const figure_spec& f, panel_spec& p);

}  // namespace figures
