// SPDX-License-Identifier: GPL-3.0-or-later
// One implementation per thing: one bad-input type above the core, one edit distance for
// every "did you mean", the encoder's look-ahead in one place, whether a format plays motion
// in its row. And tests that catch small changes (limits at their boundaries, messages,
// encoder contracts) where no other test did.
#include "cli/errors.hpp"
#include "common/errors.hpp"
#include "common/suggest.hpp"
#include "figures/errors.hpp"
#include "figures/spec.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/formula.hpp"
#include "figures/themes.hpp"
#include "plot/errors.hpp"
#include "plot/gif.hpp"
#include "plot/output.hpp"
#include "plot/tex_markup.hpp"
#include "plot/video.hpp"

#include "process.hpp"

#include <gif_lib.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

using test_support::files_in;
using test_support::run_command;
using test_support::slurp;
using test_support::run_cli;
using test_support::temp_dir;

namespace {

/// The message of what `f` throws as `E`, or "" if it throws nothing.
template <class E, class F>
std::string thrown(F f) {
    try {
        f();
    } catch (const E& e) {
        return e.what();
    }
    return "";
}

}  // namespace

// ---------------------------------------------------------------------------------------
// One bad-input type.

static_assert(std::is_same_v<plot::bad_input, common::bad_input>);
static_assert(std::is_same_v<figures::bad_input, common::bad_input>);
static_assert(std::is_same_v<pendulum::cli::usage_error, common::bad_input>);
static_assert(std::is_base_of_v<std::invalid_argument, common::bad_input>);
// The core's own stays apart (the core includes nothing above it), an invalid_argument too.
static_assert(!std::is_base_of_v<common::bad_input, pendulum::domain_error>);
static_assert(std::is_base_of_v<std::invalid_argument, pendulum::domain_error>);

TEST(Structure, BadInputOfEveryLayerIsExitTwoWithItsMessageAndNoFile) {
    struct reproduction {
        const char* args;     // after the command's own name
        const char* message;  // the start of the message after "pendulum-figures: error: "
    };
    // One of each layer's: the command line's, the plot layer's, the figures layer's, the core's.
    const std::array<reproduction, 4> cases = {{
        {"render fig1 -f svg --jobs 0", "--jobs 0: the number of workers, 1 to 1024"},
        {"plot period --methods exact --panel-title '$\\lamda$' -f png", "plot period"},
        {"render nosuchfigure -f png", "unknown figure"},
        {"eval --theta0 4", "--theta0"},
    }};
    for (const auto& c : cases) {
        const auto dir = temp_dir("structure-bad-input");
        const auto r = run_cli(c.args, dir);
        EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
        EXPECT_EQ(r.err.rfind(std::string("pendulum-figures: error: ") + c.message, 0), 0u) << c.args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << "\n" << r.err;
        EXPECT_TRUE(r.out.empty()) << c.args;
        EXPECT_TRUE(files_in(dir).empty()) << c.args;
        std::filesystem::remove_all(dir);
    }
}

// ---------------------------------------------------------------------------------------
// One edit distance.

TEST(Suggest, EditDistanceCountsEachEditOnce) {
    using common::edit_distance;
    EXPECT_EQ(edit_distance("", ""), 0u);
    EXPECT_EQ(edit_distance("", "abc"), 3u);
    EXPECT_EQ(edit_distance("abc", ""), 3u);
    EXPECT_EQ(edit_distance("theta0", "theta0"), 0u);
    EXPECT_EQ(edit_distance("theta", "theta0"), 1u);   // insertion
    EXPECT_EQ(edit_distance("thetta0", "theta0"), 1u);  // deletion
    EXPECT_EQ(edit_distance("thata0", "theta0"), 1u);   // substitution
    EXPECT_EQ(edit_distance("tehta0", "theta0"), 1u);   // two neighbours swapped: one edit
    EXPECT_EQ(edit_distance("ab", "ba"), 1u);
    EXPECT_EQ(edit_distance("abc", "ca"), 3u);  // optimal string alignment: no edit of a swapped pair
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
    EXPECT_EQ(edit_distance("sitting", "kitten"), 3u);
}

