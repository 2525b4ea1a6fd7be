#include "report/plot/plot.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "engine/recording/number_text.hpp"
#include "report/plot/canvas.hpp"

namespace elbowsim::plot {

using namespace canvas;

namespace {

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

// Room for the y tick labels and lane labels: where the plot area starts.
double left_margin(cairo_t* cr, const LinePlot& plot, const Ticks& yt) {
  set_font(cr, 12);
  double label_room = widest(cr, yt.labels);
  set_font(cr, 11);
  for (const Lane& lane : plot.lanes) label_room = std::max(label_room, text_width(cr, lane.label));
  return kPad + 22 + label_room + 8;
}

// Fixed limits on both axes, around the data's centre, at one scale (data
// units per pixel) that shows all of it with 6 % to spare.
void equal_scale(const Range& xr, const Range& yr, const Box& area, Axis& xa, Axis& ya) {
  const double span_x = std::max(xr.hi - xr.lo, 1e-12), span_y = std::max(yr.hi - yr.lo, 1e-12);
  const double per_pixel = 1.06 * std::max(span_x / area.width(), span_y / area.height());
  const double cx = (xr.lo + xr.hi) / 2, cy = (yr.lo + yr.hi) / 2;
  xa.min = cx - per_pixel * area.width() / 2, xa.max = cx + per_pixel * area.width() / 2;
  ya.min = cy - per_pixel * area.height() / 2, ya.max = cy + per_pixel * area.height() / 2;
  xa.tight = ya.tight = true;
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
  Axis xa = plot.x, ya = plot.y;
  Ticks yt = axis_ticks(ya, yr, std::max(2, static_cast<int>(area.height() / 55)));
  area.left = left_margin(cr, plot, yt);
  if (plot.equal_aspect) {
    // Twice: the first pass's y labels set the margin the second pass fills.
    for (int pass = 0; pass < 2; ++pass) {
      equal_scale(xr, yr, area, xa, ya);
      yt = axis_ticks(ya, yr, std::max(2, static_cast<int>(area.height() / 55)));
      area.left = left_margin(cr, plot, yt);
    }
    equal_scale(xr, yr, area, xa, ya);
  }
  const Ticks xt = axis_ticks(xa, xr, std::max(2, static_cast<int>(area.width() / 100)));
  const Mapping x{xt, xa.scale, area.left, area.right};
  const Mapping y{yt, ya.scale, area.bottom, area.top};
  draw_axes(cr, area, x, &y, xa, ya, x_labels_top, plot.height);
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

// One bar per group in each category's slot, its value printed above (below,
// if negative); "n/a" where a value is missing.
void draw_bars(cairo_t* cr, const BarChart& chart, const Box& area, const Mapping& y) {
  const double slot = area.width() / chart.categories.size();
  const double bar = slot * 0.7 / chart.groups.size();
  // The values' font shrinks (to 7 at the least) until the widest fits its bar:
  // three or more groups otherwise print their values into one another.
  set_font(cr, 11);
  double widest = 0;
  for (const BarGroup& g : chart.groups)
    for (double v : g.values)
      if (std::isfinite(v)) widest = std::max(widest, text_width(cr, significant(v, chart.value_digits)));
  if (widest > bar - 2) set_font(cr, std::max(7.0, 11 * (bar - 2) / widest));
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
      draw_text(cr, left + bar / 2, values[c] >= 0 ? y1 - 4 : y1 + 13,
                significant(values[c], chart.value_digits), Align::center);
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
