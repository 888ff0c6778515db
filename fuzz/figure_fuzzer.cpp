// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: any bytes as a figure spec, and a spec read without error built as the
// program builds it for render, describe and data (the figure's panels and series, its
// description and its CSV), without rasterising. A spec is bad input (a spec_error listing
// problems) or builds; building may still refuse it as bad input (std::invalid_argument:
// exit 2). Anything else (a crash, a stack overflow, another exception) is a finding.
#include "figures/batch.hpp"
#include "figures/describe.hpp"
#include "figures/spec.hpp"
#include "figures/spec_build.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    figures::figure_spec spec;
    try {
        spec = figures::parse_spec(text, "fuzz.toml");
    } catch (const figures::spec_error& e) {
        if (e.problems().empty()) std::abort();
        return 0;
    }
    if (spec.panels.empty()) std::abort();  // a spec read without error has panels
    try {
        const plot::figure figure = figures::build_figure(spec);
        const auto words = figures::describe(spec, figure);
        const std::string csv = figures::figure_csv(figure);
        if (words.alt.empty() || csv.empty()) std::abort();
    } catch (const std::invalid_argument&) {
        // Bad input found while building (figures::bad_input, plot::bad_input): exit 2.
    }
    return 0;
}