TEST(Suggest, WordsUpToTheLimitAreMeasuredLongerOnesAreFarFromEverything) {
    using common::edit_distance;
    using common::max_suggest_length;
    const std::string at(max_suggest_length, 'a');
    const std::string over(max_suggest_length + 1, 'a');
    EXPECT_EQ(edit_distance(at, at), 0u);
    EXPECT_EQ(edit_distance(at, at.substr(1)), 1u);
    EXPECT_EQ(edit_distance(over, over), max_suggest_length + 1);
    EXPECT_EQ(edit_distance(over, "a"), max_suggest_length + 1);
    EXPECT_EQ(edit_distance("a", over), max_suggest_length + 1);
    const std::vector<std::string> names = {at};
    EXPECT_EQ(common::nearest_name(at.substr(1), names, 2), at);
    EXPECT_EQ(common::nearest_name(over, std::vector<std::string>{over}, max_suggest_length + 1), "");
}

TEST(Suggest, NearestNameIsTheFirstOfTheNearestBelowTheBound) {
    const std::vector<std::string_view> names = {"first", "each", "none", "fist"};
    EXPECT_EQ(common::nearest_name("frist", names, 2), "first");  // a swap, before "fist" (also 1)
    EXPECT_EQ(common::nearest_name("fisrt", names, 2), "first");
    EXPECT_EQ(common::nearest_name("eahc", names, 2), "each");
    EXPECT_EQ(common::nearest_name("eahc", names, 1), "");  // the bound is strict
    EXPECT_EQ(common::nearest_name("", names, 5), "each");  // 4 edits, the first of the shortest names
    EXPECT_EQ(common::nearest_name("", names, 4), "");
    EXPECT_EQ(common::nearest_name("xyz", std::vector<std::string>{}, 10), "");
}

TEST(Suggest, EveryLayerSuggestsASwappedPair) {
    // The core's formula language, the plot layer's TeX macros, the figures layer's keys.
    EXPECT_EQ(thrown<pendulum::domain_error>([] { pendulum::formula f("sqtr(2)"); }).rfind(
                  "formula:1:1: unknown name 'sqtr'; did you mean 'sqrt'?", 0),
              0u);
    EXPECT_EQ(thrown<plot::bad_input>([] { plot::tex_to_markup("$\\lmabda$"); }),
              "label '$\\lmabda$': unknown macro \\lmabda (did you mean \\lambda?)");
    EXPECT_EQ(figures::suggest("mtehods", {"methods", "theta0"}), "methods");
    // A short macro with a swapped pair: two edits for Levenshtein (no suggestion below 5
    // letters), one here.
    EXPECT_EQ(thrown<plot::bad_input>([] { plot::tex_to_markup("$\\tua$"); }),
              "label '$\\tua$': unknown macro \\tua (did you mean \\tau?)");
}

// ---------------------------------------------------------------------------------------
// The encoder's look-ahead in one place; whether a format plays motion in its row.

TEST(Structure, TheLookAheadIsWrittenOnceInTheVideoKind) {
    for (const plot::video_kind* kind : {&plot::mp4_video, &plot::webm_video}) {
        // Not in the options string: options_with adds it, with the settings' value.
        EXPECT_EQ(std::string_view(kind->codec_options).find(kind->lookahead_option), std::string_view::npos)
            << kind->codec_options;
        // A small frame keeps the kind's look-ahead and threads.
        const plot::video_settings small = plot::video_settings_for(*kind, 320, 240);
        EXPECT_EQ(small.lookahead, kind->lookahead) << kind->container;
        EXPECT_EQ(small.threads, kind->threads) << kind->container;
    }
    EXPECT_STREQ(plot::mp4_video.lookahead_option, "rc-lookahead");
    EXPECT_EQ(plot::mp4_video.lookahead, 0);
    EXPECT_STREQ(plot::webm_video.lookahead_option, "lag-in-frames");
    EXPECT_EQ(plot::webm_video.lookahead, 25);
}

