// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/format_help.hpp"

#include <string_view>
#include <vector>

namespace pendulum::cli {

bool is_overlay(const plot::format_row& f) { return !f.graphics.empty(); }

std::string format_list() {
    std::string out;
    for (const auto& f : plot::format_names()) out += (out.empty() ? "" : ", ") + f;
    return out;
}

std::string raster_formats() {
    return plot::format_names([](const plot::format_row& f) { return f.raster; }, " and ");
}

std::string overlay_formats() { return plot::format_names(is_overlay); }

std::string animation_help() {
    std::vector<std::string_view> ways;
    for (const auto& f : plot::format_table()) {
        if (f.animate) ways.push_back(f.animation);
    }
    std::string out;
    for (std::size_t i = 0; i < ways.size(); ++i) {
        out += std::string(i == 0 ? "" : i + 1 == ways.size() ? ", or " : ", ") + std::string(ways[i]);
    }
    return out + "; " + plot::format_names([](const plot::format_row& f) { return f.animate == nullptr; }, " and ") +
           ", and every format with --at, get one frame";
}

std::string format_help() {
    std::string out;
    for (const auto& f : plot::format_table()) {
        out += (out.empty() ? "" : ", ") + std::string(f.name) + " (" + std::string(f.description) + ")";
    }
    return out;
}

}  // namespace pendulum::cli
