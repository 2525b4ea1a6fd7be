#include "report/plot/canvas.hpp"

#include <png.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace elbowsim::plot::canvas {

void set_color(cairo_t* cr, const Color& c, double alpha) {
  cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

void set_font(cairo_t* cr, double size, bool bold) {
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

double text_width(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

// Text with its baseline at y, aligned on x.
void draw_text(cairo_t* cr, double x, double y, const std::string& text, Align align,
               const Color& color) {
  const double w = text_width(cr, text);
  cairo_move_to(cr, align == Align::left ? x : align == Align::center ? x - w / 2 : x - w, y);
  set_color(cr, color);
  cairo_show_text(cr, text.c_str());
}

// Text turned a quarter left, centred on (x, y): the y-axis label.
void draw_vertical_text(cairo_t* cr, double x, double y, const std::string& text) {
  cairo_save(cr);
  cairo_translate(cr, x, y);
  cairo_rotate(cr, -M_PI / 2);
  draw_text(cr, 0, 0, text, Align::center);
  cairo_restore(cr);
}

// Dash patterns scale with the line width (1.6 px: 6 on, 4 off, ...).
void set_dash(cairo_t* cr, Dash dash, double width) {
  const double u = width / 1.6;
  const double dashed[] = {6 * u, 4 * u}, dotted[] = {1.5 * u, 3 * u},
               dash_dot[] = {7 * u, 3 * u, 1.5 * u, 3 * u};
  if (dash == Dash::dashed)
    cairo_set_dash(cr, dashed, 2, 0);
  else if (dash == Dash::dotted)
    cairo_set_dash(cr, dotted, 2, 0);
  else if (dash == Dash::dash_dot)
    cairo_set_dash(cr, dash_dot, 4, 0);
  else
    cairo_set_dash(cr, nullptr, 0, 0);
}

namespace {

// The surface's pixels (cairo's RGB24: one native-endian 0x00RRGGBB word
// each) as PNG rows. The UP filter and zlib level 3: plots are flat colour
// and thin lines, and this writes them 2.9 times as fast as cairo's own
// writer (all filters tried per row, level 6) for 11 % more bytes, measured
// on a run's 14 plots; writing them was two thirds of a report's time.
void write_rgb24(cairo_surface_t* surface, std::FILE* file, const std::filesystem::path& png) {
  const int width = cairo_image_surface_get_width(surface);
  const int height = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  std::vector<png_byte> row(std::size_t(width) * 3);
  // libpng's messages go nowhere (not to stderr): the exception says what failed.
  const auto quiet = [](png_structp p, png_const_charp) { png_longjmp(p, 1); };
  const auto no_warning = [](png_structp, png_const_charp) {};
  png_structp writer = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, quiet, no_warning);
  png_infop info = writer ? png_create_info_struct(writer) : nullptr;
  if (!info) {
    png_destroy_write_struct(&writer, nullptr);
    throw std::runtime_error(png.string() + ": cannot write PNG: libpng could not start");
  }
  // libpng reports errors by longjmp: nothing below owns anything to destroy.
  errno = 0;
  if (setjmp(png_jmpbuf(writer))) {
    const int error_number = errno;  // the failed write's reason, if it was one
    png_destroy_write_struct(&writer, &info);
    throw std::runtime_error(png.string() + ": cannot write PNG: " +
                             (error_number ? std::strerror(error_number) : "libpng failed"));
  }
  png_init_io(writer, file);
  png_set_filter(writer, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  png_set_compression_level(writer, 3);
  png_set_IHDR(writer, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  png_write_info(writer, info);
  for (int y = 0; y < height; ++y) {
    const unsigned char* line = data + std::size_t(y) * std::size_t(stride);
    for (int x = 0; x < width; ++x) {
      std::uint32_t pixel;
      std::memcpy(&pixel, line + 4 * std::size_t(x), 4);
      row[3 * std::size_t(x)] = png_byte(pixel >> 16);
      row[3 * std::size_t(x) + 1] = png_byte(pixel >> 8);
      row[3 * std::size_t(x) + 2] = png_byte(pixel);
    }
    png_write_row(writer, row.data());
  }
  png_write_end(writer, nullptr);
  png_destroy_write_struct(&writer, &info);
}

}  // namespace

void write_surface(cairo_surface_t* surface, const std::filesystem::path& png) {
  cairo_surface_flush(surface);
  if (cairo_image_surface_get_format(surface) != CAIRO_FORMAT_RGB24)
    throw std::logic_error("write_surface: an RGB24 image surface is expected");
  // Written under a temporary name and renamed: never a half-written PNG.
  const std::filesystem::path partial = png.string() + ".tmp";
  std::FILE* file = std::fopen(partial.c_str(), "wb");
  if (!file) throw std::runtime_error(png.string() + ": cannot write PNG: " + std::strerror(errno));
  std::error_code ignored;
  try {
    write_rgb24(surface, file, png);
  } catch (...) {
    std::fclose(file);
    std::filesystem::remove(partial, ignored);
    throw;
  }
  // The first failure's reason: the flush's, else the close's.
  const bool flushed = std::fflush(file) == 0 && !std::ferror(file);
  int error_number = errno;
  const bool closed = std::fclose(file) == 0;
  if (flushed && !closed) error_number = errno;
  if (!flushed || !closed) {
    std::filesystem::remove(partial, ignored);
    throw std::runtime_error(png.string() + ": cannot write PNG: " + std::strerror(error_number));
  }
  std::error_code error;
  std::filesystem::rename(partial, png, error);
  if (error) {
    std::filesystem::remove(partial, ignored);
    throw std::runtime_error(png.string() + ": " + error.message());
  }
}

std::string axis_title(const Axis& axis) {
  return axis.unit.empty() ? axis.label : axis.label + " [" + axis.unit + "]";
}

// ---- legend ---------------------------------------------------------------

double entry_width(cairo_t* cr, const LegendEntry& e) {
  return kSample + 6 + text_width(cr, e.label) + 18;
}

// Entries flow left to right and wrap; returns the height used.
double legend(cairo_t* cr, const std::vector<LegendEntry>& entries, double left, double right,
              double top, bool draw) {
  if (entries.empty()) return 0;
  set_font(cr, 12);
  double x = left, y = top;
  for (const LegendEntry& e : entries) {
    const double w = entry_width(cr, e);
    if (x > left && x + w > right) x = left, y += kLegendRow;
    if (draw) {
      const double mid = y + kLegendRow / 2;
      set_color(cr, e.color);
      if (e.bar) {
        cairo_rectangle(cr, x + 8, mid - 5, 10, 10);
        cairo_fill(cr);
      } else {
        cairo_set_line_width(cr, 2.2);
        set_dash(cr, e.dash, 2.2);
        cairo_move_to(cr, x, mid);
        cairo_line_to(cr, x + kSample, mid);
        cairo_stroke(cr);
        set_dash(cr, Dash::solid, 1);
        if (e.markers) cairo_arc(cr, x + kSample / 2, mid, 3.2, 0, 2 * M_PI), cairo_fill(cr);
      }
      draw_text(cr, x + kSample + 6, mid + 4.5, e.label, Align::left);
    }
    x += w;
  }
  return y + kLegendRow - top;
}

// Title and legend: returns the y where the plot area may start.
double header(cairo_t* cr, const std::string& title, const std::vector<LegendEntry>& entries,
              int width, bool draw) {
  set_font(cr, 17, true);
  if (draw) draw_text(cr, width / 2.0, kPad + 15, title, Align::center);
  const double top = kPad + 26;
  return top + legend(cr, entries, kPad + 40, width - kPad, top, draw) + 8;
}

// ---- axes -----------------------------------------------------------------

bool drawable(double v, Scale scale) {
  return std::isfinite(v) && (scale == Scale::linear || v > 0);
}

// Linear axes: 4 % of the data range on each free side, so that a line at its
// extreme does not run along the frame; a side at or beyond zero does not
// cross it. (Log axes snap to whole decades instead.)
Range padded(Range r, const Axis& axis) {
  if (axis.tight || axis.scale == Scale::log || r.empty() || !(r.hi > r.lo)) return r;
  const double pad = 0.04 * (r.hi - r.lo);
  Range out = r;
  if (!axis.min) out.lo = r.lo >= 0 ? std::max(0.0, r.lo - pad) : r.lo - pad;
  if (!axis.max) out.hi = r.hi <= 0 ? std::min(0.0, r.hi + pad) : r.hi + pad;
  return out;
}

// The limits an axis shows for data in `data` (fixed limits win).
Ticks axis_ticks(const Axis& axis, Range data, int target) {
  if (axis.min) data.lo = *axis.min;
  if (axis.max) data.hi = *axis.max;
  if (axis.include_zero && axis.scale == Scale::linear) data.add(0);
  data = padded(data, axis);
  if (axis.scale == Scale::log) return log_ticks(data.lo, data.hi);
  const bool fixed = axis.min && axis.max;
  return linear_ticks(data.lo, data.hi, target, !(axis.tight || fixed));
}

double widest(cairo_t* cr, const std::vector<std::string>& labels) {
  double w = 0;
  for (const std::string& s : labels) w = std::max(w, text_width(cr, s));
  return w;
}

// Grid lines, frame, tick marks and labels, axis titles.
void draw_axes(cairo_t* cr, const Box& area, const Mapping& x, const Mapping* y, const Axis& xa,
               const Axis& ya, double x_labels_top, int height) {
  cairo_set_line_width(cr, 1);
  const auto vline = [&](double v, double shade) {
    const double px = std::round(x(v)) + 0.5;
    cairo_set_source_rgb(cr, shade, shade, shade);
    cairo_move_to(cr, px, area.top), cairo_line_to(cr, px, area.bottom), cairo_stroke(cr);
  };
  const auto hline = [&](double v, double shade) {
    const double py = std::round((*y)(v)) + 0.5;
    cairo_set_source_rgb(cr, shade, shade, shade);
    cairo_move_to(cr, area.left, py), cairo_line_to(cr, area.right, py), cairo_stroke(cr);
  };
  for (double v : x.ticks.minor) vline(v, 0.95);
  for (double v : x.ticks.major) vline(v, 0.87);
  if (y) {
    for (double v : y->ticks.minor) hline(v, 0.95);
    for (double v : y->ticks.major) hline(v, 0.87);
  }
  set_color(cr, kFrame);
  cairo_rectangle(cr, area.left + 0.5, area.top + 0.5, area.width() - 1, area.height() - 1);
  cairo_stroke(cr);
  set_font(cr, 12);
  for (std::size_t k = 0; k < x.ticks.major.size(); ++k) {
    const double px = std::round(x(x.ticks.major[k])) + 0.5;
    set_color(cr, kFrame);
    cairo_move_to(cr, px, area.bottom), cairo_line_to(cr, px, area.bottom + 4), cairo_stroke(cr);
    draw_text(cr, px, x_labels_top + 13, x.ticks.labels[k], Align::center);
  }
  if (y) {
    for (std::size_t k = 0; k < y->ticks.major.size(); ++k) {
      const double py = std::round((*y)(y->ticks.major[k])) + 0.5;
      set_color(cr, kFrame);
      cairo_move_to(cr, area.left - 4, py), cairo_line_to(cr, area.left, py), cairo_stroke(cr);
      draw_text(cr, area.left - 7, py + 4.5, y->ticks.labels[k], Align::right);
    }
  }
  set_font(cr, 13);
  draw_text(cr, (area.left + area.right) / 2, height - kPad, axis_title(xa), Align::center);
  draw_vertical_text(cr, kPad + 11, (area.top + area.bottom) / 2, axis_title(ya));
}

void draw_message(cairo_t* cr, const Box& area, const std::string& message) {
  set_color(cr, kFrame);
  cairo_set_line_width(cr, 1);
  cairo_rectangle(cr, area.left + 0.5, area.top + 0.5, area.width() - 1, area.height() - 1);
  cairo_stroke(cr);
  set_font(cr, 16);
  draw_text(cr, (area.left + area.right) / 2, (area.top + area.bottom) / 2, message, Align::center,
            {0.45, 0.45, 0.45});
}

}  // namespace elbowsim::plot::canvas