TEST(Structure, AFormatPlaysMotionWhenItsFramesGoIntoOneRasterFile) {
    std::vector<std::string> playing;
    for (const auto& f : plot::format_table()) {
        const bool one_file = f.frame_file && f.frame_file("x", 0, 2) == f.frame_file("x", 1, 2);
        EXPECT_EQ(f.plays_motion, f.raster && f.animate && one_file) << f.name;
        if (f.plays_motion) playing.emplace_back(f.name);
    }
    EXPECT_EQ(playing, (std::vector<std::string>{"gif", "mp4", "webm"}));
}

// ---------------------------------------------------------------------------------------
// One lexer for the angle's and the formula's numbers (pendulum/expression_lexer.hpp).

TEST(Structure, AnAngleAndAFormulaReadTheSameNumbers) {
    // Each is read alike by both: the same double, correctly rounded (strtod and MPFR).
    for (const char* text : {"2.5e-3", ".5", "5.", "1E+2", "007", "0.1", "1e-300", "4.9e-324", "1.7976931348623157e308",
                             "2.5 ", " 3"}) {
        const double angle = pendulum::parse_expression(text);
        const double formula = pendulum::formula(text).value(0);
        EXPECT_EQ(angle, formula) << text;
    }
    // Each is refused by both.
    for (const char* text : {".", ".e5", "1e400", "", " "}) {
        EXPECT_NE(thrown<pendulum::domain_error>([&] { (void)pendulum::parse_expression(text); }), "") << text;
        EXPECT_NE(thrown<pendulum::domain_error>([&] { pendulum::formula f(text); }), "") << text;
    }
    EXPECT_EQ(thrown<pendulum::domain_error>([] { (void)pendulum::parse_expression(".e5"); }).rfind(
                  "invalid value '.e5': '.e5' is not a number;", 0),
              0u);
    EXPECT_EQ(thrown<pendulum::domain_error>([] { pendulum::formula f(".e5"); }), "formula:1:1: '.e5' is not a number");
    EXPECT_EQ(thrown<pendulum::domain_error>([] { pendulum::formula f("1e400"); }),
              "formula:1:1: number 1e400 is beyond a double's range");
}

// ---------------------------------------------------------------------------------------
// What a mutation pass found untested: each test below fails under one small change of the
// code (named in its comment) that every other test let through.

namespace {

/// True where text contains part.
bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// Runs args in a new directory; the result, and whether a file was written.
test_support::run_result run_in_new_dir(const std::string& tag, const std::string& args, bool& wrote) {
    const auto dir = temp_dir("structure-" + tag);
    const auto r = run_cli(args + " -o '" + dir.string() + "'");
    wrote = !files_in(dir).empty();
    std::filesystem::remove_all(dir);
    return r;
}

}  // namespace

// Mutations: --tex-font-size's range 5..30 as > 5 or < 30.
TEST(Mutations, TexFontSizeFiveToThirty) {
    for (const char* inside : {"5", "30"}) {
        bool wrote = false;
        // A panel wide enough for 30 pt text.
        const auto r = run_in_new_dir(
            "tex-font", std::string("render fig1 -f pdf_tex --set panel_width_cm=30 --tex-font-size ") + inside, wrote);
        EXPECT_EQ(r.status, 0) << inside << ": " << r.err;
        EXPECT_TRUE(wrote) << inside;
    }
    for (const char* beyond : {"4.99", "30.01"}) {
        bool wrote = false;
        const auto r = run_in_new_dir("tex-font", std::string("render fig1 -f pdf_tex --tex-font-size ") + beyond, wrote);
        EXPECT_EQ(r.status, 2) << beyond;
        EXPECT_TRUE(has(r.err, std::string("--tex-font-size ") + beyond + ": the document's font size in points, 5 to 30"))
            << r.err;
        EXPECT_FALSE(wrote) << beyond;
    }
}

