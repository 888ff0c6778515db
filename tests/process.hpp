// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs the pendulum-figures executable and captures its exit code, stdout and stderr.

#include <cstdlib>
#include <filesystem>
#include <set>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace test_support {

/// The result of running a command.
struct run_result {
    int status = -1;      ///< exit code
    std::string out;      ///< standard output
    std::string err;      ///< standard error
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Runs a shell command line, capturing both streams.
inline run_result run_command(const std::string& command) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("pendulum-run-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto out = dir / "out";
    const auto err = dir / "err";
    const std::string cmd = "{ " + command + " ; } >'" + out.string() + "' 2>'" + err.string() + "' </dev/null";
    const int raw = std::system(cmd.c_str());
    run_result r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    std::filesystem::remove_all(dir);
    return r;
}

/// Runs PENDULUM_EXE with `args` (shell syntax) in `cwd`, capturing both streams.
inline run_result run_cli(const std::string& args, const std::filesystem::path& cwd = ".") {
    return run_command("cd '" + cwd.string() + "' && '" + std::string(PENDULUM_EXE) + "' " + args);
}

/// A new empty directory for one test, removed first if a previous run left it.
inline std::filesystem::path temp_dir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("pendulum-figures-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

/// The names of the files in dir.
inline std::set<std::string> files_in(const std::filesystem::path& dir) {
    std::set<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir)) names.insert(e.path().filename().string());
    return names;
}

}  // namespace test_support
