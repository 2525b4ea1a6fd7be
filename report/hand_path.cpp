#include "report/hand_path.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/recording/number_text.hpp"
#include "report/columns.hpp"

namespace elbowsim::report {

namespace {

const char* kAxis[] = {"x", "y", "z"};
const plot::Color kDesired{0.25, 0.25, 0.25};

double extent(const std::vector<double>& v) {
  double lo = INFINITY, hi = -INFINITY;
  for (double x : v)
    if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
  return hi >= lo ? hi - lo : 0.0;
}

// The hand's (or, with a task, the desired hand's) extent along each axis, over all runs.
std::vector<double> extents(const std::vector<const Recording*>& recordings) {
  std::vector<double> out(3, 0.0);
  for (const Recording* rec : recordings)
    for (int axis = 0; axis < 3; ++axis) {
      const int desired = rec->layout.hand_desired(axis);
      out[axis] = std::max(out[axis], extent(column(*rec, rec->layout.hand(axis))));
      if (desired >= 0) out[axis] = std::max(out[axis], extent(column(*rec, desired)));
    }
  return out;
}

// Largest in-plane distance from the desired path, over all runs; 0 without one.
double largest_error(const std::vector<const Recording*>& recordings, const TaskPlane& plane) {
  double worst = 0;
  for (const Recording* rec : recordings) {
    const TrajectoryLayout& L = rec->layout;
    if (!L.has_desired_hand()) continue;
    const auto a = column(*rec, L.hand(plane.a)), b = column(*rec, L.hand(plane.b));
    const auto da = column(*rec, L.hand_desired(plane.a)),
               db = column(*rec, L.hand_desired(plane.b));
    for (std::size_t k = 0; k < a.size(); ++k) {
      const double e = std::hypot(a[k] - da[k], b[k] - db[k]);
      if (std::isfinite(e)) worst = std::max(worst, e);
    }
  }
  return worst;
}

plot::Series line(std::string label, std::vector<double> x, std::vector<double> y, plot::Color c,
                  plot::Dash dash = plot::Dash::solid, double width = 1.8) {
  plot::Series s;
  s.label = std::move(label);
  s.x = std::move(x);
  s.y = std::move(y);
  s.color = c;
  s.dash = dash;
  s.width = width;
  return s;
}

// A dot where the path starts (not in the legend).
plot::Series start_marker(const std::vector<double>& x, const std::vector<double>& y,
                          plot::Color c) {
  plot::Series s = line("", {x.front()}, {y.front()}, c);
  s.markers = true;
  return s;
}

// A height at which the equal-scale plot fills its width: tall for a tall
// path, low for a flat one (within 320 to 640 px).
void fit_height(plot::LinePlot& p) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const plot::Series& s : p.series)
    for (std::size_t k = 0; k < std::min(s.x.size(), s.y.size()); ++k)
      if (std::isfinite(s.x[k]) && std::isfinite(s.y[k]))
        x0 = std::min(x0, s.x[k]), x1 = std::max(x1, s.x[k]), y0 = std::min(y0, s.y[k]),
        y1 = std::max(y1, s.y[k]);
  if (!(x1 > x0) || !(y1 >= y0)) return;
  const double area_width = p.width - 120.0, chrome = 150;  // [px] margins, title, legend, axis
  const double wanted = chrome + 1.1 * area_width * (y1 - y0) / (x1 - x0);
  p.height = static_cast<int>(std::clamp(wanted, 320.0, 640.0));
}

plot::LinePlot plane_plot(const TaskPlane& plane, const std::string& title) {
  plot::LinePlot p;
  p.title = title;
  p.x = plot::linear_axis(std::string("hand ") + kAxis[plane.a], "m");
  p.y = plot::linear_axis(std::string("hand ") + kAxis[plane.b], "m");
  p.equal_aspect = true;
  return p;
}

// Whether run r's desired path is drawn: the first run's always, another's
// only where it differs from the first's.
bool own_desired(const std::vector<const RunData*>& runs, std::size_t r, const TaskPlane& plane) {
  if (r == 0) return true;
  const Recording& first = runs[0]->trajectory;
  const Recording& rec = runs[r]->trajectory;
  if (!first.layout.has_desired_hand() || first.rows() != rec.rows()) return true;
  for (int axis : {plane.a, plane.b}) {
    const auto u = column(first, first.layout.hand_desired(axis));
    const auto v = column(rec, rec.layout.hand_desired(axis));
    for (std::size_t k = 0; k < u.size(); ++k)
      if (std::abs(u[k] - v[k]) > 1e-9) return true;
  }
  return false;
}

}  // namespace

