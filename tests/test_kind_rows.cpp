// SPDX-License-Identifier: GPL-3.0-or-later
// A plot kind is a row of plot_table() and its functions: each row's keys are read by its
// own function, accepted by that kind and refused by every other with the kinds that take
// them; the spec reader and the descriptions name no kind.
#include "figures/plots.hpp"
#include "figures/spec.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace figures;

std::vector<std::string> split_words(std::string_view text) {
    std::vector<std::string> out;
    std::istringstream in{std::string(text)};
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

bool lists(const plot_row& row, const std::string& key) {
    for (const auto& k : split_words(row.keys)) {
        if (k == key) return true;
    }
    return false;
}

/// The problems of a one-panel spec of `kind` with `key` given a table (a type no key takes),
/// on line 3; "accepted" if it parses.
std::string problems_with(std::string_view kind, const std::string& key) {
    const std::string text = "[[panel]]\nplot = \"" + std::string(kind) + "\"\n" + key + " = { bogus = 1 }\n";
    try {
        parse_spec(text, "kinds.toml");
    } catch (const spec_error& e) {
        return e.what();
    }
    return "accepted";
}

/// "plot phase takes it", "plots trajectory, phase, pendulum take it".
std::string takers_of(const std::string& key) {
    std::vector<std::string> takers;
    for (const auto& row : plot_table()) {
        if (lists(row, key)) takers.emplace_back(row.name);
    }
    std::string names;
    for (const auto& t : takers) names += (names.empty() ? "" : ", ") + t;
    return (takers.size() == 1 ? "plot " : "plots ") + names + (takers.size() == 1 ? " takes it" : " take it");
}

TEST(KindRows, EveryRowHasItsFunctions) {
    for (const auto& row : plot_table()) {
        EXPECT_NE(row.read_keys, nullptr) << row.name;
        EXPECT_NE(row.build, nullptr) << row.name;
        EXPECT_FALSE(split_words(row.keys).empty()) << row.name;
        EXPECT_EQ(find_plot(row.name), &row);
    }
}

TEST(KindRows, EachKeyIsReadByTheKindsThatListIt) {
    for (const auto& row : plot_table()) {
        for (const auto& key : split_words(row.keys)) {
            const std::string got = problems_with(row.name, key);
            SCOPED_TRACE(std::string(row.name) + " " + key + ":\n" + got);
            // Not refused as a key ...
            EXPECT_EQ(got.find("key '" + key + "'"), std::string::npos);
            // ... but read: its value, a table, is refused where it stands.
            EXPECT_NE(got.find("kinds.toml:3:"), std::string::npos);
        }
    }
}

TEST(KindRows, EachKeyIsRefusedByTheOtherKindsNamingThoseThatTakeIt) {
    int refusals = 0;
    for (const auto& owner : plot_table()) {
        for (const auto& key : split_words(owner.keys)) {
            for (const auto& other : plot_table()) {
                if (lists(other, key)) continue;
                const std::string got = problems_with(other.name, key);
                const std::string expected = "kinds.toml:3:1: key '" + key + "' does not apply to plot '" +
                                             std::string(other.name) + "'; " + takers_of(key);
                EXPECT_NE(got.find(expected), std::string::npos) << "expected: " << expected << "\ngot:\n" << got;
                ++refusals;
            }
        }
    }
    EXPECT_GT(refusals, 50);
}

TEST(KindRows, AKeyNoKindTakesIsUnknownWithTheKindsKeys) {
    const std::string got = problems_with("phase", "bogus_key");
    EXPECT_NE(got.find("kinds.toml:3:1: unknown key 'bogus_key' in a phase panel; keys: plot, title"),
              std::string::npos)
        << got;
}

/// A source file of the project.
std::string source(const std::string& relative) {
    const auto root = std::filesystem::path(PENDULUM_TEST_DATA).parent_path().parent_path();
    std::ifstream in(root / relative, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(KindRows, TheSpecReaderAndTheDescriptionsNameNoKind) {
    for (const char* file : {"src/figures/spec.cpp", "src/figures/panel_keys.cpp", "src/figures/describe.cpp"}) {
        std::string text = source(file);
        ASSERT_FALSE(text.empty()) << file;
        // The spec's [pendulum] table (length_m, g) shares the pendulum kind's name.
        for (const std::string table : {"doc.get(\"pendulum\")", "'pendulum' must be a table"}) {
            for (auto at = text.find(table); at != std::string::npos; at = text.find(table)) text.erase(at, table.size());
        }
        for (const auto& row : plot_table()) {
            const std::string name(row.name);
            const std::vector<std::string> namings = {'"' + name + '"', "'" + name + "'", name + " panel", "name == \""};
            for (const std::string& named : namings) {
                EXPECT_EQ(text.find(named), std::string::npos) << file << " names a kind: " << named;
            }
        }
    }
}

}  // namespace
