// SPDX-License-Identifier: GPL-3.0-or-later
// The catalog's speed work keeps what it draws: PNGs (libdeflate) hold exactly the pixels
// drawn, the private font configuration lists the fonts fontconfig's own does, and the
// alt text is the same whether the figure's curves were drawn before it or not.
#include "figures/build_options.hpp"
#include "figures/catalog.hpp"
#include "figures/describe.hpp"
#include "figures/themes.hpp"
#include "plot/frames.hpp"
#include "plot/output.hpp"
#include "plot/text.hpp"
#include "plot/workers.hpp"
#include "png_image.hpp"
#include "rgb24_image.hpp"
#include "process.hpp"

#include <fontconfig/fontconfig.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <set>
#include <string>
#include <vector>

using namespace test_support;

namespace {

/// An RGB24 image of w x h pixels, pixel(x, y) each (0xRRGGBB), its unused byte 0xff.
plot::argb_image image_of(int w, int h, const std::function<std::uint32_t(int, int)>& pixel) {
    return rgb24_of(w, h, [&](int x, int y) { return pixel(x, y) | 0xff000000u; });
}

/// CRC-32 of PNG (ISO 3309), bit by bit: independent of the encoder's own.
std::uint32_t crc32_of(const std::string& bytes, std::size_t from, std::size_t size) {
    std::uint32_t c = 0xffffffffu;
    for (std::size_t i = from; i < from + size; ++i) {
        c ^= static_cast<unsigned char>(bytes[i]);
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
}

std::uint32_t be32(const std::string& b, std::size_t at) {
    return (std::uint32_t{static_cast<unsigned char>(b[at])} << 24) | (std::uint32_t{static_cast<unsigned char>(b[at + 1])} << 16) |
           (std::uint32_t{static_cast<unsigned char>(b[at + 2])} << 8) | static_cast<unsigned char>(b[at + 3]);
}

/// The chunk types of a PNG in order, each chunk's CRC checked.
std::vector<std::string> checked_chunks(const std::string& png) {
    std::vector<std::string> types;
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    for (std::size_t at = 8; at + 12 <= png.size();) {
        const std::uint32_t length = be32(png, at);
        EXPECT_LE(at + 12 + length, png.size());
        if (at + 12 + length > png.size()) break;
        types.push_back(png.substr(at + 4, 4));
        EXPECT_EQ(be32(png, at + 8 + length), crc32_of(png, at + 4, 4 + length)) << types.back();
        at += 12 + length;
    }
    return types;
}

/// Encodes, checks the chunks and decodes the image; the decoded pixels must be the image's.
std::string round_trip(const plot::argb_image& im, double dpi = 300) {
    std::vector<unsigned char> scratch;
    const std::string png = plot::png_of_pixels(im, dpi, scratch);
    const auto chunks = checked_chunks(png);
    EXPECT_FALSE(chunks.empty());
    if (!chunks.empty()) {
        EXPECT_EQ(chunks.front(), "IHDR");
        EXPECT_EQ(chunks.back(), "IEND");
    }
    const rgb_image decoded = decode_rgb(png);
    EXPECT_EQ(decoded.width, static_cast<unsigned>(im.width));
    EXPECT_EQ(decoded.height, static_cast<unsigned>(im.height));
    EXPECT_TRUE(decoded.pixels == rgb_of(im));
    return png;
}

}  // namespace

TEST(CatalogPng, GreyPaletteAndRgbHoldTheirPixels) {
    // 256 grey levels: grey.
    EXPECT_EQ(color_type(round_trip(image_of(256, 3, [](int x, int) { return 0x010101u * x; }))), 0);
    // 256 colours: a palette (the most one holds) ...
    const auto colours = [](int n) {
        return [n](int x, int y) { return static_cast<std::uint32_t>(((x + 7 * y) % n) * 0x010203u + 0x100000u); };
    };
    const std::string palette = round_trip(image_of(300, 5, colours(256)));
    EXPECT_EQ(color_type(palette), 3);
    const auto chunks = checked_chunks(palette);
    EXPECT_EQ(chunks, (std::vector<std::string>{"IHDR", "PLTE", "pHYs", "IDAT", "IEND"}));
    // ... 257: RGB.
    EXPECT_EQ(color_type(round_trip(image_of(300, 5, colours(257)))), 2);
    // One pixel, and one row of the widest kind.
    EXPECT_EQ(color_type(round_trip(image_of(1, 1, [](int, int) { return 0x1e1e28u; }))), 3);
    EXPECT_EQ(color_type(round_trip(image_of(4000, 1, [](int x, int) { return static_cast<std::uint32_t>(x * 977); }))), 2);
}

TEST(CatalogPng, ResolutionIsKept) {
    const std::string png = round_trip(image_of(10, 10, [](int, int) { return 0xffffffu; }), 300);
    const std::size_t phys = png.find("pHYs");
    ASSERT_NE(phys, std::string::npos);
    EXPECT_EQ(be32(png, phys + 4), 11811u);  // 300 dpi in pixels a metre
    EXPECT_EQ(be32(png, phys + 8), 11811u);
    EXPECT_EQ(png[phys + 12], 1);  // the metre
}

TEST(CatalogPng, FiguresInEveryThemeHoldTheirPixels) {
    for (const char* name : {"paper", "slides", "slides-dark"}) {
        const plot::theme theme = figures::load_theme(name);
        const auto& e = figures::find("fig7");
        const plot::figure f = figures::build(e, figures::sized_by({}, theme));
        plot::argb_image image;
        plot::render_rgb24(image, f, theme, 150);
        const std::string png = round_trip(image, 150);
        // What render writes is these very bytes.
        plot::output_options o;
        o.dpi = 150;
        EXPECT_EQ(plot::render(f, theme, "png", o), png) << name;
    }
}

TEST(CatalogPng, AnotherDecoderReadsThePixels) {
    // Python's PIL, an implementation other than libpng, reads what the tool wrote.
    const auto dir = temp_dir("catalog-png");
    for (const char* theme : {"paper", "slides-dark"}) {
        const auto r = run_cli(std::string("render fig7 -f png --dpi 100 --force --theme ") + theme + " -o " + dir.string());
        ASSERT_EQ(r.status, 0) << r.err;
        const std::string png = slurp(dir / "period.png");
        const auto py = run_command("/usr/bin/python3 -c \"import sys; from PIL import Image; im = Image.open(sys.argv[1]); "
                                    "im.load(); sys.stdout.buffer.write(im.convert('RGB').tobytes())\" " +
                                    (dir / "period.png").string());
        ASSERT_EQ(py.status, 0) << py.err;
        const rgb_image ours = decode_rgb(png);
        EXPECT_TRUE(std::vector<unsigned char>(py.out.begin(), py.out.end()) == ours.pixels) << theme;
    }
}

TEST(CatalogFonts, PrivateDirectoriesAreFontconfigsOwn) {
    // Read from the fontconfig files, not by fontconfig parsing them: the same directories.
    std::set<std::string> own;
    FcConfig* system = FcInitLoadConfig();
    ASSERT_NE(system, nullptr);
    FcStrList* dirs = FcConfigGetFontDirs(system);
    while (const FcChar8* d = FcStrListNext(dirs)) own.insert(reinterpret_cast<const char*>(d));
    FcStrListDone(dirs);
    FcConfigDestroy(system);
    // Built, the configuration lists the subdirectories it scanned too.
    const auto ours = plot::private_font_directories();
    const std::set<std::string> listed(ours.begin(), ours.end());
    EXPECT_EQ(listed.size(), ours.size());  // none twice
    for (const auto& d : own) EXPECT_TRUE(listed.contains(d)) << d;
    for (const auto& d : listed) {
        const bool under = std::any_of(own.begin(), own.end(), [&](const std::string& o) { return d == o || d.starts_with(o + "/"); });
        EXPECT_TRUE(under) << d << " is not in fontconfig's own directories";
    }
}

namespace {

/// A font outside fontconfig's directories (one of TeX Live's) and its family; empty if none.
std::pair<std::string, std::string> font_unknown_to_fontconfig() {
    const auto script = temp_dir("catalog-font-find") / "find.sh";
    std::ofstream(script) << (
        "known=$(fc-list : family); find /usr/share/texlive /usr/share/texmf -name '*.otf' 2>/dev/null | sort | "
        "while read -r f; do fam=$(fc-scan --format '%{family[0]}\\n' \"$f\" 2>/dev/null | sed -n 1p); "
        "if [ -n \"$fam\" ] && ! grep -qxF \"$fam\" <<<\"$known\" && ! grep -q '[,\"&<]' <<<\"$fam\"; then "
        "echo \"$f\"; echo \"$fam\"; break; fi; done\n");
    const auto r = run_command("bash " + script.string());
    const auto nl = r.out.find('\n');
    if (nl == std::string::npos) return {};
    std::string family = r.out.substr(nl + 1);
    while (!family.empty() && family.back() == '\n') family.pop_back();
    return {r.out.substr(0, nl), family};
}

/// Renders fig1 as SVG with the family first, HOME and XDG_CONFIG_HOME in `home`.
run_result render_with_family(const std::filesystem::path& home, const std::string& family) {
    return run_command("cd " + home.string() + " && env -u FONTCONFIG_FILE -u FONTCONFIG_PATH -u XDG_DATA_HOME HOME=" +
                       home.string() + " XDG_CONFIG_HOME=" + (home / "config").string() + " XDG_CACHE_HOME=" +
                       (home / "cache").string() + " timeout 120 " + PENDULUM_EXE + " render fig1 -f svg --force -o " +
                       home.string() + " --set 'font_family=" + family + ", DejaVu Sans'");
}

void write_file(const std::filesystem::path& p, const std::string& text) {
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << text;
}

}  // namespace

TEST(CatalogFonts, TheUsersFontconfigDirectoriesAreRead) {
    const auto [font, family] = font_unknown_to_fontconfig();
    if (font.empty()) GTEST_SKIP() << "no font outside fontconfig's directories";
    const auto home = temp_dir("catalog-fonts");
    std::filesystem::create_directories(home / "config");
    // Not named anywhere: refused (exit 2), as before.
    auto r = render_with_family(home, family);
    EXPECT_EQ(r.status, 2) << r.err;
    // The user's fonts.conf names the font's directory (an & in its name, as XML writes it).
    const auto dir = home / "my fonts & more";
    std::filesystem::create_directories(dir);
    std::filesystem::copy_file(font, dir / std::filesystem::path(font).filename());
    write_file(home / "config/fontconfig/fonts.conf",
               "<?xml version=\"1.0\"?>\n<fontconfig>\n  <!-- <dir>/nowhere</dir> -->\n  <dir>" +
                   (home / "my fonts &amp; more").string() + "</dir>\n</fontconfig>\n");
    r = render_with_family(home, family);
    EXPECT_EQ(r.status, 0) << r.err;
    // Through a file the user's conf.d includes, and a relative <dir>, which fontconfig resolves itself.
    std::filesystem::remove(home / "config/fontconfig/fonts.conf");
    write_file(home / "config/fontconfig/conf.d/10-mine.conf",
               "<fontconfig><include ignore_missing=\"yes\">" + (home / "more.conf").string() + "</include></fontconfig>");
    write_file(home / "more.conf", "<fontconfig><dir prefix=\"cwd\">my fonts &amp; more</dir></fontconfig>");
    r = render_with_family(home, family);
    EXPECT_EQ(r.status, 0) << r.err;
}

TEST(CatalogFonts, HostileConfigurationsEndAndChangeNothing) {
    const auto home = temp_dir("catalog-fonts-hostile");
    std::filesystem::create_directories(home / "config");
    // A file that includes itself, one not closed, and a <reset-dirs/>: the scan leaves them
    // to fontconfig, which reads them as it always did.
    write_file(home / "config/fontconfig/fonts.conf",
               "<fontconfig><include>" + (home / "config/fontconfig/fonts.conf").string() +
                   "</include><dir>/usr/share/fonts</fontconfig>");
    auto r = render_with_family(home, "DejaVu Sans");
    EXPECT_EQ(r.status, 0) << r.err;
    write_file(home / "config/fontconfig/fonts.conf", "<fontconfig><reset-dirs/><dir>/usr/share/fonts</dir></fontconfig>");
    r = render_with_family(home, "DejaVu Sans");
    EXPECT_EQ(r.status, 0) << r.err;
}

TEST(CatalogAltText, TheSameBeforeAndAfterTheDrawing) {
    // The description reads the curves through their memo: drawn first or not, the same words.
    const plot::theme paper = figures::load_theme("paper");
    const auto& e = figures::find("fig7");
    const figures::build_options options = figures::sized_by({}, paper);
    const plot::figure fresh = figures::build(e, options);
    const auto before = figures::describe(e, fresh, options);
    const plot::figure drawn = figures::build(e, options);
    plot::output_options o;
    o.dpi = 300;
    (void)plot::render(drawn, paper, "png", o);
    const auto after = figures::describe(e, drawn, options);
    EXPECT_EQ(before.alt, after.alt);
    EXPECT_EQ(before.text, after.text);
    EXPECT_NE(before.text.find("Leaving"), std::string::npos) << before.text;
}

TEST(CatalogThreads, ParallelForRunsEachOnceWithinTheLimit) {
    for (unsigned limit : {1u, 2u, 3u}) {
        plot::set_thread_limit(limit);
        std::mutex lock;
        std::condition_variable all_in;
        int running = 0, most = 0;
        std::vector<int> runs(12, 0);
        plot::parallel_for(runs.size(), [&](std::size_t i) {
            std::unique_lock hold(lock);
            most = std::max(most, ++running);
            ++runs[i];
            all_in.notify_all();
            // Waits a while for the other threads, so that all of them run at once.
            all_in.wait_for(hold, std::chrono::seconds(5), [&] { return most >= static_cast<int>(limit); });
            hold.unlock();
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            hold.lock();
            --running;
        });
        EXPECT_EQ(runs, std::vector<int>(12, 1));
        // The calling thread counts as one: `limit` threads at most, and here all of them.
        EXPECT_EQ(most, static_cast<int>(limit)) << limit;
    }
    plot::set_thread_limit(0);
}

TEST(CatalogThreads, ParallelForRethrowsTheError) {
    plot::set_thread_limit(2);
    EXPECT_THROW(plot::parallel_for(8, [](std::size_t i) {
                     if (i == 3) throw std::runtime_error("three");
                 }),
                 std::runtime_error);
    plot::parallel_for(0, [](std::size_t) { ADD_FAILURE() << "no index"; });
    plot::set_thread_limit(0);
}

TEST(CatalogThreads, ConvergenceIsTheSameOnAnyNumberOfThreads) {
    const auto one = run_command(std::string("PENDULUM_FIGURES_JOBS=1 ") + PENDULUM_EXE + " data convergence");
    const auto two = run_command(std::string("PENDULUM_FIGURES_JOBS=2 ") + PENDULUM_EXE + " data convergence");
    const auto most = run_command(std::string("PENDULUM_FIGURES_JOBS=1024 ") + PENDULUM_EXE + " data convergence");
    ASSERT_EQ(one.status, 0) << one.err;
    EXPECT_GT(one.out.size(), 1000u);
    EXPECT_EQ(one.out, two.out);
    EXPECT_EQ(one.out, most.out);
    const auto over = run_command(std::string("PENDULUM_FIGURES_JOBS=1025 ") + PENDULUM_EXE + " data convergence");
    EXPECT_EQ(over.status, 2);
    EXPECT_NE(over.err.find("PENDULUM_FIGURES_JOBS='1025': the number of workers, 1 to 1024"), std::string::npos) << over.err;
    const auto dir = temp_dir("catalog-convergence");
    for (const char* jobs : {"1", "2"}) {
        std::filesystem::create_directories(dir / jobs);
        const auto r = run_cli(std::string("render convergence -f pdf,png --dpi 100 --force --jobs ") + jobs + " -o " +
                               (dir / jobs).string());
        ASSERT_EQ(r.status, 0) << r.err;
    }
    EXPECT_EQ(slurp(dir / "1/convergence.pdf"), slurp(dir / "2/convergence.pdf"));
    EXPECT_EQ(slurp(dir / "1/convergence.png"), slurp(dir / "2/convergence.png"));
}