// Mutation: --jobs's limit 1024 as >= 1024.
TEST(Mutations, JobsUpTo1024) {
    bool wrote = false;
    const auto in = run_in_new_dir("jobs", "render fig1 -f svg --jobs 1024", wrote);
    EXPECT_EQ(in.status, 0) << in.err;
    EXPECT_TRUE(wrote);
    const auto out = run_in_new_dir("jobs", "render fig1 -f svg --jobs 1025", wrote);
    EXPECT_EQ(out.status, 2);
    EXPECT_TRUE(has(out.err, "--jobs 1025: the number of workers, 1 to 1024")) << out.err;
    EXPECT_FALSE(wrote);
}

// Mutation: a data file's problems shown up to 20 as < 20.
TEST(Mutations, ADataFileShowsTwentyProblems) {
    const auto dir = temp_dir("structure-data-problems");
    const auto problems = [&](int bad_rows) {
        std::string rows = "x,y\n";
        for (int i = 0; i < bad_rows; ++i) rows += "1,a\n";
        std::ofstream(dir / "m.csv") << rows;
        const std::string spec = "[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\n[[panel.data]]\nfile = \"m.csv\"\n"
                                 "x = \"x\"\nx_unit = \"rad\"\ny = \"y\"\ny_unit = \"T/T0\"\n";
        try {
            figures::parse_spec(spec, (dir / "s.toml").string());
        } catch (const figures::spec_error& e) {
            int n = 0;
            for (const auto& p : e.problems()) n += has(p.text(), "is not a number") ? 1 : 0;
            return n;
        }
        return 0;
    };
    EXPECT_EQ(problems(20), 20);
    EXPECT_EQ(problems(21), 20);
    std::filesystem::remove_all(dir);
}

// Mutations: x264's crf, look-ahead, threads, B-frames or the High profile's CABAC and 8x8
// transform changed in mp4_video (the frames differ too little for the pixel tests). x264
// writes its settings into the stream (the ultrafast preset with CABAC and 8x8dct back on).
TEST(Mutations, Mp4HasTheEncoderSettingsItSays) {
    const auto dir = temp_dir("structure-mp4");
    const auto r = run_cli("render swing --theme slides -f mp4 --frames 1..3 --dpi 24 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string mp4 = slurp(dir / "swing.mp4");
    const std::size_t at = mp4.find("options: ");
    ASSERT_NE(at, std::string::npos);
    const std::string options = " " + mp4.substr(at + 9, mp4.find('\0', at) - at - 9) + " ";
    for (const char* setting : {" crf=23.0 ", " subme=0 ", " sliced_threads=1 ", " threads=2 ", " bframes=0 ", " mbtree=0 ",
                                " cabac=1 ", " 8x8dct=1 "}) {
        EXPECT_TRUE(has(options, setting)) << setting << " not in" << options;
    }
    std::filesystem::remove_all(dir);
}

namespace {

/// A GIF read back with giflib, freed on scope exit.
struct read_gif {
    explicit read_gif(std::string bytes) : data(std::move(bytes)) {
        int error = 0;
        gif = DGifOpen(this, &read_gif::read, &error);
        if (!gif || DGifSlurp(gif) == GIF_ERROR) throw std::runtime_error("not a GIF");
    }
    ~read_gif() {
        int error = 0;
        if (gif) DGifCloseFile(gif, &error);
    }
    read_gif(const read_gif&) = delete;
    read_gif& operator=(const read_gif&) = delete;
    static int read(GifFileType* g, GifByteType* buf, int n) {
        auto* self = static_cast<read_gif*>(g->UserData);
        n = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(n), self->data.size() - self->pos));
        std::memcpy(buf, self->data.data() + self->pos, static_cast<std::size_t>(n));
        self->pos += static_cast<std::size_t>(n);
        return n;
    }
    std::string data;
    std::size_t pos = 0;
    GifFileType* gif = nullptr;
};

