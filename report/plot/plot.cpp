#include "report/plot/plot.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>

#include "report/plot/ticks.hpp"

namespace elbowsim::plot {

namespace {

constexpr const char* kFont = "DejaVu Sans";
constexpr double kPad = 14;         // [px] outer margin
constexpr double kLaneHeight = 12;  // [px] one timeline strip
constexpr double kLaneGap = 6;      // [px] between strips
const Color kText{0.1, 0.1, 0.1}, kFrame{0.35, 0.35, 0.35};

// ---- drawing primitives ---------------------------------------------------

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

void set_color(cairo_t* cr, const Color& c, double alpha = 1) {
  cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

void set_font(cairo_t* cr, double size, bool bold = false) {
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
               const Color& color = kText) {
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

void write_surface(cairo_surface_t* surface, const std::filesystem::path& png) {
  cairo_surface_flush(surface);
  // Written under a temporary name and renamed: never a half-written PNG.
  const std::filesystem::path partial = png.string() + ".tmp";
  const cairo_status_t status = cairo_surface_write_to_png(surface, partial.c_str());
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(png.string() +
                             ": cannot write PNG: " + cairo_status_to_string(status));
  std::error_code error;
  std::filesystem::rename(partial, png, error);
  if (error) throw std::runtime_error(png.string() + ": " + error.message());
}

std::string axis_title(const Axis& axis) {
  return axis.unit.empty() ? axis.label : axis.label + " [" + axis.unit + "]";
}

// ---- legend ---------------------------------------------------------------

struct LegendEntry {
  std::string label;
  Color color;
  Dash dash = Dash::solid;
  bool markers = false;
  bool bar = false;  // a filled square instead of a line sample
};

constexpr double kLegendRow = 18, kSample = 26;

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

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
  bool empty() const { return lo > hi; }
};

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

// ---- line plots -----------------------------------------------------------

Color series_color(const Series& s, int index) { return s.color.value_or(palette(index)); }

// Strokes one series: a line through each run of drawable points; a run of a
// single point (between gaps) shows as a dot.
void draw_series(cairo_t* cr, const Series& s, Color color, const Mapping& x, const Mapping& y) {
  set_color(cr, color);
  cairo_set_line_width(cr, s.width);
  set_dash(cr, s.dash, s.width);
  const std::size_t n = std::min(s.x.size(), s.y.size());
  const auto ok = [&](std::size_t k) {
    return k < n && drawable(s.x[k], x.scale) && drawable(s.y[k], y.scale);
  };
  std::vector<std::size_t> dots;
  for (std::size_t k = 0; k < n; ++k) {
    if (!ok(k)) continue;
    const bool first = k == 0 || !ok(k - 1);
    if (first && !ok(k + 1)) dots.push_back(k);
    (first ? cairo_move_to : cairo_line_to)(cr, x(s.x[k]), y(s.y[k]));
  }
  cairo_stroke(cr);
  set_dash(cr, Dash::solid, 1);
  if (s.markers) {
    dots.clear();
    for (std::size_t k = 0; k < n; ++k)
      if (ok(k)) dots.push_back(k);
  }
  const double radius = s.markers ? 3.2 : s.width;
  for (std::size_t k : dots) {
    cairo_new_sub_path(cr);
    cairo_arc(cr, x(s.x[k]), y(s.y[k]), radius, 0, 2 * M_PI);
  }
  cairo_fill(cr);
}

void draw_lanes(cairo_t* cr, const LinePlot& plot, const Box& area, const Mapping& x) {
  set_font(cr, 11);
  for (std::size_t k = 0; k < plot.lanes.size(); ++k) {
    const Lane& lane = plot.lanes[k];
    const double top = area.bottom + kLaneGap + k * (kLaneHeight + kLaneGap);
    cairo_set_source_rgb(cr, 0.94, 0.94, 0.94);
    cairo_rectangle(cr, area.left, top, area.width(), kLaneHeight);
    cairo_fill(cr);
    set_color(cr, lane.color.value_or(palette(static_cast<int>(k))));
    for (const Interval& i : lane.on) {
      const double a = std::clamp(x(i.begin), area.left, area.right);
      const double b = std::clamp(x(i.end), area.left, area.right);
      cairo_rectangle(cr, a, top, std::max(b - a, 1.0), kLaneHeight);
    }
    cairo_fill(cr);
    draw_text(cr, area.left - 7, top + kLaneHeight - 2, lane.label, Align::right);
  }
}

std::vector<LegendEntry> legend_entries(const LinePlot& plot) {
  std::vector<LegendEntry> entries;
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const Series& s = plot.series[k];
    if (!s.label.empty())
      entries.push_back({s.label, series_color(s, static_cast<int>(k)), s.dash, s.markers});
  }
  return entries;
}

// y: the drawable points; x: every x with a finite y, so that the plots of one
// run share their time span even where a log axis cannot show y (y = 0).
// Returns false when nothing is drawable.
bool data_ranges(const LinePlot& plot, Range& xr, Range& yr) {
  for (const Series& s : plot.series)
    for (std::size_t k = 0; k < std::min(s.x.size(), s.y.size()); ++k) {
      if (drawable(s.x[k], plot.x.scale) && std::isfinite(s.y[k])) xr.add(s.x[k]);
      if (drawable(s.x[k], plot.x.scale) && drawable(s.y[k], plot.y.scale)) yr.add(s.y[k]);
    }
  return !yr.empty();
}

}  // namespace

Axis linear_axis(std::string label, std::string unit) {
  Axis axis;
  axis.label = std::move(label);
  axis.unit = std::move(unit);
  return axis;
}

Axis log_axis(std::string label, std::string unit) {
  Axis axis = linear_axis(std::move(label), std::move(unit));
  axis.scale = Scale::log;
  return axis;
}

Axis time_axis() {
  Axis axis = linear_axis("time", "s");
  axis.tight = true;
  return axis;
}

Color palette(int i) {
  static const Color colors[] = {
      {0.306, 0.475, 0.655}, {0.949, 0.557, 0.169}, {0.882, 0.341, 0.349}, {0.463, 0.718, 0.698},
      {0.349, 0.631, 0.310}, {0.929, 0.788, 0.282}, {0.690, 0.478, 0.631}, {1.000, 0.616, 0.655},
      {0.612, 0.459, 0.373}, {0.729, 0.690, 0.675}};
  return colors[((i % 10) + 10) % 10];
}

void write_png(const LinePlot& plot, const std::filesystem::path& png) {
  Canvas canvas(plot.width, plot.height);
  cairo_t* cr = canvas.cr;
  const auto entries = legend_entries(plot);
  const double top = header(cr, plot.title, entries, plot.width, true);
  const double lanes = plot.lanes.size() * (kLaneHeight + kLaneGap);
  const double x_labels_top = plot.height - kPad - 18 - 18;
  Box area{kPad + 30, top, plot.width - kPad - 22.0, x_labels_top - lanes - 4};
  Range xr, yr;
  if (!data_ranges(plot, xr, yr)) {
    area.left = kPad + 60;
    draw_message(cr, area, plot.empty_message);
    set_font(cr, 13);
    draw_text(cr, (area.left + area.right) / 2, plot.height - kPad, axis_title(plot.x),
              Align::center);
    draw_vertical_text(cr, kPad + 11, (area.top + area.bottom) / 2, axis_title(plot.y));
    return write_surface(canvas.surface, png);
  }
  // The y ticks fix the left margin (their labels' width), then x gets the rest.
  const Ticks yt = axis_ticks(plot.y, yr, std::max(2, static_cast<int>(area.height() / 55)));
  set_font(cr, 12);
  double label_room = widest(cr, yt.labels);
  set_font(cr, 11);
  for (const Lane& lane : plot.lanes) label_room = std::max(label_room, text_width(cr, lane.label));
  area.left = kPad + 22 + label_room + 8;
  const Ticks xt = axis_ticks(plot.x, xr, std::max(2, static_cast<int>(area.width() / 100)));
  const Mapping x{xt, plot.x.scale, area.left, area.right};
  const Mapping y{yt, plot.y.scale, area.bottom, area.top};
  draw_axes(cr, area, x, &y, plot.x, plot.y, x_labels_top, plot.height);
  // Clipped a marker's radius outside the frame: points on the limits stay whole.
  cairo_save(cr);
  cairo_rectangle(cr, area.left - 4, area.top - 4, area.width() + 8, area.height() + 8);
  cairo_clip(cr);
  for (std::size_t k = 0; k < plot.series.size(); ++k)
    draw_series(cr, plot.series[k], series_color(plot.series[k], static_cast<int>(k)), x, y);
  cairo_restore(cr);
  draw_lanes(cr, plot, area, x);
  write_surface(canvas.surface, png);
}

namespace {

Range bar_range(const BarChart& chart) {
  Range r;
  for (const BarGroup& g : chart.groups)
    for (std::size_t c = 0; c < std::min(g.values.size(), chart.categories.size()); ++c)
      if (std::isfinite(g.values[c])) r.add(g.values[c]);
  return r;
}

std::string value_label(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

// One bar per group in each category's slot, its value printed above (below,
// if negative); "n/a" where a value is missing.
void draw_bars(cairo_t* cr, const BarChart& chart, const Box& area, const Mapping& y) {
  const double slot = area.width() / chart.categories.size();
  const double bar = slot * 0.7 / chart.groups.size();
  set_font(cr, 11);
  for (std::size_t c = 0; c < chart.categories.size(); ++c) {
    for (std::size_t g = 0; g < chart.groups.size(); ++g) {
      const auto& values = chart.groups[g].values;
      const double left = area.left + c * slot + slot * 0.15 + g * bar;
      if (c >= values.size() || !std::isfinite(values[c])) {
        draw_text(cr, left + bar / 2, y(0.0) - 4, "n/a", Align::center, {0.45, 0.45, 0.45});
        continue;
      }
      const double y0 = y(0.0), y1 = y(values[c]);
      set_color(cr, palette(static_cast<int>(g)));
      cairo_rectangle(cr, left + 1, std::min(y0, y1), bar - 2, std::max(std::abs(y1 - y0), 1.0));
      cairo_fill(cr);
      draw_text(cr, left + bar / 2, values[c] >= 0 ? y1 - 4 : y1 + 13, value_label(values[c]),
                Align::center);
    }
  }
}

}  // namespace

void write_png(const BarChart& chart, const std::filesystem::path& png) {
  Canvas canvas(chart.width, chart.height);
  cairo_t* cr = canvas.cr;
  std::vector<LegendEntry> entries;
  for (std::size_t g = 0; g < chart.groups.size(); ++g)
    entries.push_back(
        {chart.groups[g].label, palette(static_cast<int>(g)), Dash::solid, false, true});
  const double top = header(cr, chart.title, entries, chart.width, true) + 12;
  const double x_labels_top = chart.height - kPad - 18 - 18;
  Box area{kPad + 60, top, chart.width - kPad - 10.0, x_labels_top - 4};
  const Range r = bar_range(chart);
  if (chart.categories.empty() || chart.groups.empty() || r.empty()) {
    draw_message(cr, area, chart.empty_message);
    return write_surface(canvas.surface, png);
  }
  Axis ya = chart.y;
  ya.include_zero = true;
  ya.scale = Scale::linear;
  const Ticks yt = axis_ticks(ya, r, std::max(2, static_cast<int>(area.height() / 55)));
  set_font(cr, 12);
  area.left = kPad + 22 + widest(cr, yt.labels) + 8;
  const Mapping y{yt, Scale::linear, area.bottom, area.top};
  // The x "axis" is the categories: one slot each, its name centred under it.
  Ticks xt;
  xt.lo = 0, xt.hi = static_cast<double>(chart.categories.size());
  const Mapping x{xt, Scale::linear, area.left, area.right};
  draw_axes(cr, area, x, &y, linear_axis("", ""), ya, x_labels_top, chart.height);
  set_font(cr, 12);
  for (std::size_t c = 0; c < chart.categories.size(); ++c)
    draw_text(cr, x(c + 0.5), x_labels_top + 13, chart.categories[c], Align::center);
  draw_bars(cr, chart, area, y);
  write_surface(canvas.surface, png);
}

Image read_png(const std::filesystem::path& png) {
  cairo_surface_t* surface = cairo_image_surface_create_from_png(png.c_str());
  const cairo_status_t status = cairo_surface_status(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface);
    throw std::runtime_error(png.string() +
                             ": cannot decode PNG: " + cairo_status_to_string(status));
  }
  cairo_surface_flush(surface);
  Image image;
  image.width = cairo_image_surface_get_width(surface);
  image.height = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  // RGB24 and ARGB32 both keep a native-endian 32-bit word per pixel.
  for (int y = 0; y < image.height; ++y) {
    const auto* row =
        reinterpret_cast<const std::uint32_t*>(data + static_cast<std::size_t>(y) * stride);
    for (int x = 0; x < image.width; ++x) image.rgb.push_back(row[x] & 0xFFFFFFu);
  }
  cairo_surface_destroy(surface);
  return image;
}

LinePlot work_precision_plot(const std::vector<MethodResult>& methods, const std::string& title,
                             const std::string& error_label, const std::string& error_unit) {
  LinePlot plot;
  plot.title = title;
  plot.x = log_axis("CPU time", "s");
  plot.y = log_axis(error_label, error_unit);
  plot.empty_message = "no data: no method has a positive time and error";
  for (const MethodResult& m : methods) {
    Series s;
    s.label = m.method;
    s.x = m.cpu_seconds;
    s.y = m.error;
    s.width = 1.8;
    s.markers = true;
    plot.series.push_back(std::move(s));
  }
  return plot;
}

}  // namespace elbowsim::plot
