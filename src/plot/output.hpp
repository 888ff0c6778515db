// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "plot/errors.hpp"
#include "plot/figure.hpp"
#include "plot/theme.hpp"

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace plot {

/// How a LaTeX overlay (pdf_tex, eps_tex) sizes its text.
enum class tex_sizing {
    relative,  ///< LaTeX's size commands (\footnotesize, \small): the text follows the document's size
    absolute,  ///< the theme's sizes in points (\fontsize): the same in any document
};

/// One way of sizing an overlay's text: its name, what it does, for help, errors and lists.
struct tex_sizing_row {
    std::string_view name;         ///< the value of --tex-sizes
    tex_sizing value;              ///< the sizing
    std::string_view description;  ///< one line for help and lists
};

/// Every way of sizing an overlay's text, the default first.
std::span<const tex_sizing_row> tex_sizing_table();

/// The sizing of that name; throws plot::bad_input listing the names otherwise.
const tex_sizing_row& find_tex_sizing(std::string_view name);

/// Options that apply when a figure is written.
struct output_options {
    double dpi = 300;          ///< raster resolution (PNG)
    bool force = false;        ///< rewrite a file even if it already holds the same bytes
    double tex_font_pt = 10;   ///< the document's font size, for pdf_tex and eps_tex (relative sizes)
    tex_sizing tex_sizes = tex_sizing::relative;  ///< how pdf_tex and eps_tex size their text
    unsigned jobs = 0;         ///< worker threads; 0: one per CPU this process may use (plot::usable_cpus)
};

/// The smallest and largest accepted --dpi.
inline constexpr double min_dpi = 10;
/// The largest accepted dpi.
inline constexpr double max_dpi = 2400;

/// The largest raster: Cairo's limit per side, and a bound on memory (4 bytes a pixel).
inline constexpr int max_raster_side = 32767;
/// The most pixels in one raster (400 MB as Cairo holds it).
inline constexpr double max_raster_pixels = 1e8;

/// Throws plot::bad_input, naming the size and the largest dpi that fits, if the
/// figure at dpi would be a raster larger than the limits above.
void check_raster_size(const figure& fig, const theme& th, double dpi);

struct placed_text;

/// The frames of an animation, as an animation writer takes them.
struct animation_frames {
    int first = 0;                     ///< the first frame to write, from 0
    int last = 0;                      ///< the last frame to write (inclusive)
    int count = 1;                     ///< frames in the whole animation (a sequence's numbers have its width)
    double fps = 30;                   ///< frames per second of playback
    std::function<figure(int)> frame;  ///< the figure of frame i, callable from several threads
};

/// Writes an animation's frames as DIR/ID.EXT (or a sequence DIR/ID-0001.EXT ...).
using animation_writer = void (*)(const animation_frames& frames, const theme& th, const std::filesystem::path& dir,
                                  const std::string& id, const output_options& options);

/// One output format and what it means: its file extension, what it is, and the functions
/// that write it. A new format is a row here and its writers; help, lists, messages and
/// the command line's checks read the rest from the row.
struct format_row {
    std::string_view name;         ///< file extension
    std::string_view description;  ///< one line for help and lists
    /// A still figure's bytes; null for a format that holds animations only (a video).
    std::string (*write)(const figure& fig, const theme& th, const output_options& options);
    std::string_view graphics;     ///< for a LaTeX overlay: the format of the drawing beside it
    /// The bytes with every text left out and recorded in `texts` instead, to be the drawing
    /// under a LaTeX overlay; null if the format cannot be one.
    std::string (*write_without_text)(const figure& fig, const theme& th, const output_options& options,
                                      std::vector<placed_text>* texts);
    bool raster;                   ///< pixels at --dpi: its size is checked before any work
    animation_writer animate;      ///< writes all frames of an animation; null: an animation is one frame
    std::string_view animation;    ///< what animate writes, for help: "a looping GIF"
    /// The name of the file that frame i (from 0) of an animation of `count` frames goes to:
    /// ID.EXT for a format that holds every frame in one file, ID-0001.EXT ... for a
    /// sequence; null where animate is.
    std::string (*frame_file)(const std::string& id, int frame, int count);
    /// Throws plot::bad_input, naming fps and the rates that play, if an animation at `fps`
    /// frames per second cannot be played as the format holds it; null: any rate plays.
    void (*check_frame_rate)(double fps);
    /// Whether an animation in this format plays its motion: every frame in one file that
    /// plays them in time (GIF, video), not a sequence of PNGs nor a PDF of pages.
    bool plays_motion;
    /// The frame rate the format plays for a spec's `fps` (a GIF's of whole hundredths of a
    /// second); null: the spec's rate.
    double (*playback_rate)(double fps);
};

/// A LaTeX overlay's two files: the drawing without text, and the picture that sets the text.
struct overlay_files {
    std::string graphics;  ///< PDF or EPS bytes
    std::string tex;       ///< the picture environment, \input by the document
};

/// Renders the drawing (in graphics_format, pdf or eps) without its text, and the LaTeX
/// picture that includes it as graphics_name and puts every text at its place.
overlay_files render_overlay(const figure& fig, const theme& th, std::string_view graphics_format,
                             const std::string& graphics_name, const output_options& options);

/// Every output format, in the order help lists them.
std::span<const format_row> format_table();

/// The format of that name; throws plot::bad_input listing the formats otherwise.
const format_row& find_format(std::string_view format);

/// The supported output formats, as file extensions, in the table's order.
std::vector<std::string> format_names();

/// The names of the formats whose row passes `keep`, joined with ", " and `last` before the
/// final one: "pdf_tex and eps_tex".
std::string format_names(bool (*keep)(const format_row&), std::string_view last = ", ");

/// Throws plot::bad_input listing the supported formats unless `format` is one.
void check_format(std::string_view format);

/// Throws plot::bad_input, naming the formats that can, unless `format` holds a still figure.
void check_still_format(std::string_view format);

/// The creation date of PDF files, "YYYY-MM-DDTHH:MM:SSZ" from SOURCE_DATE_EPOCH, or empty;
/// throws plot::bad_input naming it if it is set and not 0 to 253402300799 seconds.
std::string pdf_creation_date();

/// Renders the figure in the format and returns the file's bytes. The same input always
/// gives the same bytes: dates come from SOURCE_DATE_EPOCH or are left out.
std::string render(const figure& fig, const theme& th, std::string_view format, const output_options& options);

struct argb_image;

/// The PNG of pixels drawn by render_rgb24 at dpi: the bytes render writes for the same
/// pixels. `scratch` holds the rows to encode; reused, it spares a large frame's mapping.
std::string png_of_pixels(const argb_image& image, double dpi, std::vector<unsigned char>& scratch);

/// Throws plot::bad_input naming the path, and saying that -o - writes through such a thing,
/// if a symbolic link (dangling or not), a directory, a device, a FIFO or a socket stands at
/// path: an output is a new file or replaces a regular one, and never writes through
/// anything. The links of the directories above it are followed. Nothing is opened: a FIFO
/// does not block. Throws std::runtime_error naming the path if it cannot be looked at.
void check_output_file(const std::filesystem::path& path);

/// check_output_file for each path, in order: every output of a command, before any work.
void check_output_files(const std::vector<std::filesystem::path>& paths);

/// Writes bytes to path through a temporary file in the same directory (created with O_EXCL)
/// and a rename, so the file is either the old one or the complete new one; an existing file
/// keeps its mode. Throws plot::bad_input as check_output_file does, std::runtime_error naming
/// the path if writing fails. Renames into a directory wait for another process's group of
/// renames into it (see write_atomically of several files).
void write_atomically(const std::filesystem::path& path, const std::string& bytes);

/// Writes the file as write_atomically does, its contents written by fill(file) into the
/// file it is given by name (a temporary beside path): for a writer that opens its file
/// itself, and a file that need not be held in memory.
void write_atomically_by(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path& file)>& fill);

/// Writes the files as write_atomically does one, each complete under a temporary name and
/// on disk before the first is renamed, then renamed in order: a pair that belongs together
/// (a LaTeX overlay and its drawing) changes together. The renames hold an exclusive flock
/// on their directories, so two processes writing one pair never leave it half one's and
/// half the other's. Throws std::runtime_error naming the path that failed; then no file
/// has changed unless its rename had already been done.
void write_atomically(const std::vector<std::pair<std::filesystem::path, std::string>>& files);

/// Writes bytes to path unless it is a regular file that already holds them (so its
/// modification time stays, and make does not rebuild what depends on it); true if written.
bool write_if_changed(const std::filesystem::path& path, const std::string& bytes);

/// Renders and writes the figure; the format is the path's extension. A file that would not
/// change is left alone unless options.force.
void save(const figure& fig, const theme& th, const std::filesystem::path& path, const output_options& options);

}  // namespace plot
