// The waterfall of an account (plot.hpp, Waterfall): one row per step, a
// horizontal bar from the running total before the step to the one after
// it, a dotted connector to the next row, the value printed beside the bar.
#include <algorithm>

#include "engine/recording/number_text.hpp"
#include "report/plot/canvas.hpp"

namespace elbowsim::plot {

using namespace canvas;

namespace {

constexpr double kRow = 30, kBar = 20;     // [px] row pitch, bar thickness
constexpr double kTop = 52, kBottom = 58;  // [px] title above, x axis below
const Color kAdded{0.349, 0.631, 0.310}, kTaken{0.882, 0.341, 0.349}, kTotal{0.45, 0.45, 0.45};

// [from, to] of each step's bar, in step order.
std::vector<std::pair<double, double>> spans(const Waterfall& chart) {
  std::vector<std::pair<double, double>> out;
  double running = 0;
  for (const WaterfallStep& s : chart.steps) {
    if (s.total) {
      out.push_back({0.0, running});
      continue;
    }
    out.push_back({running, running + s.value});
    running += s.value;
  }
  return out;
}

std::string value_text(const WaterfallStep& s, const std::string& unit, double running) {
  std::string out = significant(s.total ? running : s.value, 3);
  if (!unit.empty()) out += " " + unit;
  if (!s.text.empty()) out = s.text;
  return s.note.empty() ? out : out + "  " + s.note;
}

Color step_color(const WaterfallStep& s) {
  if (s.color) return *s.color;
  return s.total ? kTotal : s.value >= 0 ? kAdded : kTaken;
}

// Bars, connectors and value labels; the labels go right of a bar's right
// end, or inside a long bar's left end when they would leave the area.
void draw_rows(cairo_t* cr, const Waterfall& chart, const Box& area, const Mapping& x) {
  const auto bars = spans(chart);
  set_font(cr, 12);
  for (std::size_t k = 0; k < bars.size(); ++k) {
    const WaterfallStep& s = chart.steps[k];
    const double top = area.top + k * kRow + (kRow - kBar) / 2;
    const double a = std::clamp(x(std::min(bars[k].first, bars[k].second)), area.left, area.right);
    const double b = std::clamp(x(std::max(bars[k].first, bars[k].second)), area.left, area.right);
    set_color(cr, step_color(s));
    cairo_rectangle(cr, a, top, std::max(b - a, 1.5), kBar);
    cairo_fill(cr);
    if (k + 1 < bars.size()) {  // connector: where the next bar starts
      const double at = std::round(x(bars[k].second)) + 0.5;
      set_color(cr, kFrame);
      cairo_set_line_width(cr, 1);
      set_dash(cr, Dash::dotted, 1.6);
      cairo_move_to(cr, at, top + kBar), cairo_line_to(cr, at, top + kRow), cairo_stroke(cr);
      set_dash(cr, Dash::solid, 1);
    }
    const std::string text = value_text(s, chart.x.unit, bars[k].second);
    const double w = text_width(cr, text);
    const double baseline = top + kBar / 2 + 4.5;
    if (b + 6 + w <= area.right)
      draw_text(cr, b + 6, baseline, text, Align::left);
    else if (a - 6 - w >= area.left)
      draw_text(cr, a - 6, baseline, text, Align::right);
    else
      draw_text(cr, a + 6, baseline, text, Align::left, {1, 1, 1});
    set_font(cr, 13, s.total);
    draw_text(cr, kPad + 4, baseline, s.label, Align::left);
    set_font(cr, 12);
  }
}

}  // namespace

int waterfall_height(std::size_t steps) {
  return static_cast<int>(kTop + kRow * std::max<std::size_t>(steps, 1) + kBottom + 10);
}

void write_png(const Waterfall& chart, const std::filesystem::path& png) {
  const int height = chart.height > 0 ? chart.height : waterfall_height(chart.steps.size());
  Canvas canvas(chart.width, height);
  cairo_t* cr = canvas.cr;
  header(cr, chart.title, {}, chart.width, true);
  set_font(cr, 13, true);
  std::vector<std::string> labels;
  for (const WaterfallStep& s : chart.steps) labels.push_back(s.label);
  const double label_room = widest(cr, labels);
  Box area{kPad + 4 + label_room + 14, kTop, chart.width - kPad - 10.0,
           kTop + kRow * std::max<std::size_t>(chart.steps.size(), 1)};
  Range r;
  for (const auto& [from, to] : spans(chart)) r.add(from), r.add(to);
  // A residual a hair below 0 would open a whole tick of negative axis: such
  // a bar is drawn at the axis' edge instead.
  if (r.lo < 0 && r.hi > 0 && -r.lo < 0.02 * r.hi) r.lo = 0;
  if (chart.steps.empty() || r.empty() || !std::isfinite(r.lo) || !std::isfinite(r.hi)) {
    draw_message(cr, area, chart.empty_message);
    return write_surface(canvas.surface, png);
  }
  // Room on the right for the longest value label beyond the largest total.
  Axis xa = chart.x;
  xa.scale = Scale::linear;
  xa.include_zero = true;
  const Ticks probe = axis_ticks(xa, r, 6);
  set_font(cr, 12);
  double value_room = 0;
  const auto bars = spans(chart);
  for (std::size_t k = 0; k < bars.size(); ++k)
    value_room =
        std::max(value_room, text_width(cr, value_text(chart.steps[k], xa.unit, bars[k].second)));
  const double data_width = area.width() - std::min(value_room + 12, 0.45 * area.width());
  xa.max = probe.lo + (probe.hi - probe.lo) * area.width() / data_width;
  xa.min = probe.lo;
  const Ticks xt = axis_ticks(xa, r, std::max(2, static_cast<int>(area.width() / 110)));
  const Mapping x{xt, Scale::linear, area.left, area.right};
  Axis none = linear_axis("", "");
  draw_axes(cr, area, x, nullptr, xa, none, area.bottom + 4, height);
  // The zero line: where the account starts and should end.
  set_color(cr, kFrame);
  cairo_set_line_width(cr, 1.2);
  const double zero = std::round(x(0.0)) + 0.5;
  cairo_move_to(cr, zero, area.top), cairo_line_to(cr, zero, area.bottom), cairo_stroke(cr);
  draw_rows(cr, chart, area, x);
  write_surface(canvas.surface, png);
}

}  // namespace elbowsim::plot
