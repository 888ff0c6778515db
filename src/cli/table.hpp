// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace pendulum::cli {

/// A table of numbers with named columns, printed as CSV or JSON.
struct table {
    std::vector<std::string> columns;       ///< column names
    std::vector<std::vector<double>> rows;  ///< one value per column in each row
};

/// Output formats for tables.
enum class table_format { csv, json };

/// Parses "csv" or "json"; throws std::invalid_argument naming the text otherwise.
table_format parse_table_format(std::string_view text);

/// Writes the table: CSV with a header line, or JSON as an array of objects. Numbers use
/// the shortest form that reads back to the same double; NaN is written as nan / null.
void write_table(std::ostream& out, const table& t, table_format format);

}  // namespace pendulum::cli
