// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: any bytes as a figure spec give a spec or a spec_error listing problems.
#include "figures/spec.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const auto spec = figures::parse_spec(text, "fuzz.toml");
        if (spec.panels.empty()) std::abort();  // a spec read without error has panels
    } catch (const figures::spec_error& e) {
        if (e.problems().empty()) std::abort();
    }
    return 0;
}
