// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/catalog.hpp"

#include "figures/builtin.hpp"
#include "figures/input_file.hpp"
#include "figures/spec_build.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace figures {

bool entry::takes_amplitudes() const {
    return std::any_of(spec.panels.begin(), spec.panels.end(),
                       [](const panel_spec& p) { return p.plot->amplitudes != amplitude_policy::none; });
}

const std::vector<entry>& catalog() {
    static const std::vector<entry> entries = [] {
        std::vector<entry> v;
        for (const auto& b : builtin_specs()) {
            v.push_back({std::string(b.id), std::string(b.alias), std::string(b.paper_figure), std::string(b.text),
                         parse_spec(b.text, std::string(b.id) + ".toml")});
        }
        return v;
    }();
    return entries;
}

const entry& find(std::string_view id) {
    for (const auto& e : catalog()) {
        if (e.id == id || (!e.alias.empty() && e.alias == id)) return e;
    }
    std::string ids;
    for (const auto& e : catalog()) ids += (ids.empty() ? "" : ", ") + e.id;
    throw bad_input("unknown figure '" + std::string(id) + "'; figures: " + ids +
                                " (or fig1 ... fig7, or a spec file NAME.toml)");
}

entry load(std::string_view id_or_file) {
    if (!id_or_file.ends_with(".toml")) return find(id_or_file);
    const std::filesystem::path path(id_or_file);
    // The figure's files are named after the spec, and the name reaches Make (--depfile),
    // LaTeX (an overlay's \includegraphics) and XML: it is held to the rule of paper_file.
    if (const std::string why = file_name_problem(path.stem().string()); !why.empty()) {
        throw bad_input("spec file '" + path.string() + "': the name before .toml " + why +
                        " (the figure's files are named after it; rename the spec)");
    }
    entry e;
    e.source = read_input_file(path, "spec file");
    e.spec = parse_spec(e.source, path.string());
    e.id = e.spec.id;
    return e;
}

std::vector<panel_spec> panels_of(const entry& e, const build_options& options) {
    return panels_with(e.spec, options);
}

plot::figure build(const entry& e, const build_options& options) {
    return build_figure(e.spec, options);
}

}  // namespace figures
