// SPDX-License-Identifier: GPL-3.0-or-later
// A video module as a repository could plant it beside a copy of the program: its
// constructor runs as soon as it is loaded, and leaves a mark in $PLANTED_MARKER.
#include <cstdio>
#include <cstdlib>

namespace {

/// Writes the marker file when the module is loaded.
struct mark {
    mark() {
        if (const char* path = std::getenv("PLANTED_MARKER")) {
            if (std::FILE* f = std::fopen(path, "w")) {
                std::fputs("loaded\n", f);
                std::fclose(f);
            }
        }
    }
};

const mark marked;

}  // namespace
