// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reads the CSV reference tables written by tests/data/make_reference.py.

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace test_support {

/// The lines of a reference CSV file split at commas, comment lines skipped; the header
/// (the first line that is no comment) is the first row.
inline std::vector<std::vector<std::string>> read_reference_text(const std::string& name) {
    const std::string path = std::string(PENDULUM_TEST_DATA) + "/" + name;
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::vector<std::vector<std::string>> rows;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> row;
        std::stringstream fields(line);
        for (std::string field; std::getline(fields, field, ',');) row.push_back(field);
        rows.push_back(row);
    }
    if (rows.size() < 2) throw std::runtime_error("no rows in " + path);
    return rows;
}

/// Rows of a reference CSV file (comment lines and the header skipped), parsed as doubles.
inline std::vector<std::vector<double>> read_reference(const std::string& name) {
    const auto text = read_reference_text(name);
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 1; i < text.size(); ++i) {
        std::vector<double> row;
        for (const auto& field : text[i]) row.push_back(std::stod(field));
        rows.push_back(row);
    }
    return rows;
}

}  // namespace test_support
