// Text over a frame: the lines to show (GL- and cairo-free, testable) and
// their drawing with cairo's text API and the DejaVu Sans font into an ARGB
// image composited over the frame (RGBA, rgba_view.hpp). The renderer's only file that includes
// cairo.h (report/plot/plot.cpp is the report's).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "render/pixel_rect.hpp"
#include "render/playback.hpp"
#include "render/rgba_view.hpp"
#include "render/scene.hpp"

namespace elbowsim {

// "<title>", "t = 1.234 s", "E_in = 5.678 J" (when recorded) and per elbow
// "<name>: 9.52 N resting" (with contact; "landed" for landed_window after a
// touchdown), or "<name>: free, 20.0 mm above the table" ("lifted" after a
// lift-off; the height when the distance is recorded).
std::vector<std::string> overlay_lines(const std::string& title, const Model& model,
                                       const PlaybackState& state, double landed_window = 0.1);

// Draws `lines` in a translucent box at the top-left of `region` of a frame
// (its red, green and blue; the fourth bytes are left as they are). The font size
// follows the region: 1/40 of its height or 1/26 of its width, whichever is
// smaller, at least 6 px (18 px in a 1280x720 frame). The box is at
// least `min_width` wide; returns its width, so that a video can keep the box
// from narrowing as the numbers change.
int draw_overlay(RgbaView frame, const PixelRect& region, const std::vector<std::string>& lines,
                 int min_width = 0);

// The text and marks on an inset (inset.hpp), in output pixels.
struct InsetOverlay {
  PixelRect rect;           // the inset, from the image's top-left corner
  std::string title;        // top left: "hand path ×9"
  std::string scale_label;  // "1 cm"
  double scale_bar_px = 0;  // bottom left, this long
  Color desired, traced;    // legend, top right
};

// Draws a frame around the inset, its title, a legend of the two paths and
// the scale bar (each on a translucent white ground) into a frame. Font
// size: 1/18 of the inset's height. The marks are drawn with cairo once and
// kept: while they stay the same (all of a run's frames but where the
// title's magnification changes), each frame only blends the pixels they
// cover (runs of them), the same bytes as drawing them again.
class InsetOverlayLayer {
 public:
  void draw(RgbaView frame, const InsetOverlay& inset);

 private:
  void redraw(const InsetOverlay& inset);

  std::optional<InsetOverlay> drawn_;  // the marks in layer_
  std::vector<std::uint32_t> layer_;   // cairo's premultiplied ARGB words, rect.width x rect.height
  struct Run {
    int y, x, length;  // [px] in the layer
  };
  std::vector<Run> runs_;  // where layer_ is not transparent
};

}  // namespace elbowsim
