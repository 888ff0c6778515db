// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The writers of animations that the format table's rows hold; not a public interface
// (write an animation through find_format(name).animate).

#include "plot/output.hpp"

#include <filesystem>
#include <string>

namespace plot {

/// DIR/ID.gif: a GIF that loops, frames encoded on every core and joined in order.
void write_gif_animation(const animation_frames& frames, const theme& th, const std::filesystem::path& dir,
                         const std::string& id, const output_options& options);

/// DIR/ID.pdf: one page per frame, for Beamer's animate package.
void write_pdf_animation(const animation_frames& frames, const theme& th, const std::filesystem::path& dir,
                         const std::string& id, const output_options& options);

/// DIR/ID-0001.png ...: one PNG per frame, numbered from 1, drawn on every core.
void write_png_animation(const animation_frames& frames, const theme& th, const std::filesystem::path& dir,
                         const std::string& id, const output_options& options);

/// DIR/ID.mp4: H.264 for slides (see mp4_video); frames drawn on every core, encoded in order.
void write_mp4_animation(const animation_frames& frames, const theme& th, const std::filesystem::path& dir,
                         const std::string& id, const output_options& options);

/// DIR/ID.webm: VP9 for browsers (see webm_video); frames drawn on every core, encoded in order.
void write_webm_animation(const animation_frames& frames, const theme& th, const std::filesystem::path& dir,
                          const std::string& id, const output_options& options);

/// ID.mp4, the file of every frame.
std::string mp4_animation_file(const std::string& id, int frame, int count);

/// ID.webm, the file of every frame.
std::string webm_animation_file(const std::string& id, int frame, int count);

/// ID.gif, the file of every frame.
std::string gif_animation_file(const std::string& id, int frame, int count);

/// ID.pdf, the file of every frame.
std::string pdf_animation_file(const std::string& id, int frame, int count);

/// ID-0001.png ...: frame i's file, numbered from 1 with at least four digits, as many as
/// the largest number needs.
std::string png_frame_file(const std::string& id, int frame, int count);

}  // namespace plot
