// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <variant>
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

/// Writes a table row by row as it is computed, so that long tables need no memory.
class table_writer {
public:
    /// Writes the header (CSV) or the opening bracket (JSON).
    table_writer(std::ostream& out, std::vector<std::string> columns, table_format format);
    /// Writes one row, one value per column.
    void row(const std::vector<double>& values);
    /// Ends the table (JSON's closing bracket).
    void finish();

private:
    std::ostream& out_;
    std::vector<std::string> columns_;
    table_format format_;
    std::size_t rows_ = 0;
};

/// Writes the table: CSV with a header line, or JSON as an array of objects. Numbers use
/// the shortest form that reads back to the same double; NaN is an empty field / null.
void write_table(std::ostream& out, const table& t, table_format format);

/// A field of a record: text or a number.
using field = std::variant<std::string, double>;

/// Writes records of text and numbers: CSV quoted as RFC 4180 asks, or JSON with escaped strings.
void write_records(std::ostream& out, const std::vector<std::string>& columns,
                   const std::vector<std::vector<field>>& rows, table_format format);

}  // namespace pendulum::cli
