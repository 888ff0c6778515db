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

table_writer::table_writer(std::ostream& out, std::vector<std::string> columns, table_format format)
    : out_(out), columns_(std::move(columns)), format_(format) {
    if (format_ == table_format::csv) {
        for (std::size_t i = 0; i < columns_.size(); ++i) out_ << (i ? "," : "") << columns_[i];
        out_ << '\n';
    } else {
        out_ << "[";
    }
}

void table_writer::row(const std::vector<double>& values) {
    if (format_ == table_format::csv) {
        // A value that does not exist (the iteration's breakdown) is an empty field.
        for (std::size_t i = 0; i < values.size(); ++i) {
            out_ << (i ? "," : "") << (std::isfinite(values[i]) ? format_double(values[i]) : "");
        }
        out_ << '\n';
    } else {
        out_ << (rows_ ? ",\n " : "\n ") << "{";
        for (std::size_t i = 0; i < columns_.size() && i < values.size(); ++i) {
            const double v = values[i];
            out_ << (i ? ", " : "") << '"' << columns_[i] << "\": " << (std::isfinite(v) ? format_double(v) : "null");
        }
        out_ << "}";
    }
    ++rows_;
}

void table_writer::finish() {
    if (format_ == table_format::json) out_ << (rows_ ? "\n]\n" : "]\n");
}

void write_table(std::ostream& out, const table& t, table_format format) {
    table_writer w(out, t.columns, format);
    for (const auto& row : t.rows) w.row(row);
    w.finish();
}

}  // namespace pendulum::cli
