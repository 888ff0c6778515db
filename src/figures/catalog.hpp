#pragma once

#include "plot/figure.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace figures {

/// One figure of the catalog.
struct entry {
    std::string id;                        ///< stable name, used for file names
    std::string alias;                     ///< fig1 ... fig7, or empty
    std::string paper_figure;              ///< "Fig. 1" ... or "new"
    std::string description;               ///< one line
    std::vector<std::string> paper_files;  ///< per-panel file names in the paper's LaTeX source
    double paper_width_cm = 6.0;           ///< panel width in the paper
    bool takes_amplitudes = false;         ///< trajectory figure: --theta0 replaces its amplitudes
};

/// Every figure, in the paper's order, then the new ones.
const std::vector<entry>& catalog();

/// The entry for an id or alias; throws std::invalid_argument listing the valid ids otherwise.
const entry& find(std::string_view id);

/// Choices that change what a figure shows.
struct build_options {
    std::vector<double> amplitudes;  ///< trajectory amplitudes; empty for the paper's
};

/// The figure's data from the core library, arranged with the plot layer.
plot::figure build(const entry& e, const build_options& options = {});

/// A label for an amplitude: "9π/10" for a simple multiple of pi, "170°" for whole degrees,
/// otherwise radians with four significant digits.
std::string amplitude_label(double theta0);

}  // namespace figures
