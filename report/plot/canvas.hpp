// The drawing primitives the figures share (text, legend, axes, PNG
// writing), on a cairo surface. Included by the figure files of report/plot/
// only: cairo stays inside this folder.
#pragma once

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "report/plot/plot.hpp"
#include "report/plot/ticks.hpp"

namespace elbowsim::plot::canvas {

constexpr const char* kFont = "DejaVu Sans";
constexpr double kPad = 14;         // [px] outer margin
constexpr double kLaneHeight = 12;  // [px] one timeline strip
constexpr double kLaneGap = 6;      // [px] between strips
inline const Color kText{0.1, 0.1, 0.1}, kFrame{0.35, 0.35, 0.35};

struct Canvas {
  Canvas(int width, int height)
      : surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height)),
        cr(cairo_create(surface)) {
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  }
  ~Canvas() {
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
  }
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;
  cairo_surface_t* surface;
  cairo_t* cr;
};

struct Box {
  double left, top, right, bottom;
  double width() const { return right - left; }
  double height() const { return bottom - top; }
};

enum class Align { left, center, right };

struct LegendEntry {
  std::string label;
  Color color;
  Dash dash = Dash::solid;
  bool markers = false;
  bool bar = false;  // a filled square instead of a line sample
};

constexpr double kLegendRow = 18, kSample = 26;

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
  bool empty() const { return lo > hi; }
};

// Data value -> pixel along one axis.
struct Mapping {
  Ticks ticks;
  Scale scale;
  double from, to;  // pixels of ticks.lo and ticks.hi
  double operator()(double v) const {
    const auto f = [this](double u) { return scale == Scale::log ? std::log10(u) : u; };
    return from + (f(v) - f(ticks.lo)) / (f(ticks.hi) - f(ticks.lo)) * (to - from);
  }
};

void set_color(cairo_t* cr, const Color& c, double alpha = 1);

void set_font(cairo_t* cr, double size, bool bold = false);

double text_width(cairo_t* cr, const std::string& text);

// Text with its baseline at y, aligned on x.
void draw_text(cairo_t* cr, double x, double y, const std::string& text, Align align,
               const Color& color = kText);

// Text turned a quarter left, centred on (x, y): the y-axis label.
void draw_vertical_text(cairo_t* cr, double x, double y, const std::string& text);

// Dash patterns scale with the line width (1.6 px: 6 on, 4 off, ...).
void set_dash(cairo_t* cr, Dash dash, double width);

void write_surface(cairo_surface_t* surface, const std::filesystem::path& png);

std::string axis_title(const Axis& axis);

double entry_width(cairo_t* cr, const LegendEntry& e);

// Entries flow left to right and wrap; returns the height used.
double legend(cairo_t* cr, const std::vector<LegendEntry>& entries, double left, double right,
              double top, bool draw);

// Title and legend: returns the y where the plot area may start.
double header(cairo_t* cr, const std::string& title, const std::vector<LegendEntry>& entries,
              int width, bool draw);

bool drawable(double v, Scale scale);

// Linear axes: 4 % of the data range on each free side, so that a line at its
// extreme does not run along the frame; a side at or beyond zero does not
// cross it. (Log axes snap to whole decades instead.)
Range padded(Range r, const Axis& axis);

// The limits an axis shows for data in `data` (fixed limits win).
Ticks axis_ticks(const Axis& axis, Range data, int target);

double widest(cairo_t* cr, const std::vector<std::string>& labels);

// Grid lines, frame, tick marks and labels, axis titles.
void draw_axes(cairo_t* cr, const Box& area, const Mapping& x, const Mapping* y, const Axis& xa,
               const Axis& ya, double x_labels_top, int height);

void draw_message(cairo_t* cr, const Box& area, const std::string& message);

}  // namespace elbowsim::plot::canvas