TaskPlane task_plane(const std::vector<const Recording*>& recordings) {
  const std::vector<double> e = extents(recordings);
  if (e[1] == 0) return {0, 2, "x–z", "the arm moves in the x–z plane (hand_y is 0 throughout)"};
  // The two axes of largest extent, in x, y, z order.
  int smallest = 0;
  for (int axis = 1; axis < 3; ++axis)
    if (e[axis] < e[smallest]) smallest = axis;
  TaskPlane plane;
  plane.a = smallest == 0 ? 1 : 0;
  plane.b = smallest == 2 ? 1 : 2;
  plane.name = std::string(kAxis[plane.a]) + "–" + kAxis[plane.b];
  char why[160];
  std::snprintf(why, sizeof why,
                "the coordinate plane in which the hand's path is largest (it spans %.3g m along "
                "%s, the axis left out)",
                e[smallest], kAxis[smallest]);
  plane.why = why;
  return plane;
}

double error_magnification(const std::vector<const Recording*>& recordings,
                           const TaskPlane& plane) {
  const std::vector<double> e = extents(recordings);
  const double span = std::max(e[plane.a], e[plane.b]);
  const double worst = largest_error(recordings, plane);
  if (!(worst > 0) || !(span > 0)) return 1;
  const double wanted = span / 10 / worst;
  if (wanted < 2) return 1;
  // The 1-2-5 x 10^n at or below `wanted`.
  const double decade = std::pow(10.0, std::floor(std::log10(wanted)));
  const double m = wanted / decade;
  return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * decade;
}

HandPathFigures hand_path_figures(const std::vector<const RunData*>& runs,
                                  const std::string& title_suffix) {
  std::vector<const Recording*> recordings;
  for (const RunData* run : runs) recordings.push_back(&run->trajectory);
  const TaskPlane plane = task_plane(recordings);
  HandPathFigures out;
  out.k = error_magnification(recordings, plane);
  out.path = plane_plot(plane, "Hand path in the " + plane.name + " plane — " + title_suffix);
  plot::LinePlot magnified =
      plane_plot(plane, "Hand path, error × " + significant(out.k) + " — " + title_suffix);
  // Actual paths first, the desired ones dashed on top (where they coincide
  // the actual line shows between the dashes), start dots last.
  std::vector<plot::Series> actual, desired, dots, magnified_actual, magnified_dots;
  bool any_desired = false;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const Recording& rec = runs[r]->trajectory;
    const TrajectoryLayout& L = rec.layout;
    const plot::Color color = plot::palette(static_cast<int>(r));
    const std::string who = runs.size() > 1 ? runs[r]->label + " " : "";
    const auto a = column(rec, L.hand(plane.a)), b = column(rec, L.hand(plane.b));
    actual.push_back(line(who + "actual", a, b, color, plot::Dash::solid, 2.2));
    if (!a.empty()) dots.push_back(start_marker(a, b, color));
    if (!L.has_desired_hand()) continue;
    any_desired = true;
    const auto da = column(rec, L.hand_desired(plane.a)), db = column(rec, L.hand_desired(plane.b));
    if (own_desired(runs, r, plane))
      desired.push_back(line(r == 0 && runs.size() > 1 ? "desired" : who + "desired", da, db,
                             r == 0 ? kDesired : color, plot::Dash::dashed, 1.3));
    std::vector<double> ma(a.size()), mb(b.size());
    for (std::size_t k = 0; k < a.size(); ++k)
      ma[k] = da[k] + out.k * (a[k] - da[k]), mb[k] = db[k] + out.k * (b[k] - db[k]);
    magnified_actual.push_back(line(who + "desired + " + significant(out.k) + "·error", ma, mb,
                                    color, plot::Dash::solid, 2.0));
    if (!ma.empty()) magnified_dots.push_back(start_marker(ma, mb, color));
  }
  for (auto* group : {&actual, &desired, &dots})
    out.path.series.insert(out.path.series.end(), group->begin(), group->end());
  for (auto* group : {&magnified_actual, &desired, &magnified_dots})
    magnified.series.insert(magnified.series.end(), group->begin(), group->end());
  fit_height(out.path);
  fit_height(magnified);
  const std::string plane_note = "The " + plane.name + " plane: " + plane.why +
                                 "; both axes at one scale; a dot marks the start.";
  out.path_caption = "Where the hand went" +
                     std::string(any_desired ? " (solid) and where it was told to go (dashed). "
                                             : ". No desired path was recorded (no task). ") +
                     plane_note;
  if (any_desired) {
    out.magnified_caption =
        "The same paths with the tracking error magnified: each sample drawn at desired + "
        "k·(actual "
        "− desired) with k = " +
        significant(out.k) +
        ", so that the error's shape and where along the path it grows can be seen (an error of "
        "10 µm is drawn " +
        quantity(10e-6 * out.k, "m") + " long). " + plane_note;
    out.magnified = std::move(magnified);
  }
  return out;
}

}  // namespace elbowsim::report