/// A GIF of `frames` frames of 8 x 8 pixels, a black pixel moving along a white row.
std::string moving_dot_gif(int frames, double fps) {
    plot::gif_encoder gif(8, 8, {{0, 0, 0}, {255, 255, 255}}, fps);
    for (int f = 0; f < frames; ++f) {
        std::vector<std::uint32_t> argb(64, 0xffffffffu);
        argb[static_cast<std::size_t>(f % 8)] = 0xff000000u;
        gif.add_frame(reinterpret_cast<const unsigned char*>(argb.data()), 32);
    }
    return gif.finish();
}

}  // namespace

// Mutation: the GIF's disposal "do not dispose" as "restore to background" (a decoder that
// composes frames would then clear what the transparent pixels are meant to keep).
TEST(Mutations, GifFramesAreNotDisposed) {
    const read_gif g(moving_dot_gif(4, 10));
    ASSERT_EQ(g.gif->ImageCount, 4);
    for (int i = 0; i < g.gif->ImageCount; ++i) {
        GraphicsControlBlock gcb{};
        ASSERT_EQ(DGifSavedExtensionToGCB(g.gif, i, &gcb), GIF_OK);
        EXPECT_EQ(gcb.DisposalMode, DISPOSE_DO_NOT) << i;
        EXPECT_EQ(gcb.DelayTime, 10) << i;
        EXPECT_EQ(gcb.TransparentColor, i == 0 ? NO_TRANSPARENT_COLOR : 2) << i;
    }
}

// Mutation: the GIF encoder's frame rate 0 < fps <= 100 as < 100.
TEST(Mutations, GifFrameRateUpTo100) {
    EXPECT_EQ(read_gif(moving_dot_gif(2, 100)).gif->ImageCount, 2);
    EXPECT_EQ(thrown<std::invalid_argument>([] { (void)moving_dot_gif(2, 100.001); }),
              "GIF frame rate must be above 0 and at most 100");
    EXPECT_EQ(thrown<std::invalid_argument>([] { (void)moving_dot_gif(2, 0); }),
              "GIF frame rate must be above 0 and at most 100");
}

// Mutation: a figure's smallest size 1 cm as <= 1 (1 refused).
TEST(Mutations, AFigureOfOneCentimetreIsAccepted) {
    const auto problems = [](const std::string& set) {
        try {
            (void)figures::load_theme("paper", {set});
        } catch (const figures::spec_error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(problems("figure_width_cm=1"), "");
    EXPECT_TRUE(has(problems("figure_width_cm=0.99"), "'figure_width_cm' = 0.99 is too small; the smallest allowed is 1"))
        << problems("figure_width_cm=0.99");
    EXPECT_EQ(problems("figure_width_cm=0"), "");  // sized by its panels
}

// Mutation: a TeX macro's suggestion, one edit for names up to 4 letters and two for longer
// ones, with the bound at 3 or 5 letters.
TEST(Mutations, MacroSuggestionsOneEditUpToFourLettersTwoBeyond) {
    const auto refusal = [](const std::string& tex) { return thrown<plot::bad_input>([&] { plot::tex_to_markup(tex); }); };
    EXPECT_EQ(refusal("$\\omga$"), "label '$\\omga$': unknown macro \\omga (did you mean \\omega?)");  // 4 letters, 1 edit
    EXPECT_EQ(refusal("$\\omgz$"), "label '$\\omgz$': unknown macro \\omgz");  // 4 letters, 2 edits
    EXPECT_EQ(refusal("$\\lamdz$"), "label '$\\lamdz$': unknown macro \\lamdz (did you mean \\lambda?)");  // 5, 2 edits
}

// Mutations: the messages of a missing or unknown command (the list joined otherwise, the
// option branch taken for a word).
TEST(Mutations, MissingCommandAndOptionBeforeTheCommand) {
    const auto none = run_cli("");
    EXPECT_EQ(none.status, 2);
    EXPECT_EQ(none.err, "pendulum-figures: error: a command is required: eval, trajectory, render, list, claims, "
                        "show, plot, data, describe or complete (see --help)\n");
    const auto option = run_cli("--frobnicate");
    EXPECT_EQ(option.status, 2);
    EXPECT_EQ(option.err, "pendulum-figures: error: unknown option '--frobnicate'; options before the command are "
                          "--help and --version (see --help)\n");
}
