#include "render/overlay.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace elbowsim {

namespace {

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

const char* state_word(const ElbowSample& e, double t, double window) {
  if (!e.resting) return "free";
  return t - e.landed_at <= window ? "landed" : "resting";
}

}  // namespace

std::vector<std::string> overlay_lines(const std::string& title, const Model& model,
                                       const PlaybackState& state, double landed_window) {
  std::vector<std::string> lines{title, format("t = %.3f s", state.t)};
  if (state.energy_in) lines.push_back(format("E_in = %.3f J", *state.energy_in));
  if (!model.effects.contact) return lines;
  for (std::size_t k = 0; k < model.elbows.size() && k < state.elbows.size(); ++k) {
    const ElbowSample& e = state.elbows[k];
    std::string line = model.elbows[k].name + ": ";
    if (e.resting) line += format("%.2f N ", e.fn);
    lines.push_back(line + state_word(e, state.t, landed_window));
  }
  return lines;
}

int draw_overlay(std::uint8_t* rgb, int width, int height, const PixelRect& region,
                 const std::vector<std::string>& lines, int min_width) {
  if (lines.empty()) return min_width;
  const double size = std::max(6.0, std::min(region.height / 40.0, region.width / 26.0));
  const int pad = int(std::ceil(0.5 * size)), line_height = int(std::ceil(1.35 * size));
  // Measure the text on a scratch surface, then draw it on one of the box's size.
  cairo_surface_t* scratch = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
  cairo_t* cr = cairo_create(scratch);
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  double text_width = 0;
  for (const std::string& line : lines) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, line.c_str(), &extents);
    text_width = std::max(text_width, extents.x_advance);
  }
  cairo_destroy(cr);
  cairo_surface_destroy(scratch);
  // Box width rounded up to 2 font sizes.
  const int step = int(2 * size);
  int box_w =
      std::max(min_width, ((int(std::ceil(text_width)) + 2 * pad + step - 1) / step) * step);
  const int used_width = box_w;
  int box_h = int(lines.size()) * line_height + 2 * pad;
  const int x0 = region.x + pad, y0 = region.y + pad;
  box_w = std::min(box_w, std::min(width, region.x + region.width) - x0);
  box_h = std::min(box_h, std::min(height, region.y + region.height) - y0);
  if (box_w <= 0 || box_h <= 0) return used_width;

  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, box_w, box_h);
  cr = cairo_create(surface);
  cairo_set_source_rgba(cr, 0.08, 0.09, 0.11, 0.62);
  cairo_paint(cr);
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_set_source_rgb(cr, 1, 1, 1);
  for (std::size_t k = 0; k < lines.size(); ++k) {
    cairo_move_to(cr, pad, pad + double(k) * line_height + size);
    cairo_show_text(cr, lines[k].c_str());
  }
  cairo_destroy(cr);
  cairo_surface_flush(surface);

  // Composite: premultiplied ARGB (native-endian 32-bit words) over RGB.
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = 0; y < box_h; ++y) {
    const auto* src = reinterpret_cast<const std::uint32_t*>(data + std::size_t(y) * stride);
    std::uint8_t* dst = rgb + (std::size_t(y0 + y) * std::size_t(width) + std::size_t(x0)) * 3;
    for (int x = 0; x < box_w; ++x, dst += 3) {
      const std::uint32_t p = src[x];
      const unsigned a = p >> 24, keep = 255 - a;
      dst[0] = std::uint8_t(((p >> 16) & 255) + (dst[0] * keep + 127) / 255);
      dst[1] = std::uint8_t(((p >> 8) & 255) + (dst[1] * keep + 127) / 255);
      dst[2] = std::uint8_t((p & 255) + (dst[2] * keep + 127) / 255);
    }
  }
  cairo_surface_destroy(surface);
  return used_width;
}

}  // namespace elbowsim
