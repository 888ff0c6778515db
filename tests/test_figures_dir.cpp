// SPDX-License-Identifier: GPL-3.0-or-later
// figures/ holds what `make figures` writes: its recipe's commands, run into another
// directory, write the same PNGs and GIFs with the same bytes (a change to the drawing that
// leaves figures/ stale fails here).
#include "process.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace test_support;

namespace {

const fs::path source = fs::path(PENDULUM_TEST_DATA) / ".." / "..";

/// The commands of the Makefile's `figures` recipe that run the program, with the program
/// and the output directory replaced (`$(BUILD)/pendulum-figures`, `-o figures`).
std::vector<std::string> figures_recipe(const fs::path& out) {
    std::ifstream makefile(source / "Makefile");
    std::vector<std::string> commands;
    bool inside = false;
    for (std::string line; std::getline(makefile, line);) {
        if (line.rfind("figures:", 0) == 0) {
            inside = true;
            continue;
        }
        if (!inside) continue;
        if (line.empty() || line[0] != '\t') break;
        const std::string program = "\t$(BUILD)/pendulum-figures ";
        if (line.rfind(program, 0) != 0) continue;
        std::string args = line.substr(program.size());
        const auto at = args.find("-o figures");
        if (at == std::string::npos) continue;
        args.replace(at, std::string("-o figures").size(), "-o '" + out.string() + "'");
        commands.push_back(args);
    }
    return commands;
}

}  // namespace

TEST(FiguresDir, MakeFiguresWritesWhatIsCommitted) {
    const fs::path out = temp_dir("figures-dir");
    const auto commands = figures_recipe(out);
    ASSERT_EQ(commands.size(), 3u) << "the figures recipe's three render commands";
    for (const auto& args : commands) {
        const run_result r = run_cli(args, source);
        ASSERT_EQ(r.status, 0) << args << "\n" << r.err;
    }
    // figures/ keeps the PNGs and GIFs; its PDFs are left out of the repository (.gitignore).
    const auto kept = [](const fs::path& dir) {
        std::set<std::string> names;
        for (const auto& name : files_in(dir)) {
            if (fs::path(name).extension() != ".pdf") names.insert(name);
        }
        return names;
    };
    const auto made = kept(out);
    EXPECT_EQ(made, kept(source / "figures"));
    for (const auto& name : made) {
        EXPECT_TRUE(slurp(out / name) == slurp(source / "figures" / name))
            << name << " differs from figures/" << name << ": run make figures, look at it, and commit it";
    }
    fs::remove_all(out);
}
