#include "render/overlay.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "engine/recording/number_text.hpp"

namespace elbowsim {

namespace {

const char* state_word(const ElbowSample& e, double t, double window) {
  if (!e.resting) return t - e.lifted_at <= window ? "lifted" : "free";
  return t - e.landed_at <= window ? "landed" : "resting";
}

// One premultiplied ARGB word (cairo's, native-endian) over a pixel.
void blend_over(std::uint8_t* dst, std::uint32_t p) {
  const unsigned keep = 255 - (p >> 24);
  dst[0] = std::uint8_t(((p >> 16) & 255) + (dst[0] * keep + 127) / 255);
  dst[1] = std::uint8_t(((p >> 8) & 255) + (dst[1] * keep + 127) / 255);
  dst[2] = std::uint8_t((p & 255) + (dst[2] * keep + 127) / 255);
}

// Composites a cairo ARGB surface over a frame at (x0, y0), clipped to the frame.
void composite(cairo_surface_t* surface, RgbaView frame, int x0, int y0) {
  cairo_surface_flush(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const int w = cairo_image_surface_get_width(surface), h = cairo_image_surface_get_height(surface);
  for (int y = std::max(0, -y0); y < h && y0 + y < frame.height; ++y) {
    const auto* src = reinterpret_cast<const std::uint32_t*>(data + std::size_t(y) * stride);
    for (int x = std::max(0, -x0); x < w && x0 + x < frame.width; ++x)
      if (src[x] != 0) blend_over(frame.pixel(x0 + x, y0 + y), src[x]);  // 0: transparent
  }
}

bool operator==(const Color& a, const Color& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

bool same_marks(const InsetOverlay& a, const InsetOverlay& b) {
  return a.rect.x == b.rect.x && a.rect.y == b.rect.y && a.rect.width == b.rect.width &&
         a.rect.height == b.rect.height && a.title == b.title && a.scale_label == b.scale_label &&
         a.scale_bar_px == b.scale_bar_px && a.desired == b.desired && a.traced == b.traced;
}

cairo_t* text_context(cairo_surface_t* surface, double size) {
  cairo_t* cr = cairo_create(surface);
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  return cr;
}

double text_width(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

// A translucent white ground behind a label or mark.
void ground(cairo_t* cr, double x, double y, double w, double h) {
  cairo_set_source_rgba(cr, 1, 1, 1, 0.8);
  cairo_rectangle(cr, x, y, w, h);
  cairo_fill(cr);
}

void text_at(cairo_t* cr, double x, double baseline, const std::string& text) {
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.12);
  cairo_move_to(cr, x, baseline);
  cairo_show_text(cr, text.c_str());
}

// Legend, top right: a short stroke of each path and its name.
void legend(cairo_t* cr, const InsetOverlay& inset, double size, double pad) {
  const double swatch = 1.6 * size, line = 1.3 * size;
  const double w =
      swatch + 0.4 * size + std::max(text_width(cr, "desired"), text_width(cr, "traced"));
  const double x = inset.rect.width - pad - w, y = pad;
  ground(cr, x - 0.3 * size, y - 0.2 * size, w + 0.6 * size, 2 * line + 0.3 * size);
  const std::pair<const char*, const Color*> items[2] = {{"desired", &inset.desired},
                                                         {"traced", &inset.traced}};
  for (int k = 0; k < 2; ++k) {
    const double mid = y + (k + 0.5) * line;
    const Color& c = *items[k].second;
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_set_line_width(cr, k == 0 ? 6 : 2);
    cairo_move_to(cr, x, mid);
    cairo_line_to(cr, x + swatch, mid);
    cairo_stroke(cr);
    text_at(cr, x + swatch + 0.4 * size, mid + 0.35 * size, items[k].first);
  }
}

// Scale bar, bottom left: a bar with end ticks, its length above it.
void scale_bar(cairo_t* cr, const InsetOverlay& inset, double size, double pad) {
  const double length = inset.scale_bar_px, tick = 0.4 * size;
  const double x = pad, y = inset.rect.height - pad - tick;
  const double label = text_width(cr, inset.scale_label);
  ground(cr, x - 0.3 * size, y - 1.4 * size, std::max(length, label) + 0.6 * size,
         1.6 * size + tick);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.12);
  cairo_set_line_width(cr, 2);
  cairo_move_to(cr, x, y);
  cairo_line_to(cr, x + length, y);
  cairo_move_to(cr, x + 1, y - tick);
  cairo_line_to(cr, x + 1, y + tick);
  cairo_move_to(cr, x + length - 1, y - tick);
  cairo_line_to(cr, x + length - 1, y + tick);
  cairo_stroke(cr);
  text_at(cr, x + 0.5 * (length - label), y - 0.45 * size, inset.scale_label);
}

}  // namespace

std::vector<std::string> overlay_lines(const std::string& title, const Model& model,
                                       const PlaybackState& state, double landed_window) {
  std::vector<std::string> lines{title, "t = " + fixed(state.t, 3) + " s"};
  if (state.energy_in) lines.push_back("E_in = " + fixed(*state.energy_in, 3) + " J");
  if (!model.effects.contact) return lines;
  for (std::size_t k = 0; k < model.elbows.size() && k < state.elbows.size(); ++k) {
    const ElbowSample& e = state.elbows[k];
    std::string line = model.elbows[k].name + ": ";
    if (e.resting) line += fixed(e.fn, 2) + " N ";
    line += state_word(e, state.t, landed_window);
    if (!e.resting && e.distance)
      line += ", " + fixed(1e3 * std::max(*e.distance, 0.0), 1) + " mm above the table";
    lines.push_back(line);
  }
  // A link's own solid resting (not an elbow): named only while it rests.
  for (std::size_t j = 0; j < state.links.size(); ++j)
    if (state.links[j].resting)
      lines.push_back("link" + std::to_string(j) +
                      " (not an elbow): " + fixed(state.links[j].fn, 2) + " N resting");
  return lines;
}

int draw_overlay(RgbaView frame, const PixelRect& region, const std::vector<std::string>& lines,
                 int min_width) {
  const int width = frame.width, height = frame.height;
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
  composite(surface, frame, x0, y0);
  cairo_surface_destroy(surface);
  return used_width;
}

void InsetOverlayLayer::draw(RgbaView frame, const InsetOverlay& inset) {
  const PixelRect& r = inset.rect;
  if (r.width < 8 || r.height < 8) return;
  if (!drawn_ || !same_marks(*drawn_, inset)) redraw(inset);
  for (const Run& run : runs_) {
    const int y = r.y + run.y;
    if (y < 0 || y >= frame.height) continue;
    const std::uint32_t* src = layer_.data() + std::size_t(run.y) * std::size_t(r.width);
    for (int x = std::max(run.x, -r.x); x < run.x + run.length && r.x + x < frame.width; ++x)
      blend_over(frame.pixel(r.x + x, y), src[x]);  // a run holds no transparent word
  }
}

void InsetOverlayLayer::redraw(const InsetOverlay& inset) {
  const PixelRect& r = inset.rect;
  const double size = std::max(6.0, r.height / 18.0), pad = std::ceil(0.5 * size);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, r.width, r.height);
  cairo_t* cr = text_context(surface, size);
  const double title = text_width(cr, inset.title);
  ground(cr, pad - 0.3 * size, pad - 0.2 * size, title + 0.6 * size, 1.5 * size);
  text_at(cr, pad, pad + size, inset.title);
  legend(cr, inset, size, pad);
  if (inset.scale_bar_px > 0) scale_bar(cr, inset, size, pad);
  cairo_set_source_rgb(cr, 0.25, 0.26, 0.3);  // the frame, 2 px inside the edge
  cairo_set_line_width(cr, 2);
  cairo_rectangle(cr, 1, 1, r.width - 2, r.height - 2);
  cairo_stroke(cr);
  cairo_destroy(cr);
  cairo_surface_flush(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  layer_.resize(std::size_t(r.width) * std::size_t(r.height));
  runs_.clear();
  for (int y = 0; y < r.height; ++y) {
    std::uint32_t* row = layer_.data() + std::size_t(y) * std::size_t(r.width);
    std::memcpy(row, data + std::size_t(y) * std::size_t(stride), std::size_t(r.width) * 4);
    for (int x = 0; x < r.width;) {
      if (row[x] == 0) {
        ++x;
        continue;
      }
      const int start = x;
      while (x < r.width && row[x] != 0) ++x;
      runs_.push_back({y, start, x - start});
    }
  }
  cairo_surface_destroy(surface);
  drawn_ = inset;
}

}  // namespace elbowsim
