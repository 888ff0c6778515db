// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/table.hpp"

#include "pendulum/amplitude.hpp"

#include <cmath>
#include <stdexcept>

namespace pendulum::cli {

table_format parse_table_format(std::string_view text) {
    if (text == "csv") return table_format::csv;
    if (text == "json") return table_format::json;
    throw std::invalid_argument("unknown format '" + std::string(text) + "'; use csv or json");
}

void write_table(std::ostream& out, const table& t, table_format format) {
    if (format == table_format::csv) {
        for (std::size_t i = 0; i < t.columns.size(); ++i) out << (i ? "," : "") << t.columns[i];
        out << '\n';
        for (const auto& row : t.rows) {
            for (std::size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << format_double(row[i]);
            out << '\n';
        }
        return;
    }
    out << "[";
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        out << (r ? ",\n " : "\n ") << "{";
        for (std::size_t i = 0; i < t.columns.size(); ++i) {
            const double v = t.rows[r][i];
            out << (i ? ", " : "") << '"' << t.columns[i] << "\": "
                << (std::isfinite(v) ? format_double(v) : "null");
        }
        out << "}";
    }
    out << (t.rows.empty() ? "]\n" : "\n]\n");
}

}  // namespace pendulum::cli
