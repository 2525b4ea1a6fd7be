// A tornado chart (plot.hpp, Tornado): per row two bars from the centre value,
// one to the value at the factor's low end and one to its high end, each with
// its text beyond the bar's end; the centre as a solid line, the reference
// (where a verdict flips) dashed.
#include <algorithm>

#include "report/plot/canvas.hpp"

namespace elbowsim::plot {

using namespace canvas;

namespace {

constexpr double kRow = 34, kBar = 22;     // [px] row pitch, bar thickness
constexpr double kBottom = 58;             // [px] the x axis below
const Color kLow{0.122, 0.467, 0.706}, kHigh{0.937, 0.541, 0.180};  // blue, orange
const Color kReference{0.80, 0.10, 0.10};

struct Bar {
  double value;
  const std::string& text;
  const Color& color;
};

// One end's bar from the centre, with its text beyond the end (inside the
// area: on the far side of the bar when it would leave it).
void draw_bar(cairo_t* cr, const Box& area, const Mapping& x, double centre, double top, const Bar& bar) {
  if (!std::isfinite(bar.value)) return;
  const double c = x(centre), v = std::clamp(x(bar.value), area.left, area.right);
  set_color(cr, bar.color);
  cairo_rectangle(cr, std::min(c, v), top, std::max(std::abs(v - c), 1.5), kBar / 2);
  cairo_fill(cr);
  if (bar.text.empty()) return;
  set_font(cr, 11);
  const double w = text_width(cr, bar.text), baseline = top + kBar / 2 - 2;
  const bool right = v >= c;
  if (right && v + 5 + w <= area.right) draw_text(cr, v + 5, baseline, bar.text, Align::left);
  else if (!right && v - 5 - w >= area.left) draw_text(cr, v - 5, baseline, bar.text, Align::right);
  else draw_text(cr, right ? c - 5 : c + 5, baseline, bar.text, right ? Align::right : Align::left);
}

void vertical(cairo_t* cr, const Box& area, const Mapping& x, double v, const Color& color, Dash dash) {
  const double px = std::round(x(v)) + 0.5;
  set_color(cr, color);
  cairo_set_line_width(cr, 1.6);
  set_dash(cr, dash, 1.6);
  cairo_move_to(cr, px, area.top - 4), cairo_line_to(cr, px, area.bottom), cairo_stroke(cr);
  set_dash(cr, Dash::solid, 1);
}

std::vector<LegendEntry> legend_of(const Tornado& chart) {
  std::vector<LegendEntry> entries{{chart.low_label, kLow, Dash::solid, false, true},
                                   {chart.high_label, kHigh, Dash::solid, false, true},
                                   {chart.centre_label, kFrame}};
  if (chart.reference) entries.push_back({chart.reference_label, kReference, Dash::dashed});
  return entries;
}

}  // namespace

int tornado_height(std::size_t rows) {
  return static_cast<int>(66 + kRow * std::max<std::size_t>(rows, 1) + kBottom);
}

void write_png(const Tornado& chart, const std::filesystem::path& png) {
  const int height = tornado_height(chart.rows.size());
  Canvas canvas(chart.width, height);
  cairo_t* cr = canvas.cr;
  const std::vector<LegendEntry> entries = legend_of(chart);
  const double top = header(cr, chart.title, entries, chart.width, true) + 6;
  set_font(cr, 13);
  std::vector<std::string> labels;
  for (const TornadoRow& r : chart.rows) labels.push_back(r.label);
  const double label_room = std::min(widest(cr, labels), 0.4 * chart.width);
  Box area{kPad + 4 + label_room + 14, top, chart.width - kPad - 10.0,
           top + kRow * std::max<std::size_t>(chart.rows.size(), 1)};
  Range r;
  r.add(chart.centre);
  if (chart.reference) r.add(*chart.reference);
  for (const TornadoRow& row : chart.rows)
    for (double v : {row.low, row.high})
      if (std::isfinite(v)) r.add(v);
  if (chart.rows.empty() || !std::isfinite(chart.centre)) {
    draw_message(cr, area, chart.empty_message);
    return write_surface(canvas.surface, png);
  }
  // Room at both sides for the texts beyond the bars' ends: the data take
  // the middle 60 % of the axis.
  const double span = std::max(r.hi - r.lo, 1e-3 * std::max(1.0, std::abs(r.hi)));
  Axis xa = chart.x;
  xa.scale = Scale::linear;
  xa.min = r.lo - 0.35 * span, xa.max = r.hi + 0.35 * span;
  const Ticks xt = axis_ticks(xa, r, std::max(2, static_cast<int>(area.width() / 110)));
  const Mapping x{xt, Scale::linear, area.left, area.right};
  Axis none = linear_axis("", "");
  draw_axes(cr, area, x, nullptr, xa, none, area.bottom + 4, height);
  if (chart.reference) vertical(cr, area, x, *chart.reference, kReference, Dash::dashed);
  for (std::size_t k = 0; k < chart.rows.size(); ++k) {
    const TornadoRow& row = chart.rows[k];
    const double row_top = area.top + k * kRow + (kRow - kBar) / 2;
    draw_bar(cr, area, x, chart.centre, row_top, {row.low, row.low_text, kLow});
    draw_bar(cr, area, x, chart.centre, row_top + kBar / 2, {row.high, row.high_text, kHigh});
    set_font(cr, 13);
    std::string label = row.label;
    while (label.size() > 4 && text_width(cr, label) > label_room) label = label.substr(0, label.size() - 4) + "…";
    draw_text(cr, kPad + 4, row_top + kBar / 2 + 4.5, label, Align::left);
  }
  vertical(cr, area, x, chart.centre, kFrame, Dash::solid);
  write_surface(canvas.surface, png);
}

}  // namespace elbowsim::plot
