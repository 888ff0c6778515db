// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "plot/tex_markup.hpp"
#include "figures/build_options.hpp"
#include "figures/spec.hpp"
#include "plot/figure.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace figures {

/// A figure the tool can draw: a built-in spec or a spec file.
struct entry {
    std::string id;            ///< stable name, used for file names
    std::string alias;         ///< fig1 ... fig7, or empty
    std::string paper_figure;  ///< "Fig. 1" ... or "new"; empty for a spec file
    std::string source;        ///< the spec's TOML text
    figure_spec spec;          ///< the spec, read

    /// One line: the spec's [figure] description, or its title as plain text.
    std::string description() const { return spec.description.empty() ? plot::tex_to_plain(spec.title) : spec.description; }
    /// True if --theta0 can replace amplitudes of this figure.
    bool takes_amplitudes() const;
};

/// Every built-in figure, in the paper's order, then the new ones.
const std::vector<entry>& catalog();

/// The built-in entry for an id or alias; throws std::invalid_argument listing the valid ids otherwise.
const entry& find(std::string_view id);

/// A built-in figure by id or alias, or a spec file (a name ending in .toml) read from disk;
/// throws spec_error for a bad spec and std::runtime_error for an unreadable file.
entry load(std::string_view id_or_file);

/// The panels the figure will have with these options, as specs (for paper file names).
std::vector<panel_spec> panels_of(const entry& e, const build_options& options = {});

/// The figure's data from the core library, arranged with the plot layer.
plot::figure build(const entry& e, const build_options& options = {});

}  // namespace figures
