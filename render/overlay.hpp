// Text over a frame: the lines to show (GL- and cairo-free, testable) and
// their drawing with cairo's text API and the DejaVu Sans font into an ARGB
// image composited over the RGB frame. The renderer's only file that includes cairo.h
// (report/plot/plot.cpp is the report's).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "render/playback.hpp"

namespace elbowsim {

// "<title>", "t = 1.234 s", "E_in = 5.678 J" (when recorded) and per elbow
// "<name>: 9.52 N resting" (with contact; free elbows show no force).
std::vector<std::string> overlay_lines(const std::string& title, const Model& model,
                                       const PlaybackState& state, double landed_window = 0.1);

// A rectangle of an image in pixels, from the top-left corner.
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

// Draws `lines` in a translucent box at the top-left of `region` of an RGB
// image (width x height, rows top-down, 3 bytes per pixel). The font size
// follows the region: 1/40 of its height or 1/26 of its width, whichever is
// smaller, at least 6 px (18 px in a 1280x720 frame). The box is at
// least `min_width` wide; returns its width, so that a video can keep the box
// from narrowing as the numbers change.
int draw_overlay(std::uint8_t* rgb, int width, int height, const PixelRect& region,
                 const std::vector<std::string>& lines, int min_width = 0);

}  // namespace elbowsim
