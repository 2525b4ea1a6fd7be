// Plots drawn with cairo and written as PNG: line plots (linear or log axes,
// NaN gaps, optional timeline lanes under the x axis, equal aspect for paths),
// grouped bar charts, waterfalls (waterfall.cpp) and work-precision diagrams.
// A figure is plain data; write_png draws it. Cairo is included in
// report/plot/ only (canvas.hpp: the primitives the figures share).
//
// PNGs are written by cairo's own writer (cairo_surface_write_to_png, itself
// libpng) so that the report does not depend on the renderer's png_writer.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace elbowsim::plot {

struct Color {
  double r = 0, g = 0, b = 0;  // [0, 1]
};

// The i-th colour of a 10-colour qualitative palette (Tableau 10), cycling.
Color palette(int i);

enum class Scale { linear, log };
enum class Dash { solid, dashed, dotted, dash_dot };

struct Axis {
  std::string label;  // "time"
  std::string unit;   // "s": drawn as "time [s]"; empty: no brackets
  Scale scale = Scale::linear;
  std::optional<double> min, max;  // fixed limits; default: from the data
  bool tight = false;              // limits at the data (time axes); else out to round ticks
  bool include_zero = false;       // linear: the range reaches 0 (bar charts, magnitudes)
};

Axis linear_axis(std::string label, std::string unit);
Axis log_axis(std::string label, std::string unit);
Axis time_axis();  // "time [s]", tight

// One line. Points with a non-finite x or y (or y <= 0 on a log axis) are not
// drawn and break the line there.
struct Series {
  std::string label;  // legend entry; empty: not in the legend
  std::vector<double> x, y;
  std::optional<Color> color;  // default: palette(index of the series)
  Dash dash = Dash::solid;
  double width = 1.6;    // [px]
  bool markers = false;  // a dot at every point
};

// A timeline strip under the plot: where a state (an elbow resting) holds.
struct Interval {
  double begin = 0, end = 0;  // x units
};
struct Lane {
  std::string label;
  std::vector<Interval> on;
  std::optional<Color> color;  // default: palette(lane index)
};

struct LinePlot {
  std::string title;
  Axis x = time_axis();
  Axis y;
  std::vector<Series> series;
  std::vector<Lane> lanes;  // drawn between the plot and the x tick labels
  // Shown in the plot area when no series has a drawable point.
  std::string empty_message = "no data";
  int width = 900, height = 480;  // [px]
  // Both axes linear and at the same scale (m per pixel), for a path in a
  // plane: the limits widen around the data until they are.
  bool equal_aspect = false;
};

// Bars grouped by category: each group is one legend entry with one value per
// category (e.g. categories = runs, groups = "E_in", "Joule").
struct BarGroup {
  std::string label;
  std::vector<double> values;  // [categories]; non-finite: no bar
};
struct BarChart {
  std::string title;
  std::vector<std::string> categories;
  std::vector<BarGroup> groups;
  Axis y;  // linear, always reaching 0
  std::string empty_message = "no data";
  int value_digits = 4;  // significant digits of the value printed over each bar
  int width = 900, height = 480;
};

// An account drawn as a horizontal waterfall (energy in, then out): each step
// a bar from the running total to the running total + value, its value
// printed beside it; a total step is a bar from 0 to the running total.
struct WaterfallStep {
  std::string label;
  double value = 0;            // added (> 0) or taken (< 0); ignored for a total
  std::optional<Color> color;  // default: green for added, red for taken, grey for a total
  bool total = false;
  std::string note;  // printed after the value ("(47 %)")
  std::string text;  // printed instead of the value when not empty ("54.2 mJ")
};
struct Waterfall {
  std::string title;
  Axis x;  // the account's quantity and unit ("energy", "J"); linear
  std::vector<WaterfallStep> steps;
  std::string empty_message = "no data";
  int width = 900;
  int height = 0;  // [px]; 0: waterfall_height(steps)
};

// The height a waterfall of `steps` rows is drawn at.
int waterfall_height(std::size_t steps);

// A tornado chart (tornado.cpp): what each factor alone does to one value.
// One row per factor, in the order given (the caller's ranking), two bars
// from the centre (the value with every factor at its usual spread): to the
// value with the factor at its low end, and at its high end, each in its
// colour; a line at the centre, a dashed line at the reference (1, where a
// ratio's verdict flips).
struct TornadoRow {
  std::string label;
  double low = 0, high = 0;  // the value at each end; non-finite: no bar
  std::string low_text, high_text;  // printed beyond each bar's end ("−10 %: 0.64")
};
struct Tornado {
  std::string title;
  Axis x;  // linear
  double centre = 1;
  std::optional<double> reference;
  std::string centre_label = "centre", reference_label = "reference";
  std::string low_label = "low end", high_label = "high end";  // the legend
  std::vector<TornadoRow> rows;
  std::string empty_message = "no data";
  int width = 900;
};
// The height a tornado of `rows` rows is drawn at.
int tornado_height(std::size_t rows);

// Work-precision: one method's error against CPU time, one point per setting
// (step size, tolerance), in the order given.
struct MethodResult {
  std::string method;
  std::vector<double> cpu_seconds;  // [s] > 0
  std::vector<double> error;        // > 0, in error_unit
};

// A log-log line plot of error against CPU time, one marked line per method.
LinePlot work_precision_plot(const std::vector<MethodResult>& methods, const std::string& title,
                             const std::string& error_label, const std::string& error_unit);

// A decoded PNG, for checks: pixels row-major as 0xRRGGBB (alpha dropped).
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint32_t> rgb;  // [height x width]
  std::uint32_t at(int x, int y) const { return rgb[static_cast<std::size_t>(y) * width + x]; }
};

// Reads a PNG file. Throws std::runtime_error naming the file when it does
// not decode.
Image read_png(const std::filesystem::path& png);

// Draw the figure and write it to `png`. Throws std::runtime_error naming the
// file when it cannot be written.
void write_png(const LinePlot& plot, const std::filesystem::path& png);
void write_png(const BarChart& chart, const std::filesystem::path& png);
void write_png(const Waterfall& chart, const std::filesystem::path& png);
void write_png(const Tornado& chart, const std::filesystem::path& png);

}  // namespace elbowsim::plot
