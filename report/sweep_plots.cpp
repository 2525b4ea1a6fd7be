#include "report/sweep_plots.hpp"

#include <cmath>
#include <map>

#include "report/plot/plot.hpp"
#include "report/summary_keys.hpp"

namespace elbowsim::report {

namespace {

double metric_value(const nlohmann::ordered_json& summary, const char* name) {
  const auto m = summary.find(summary_key::metrics.name());
  if (m == summary.end() || !m->contains(name) || !(*m)[name].is_number()) return NAN;
  return (*m)[name].get<double>();
}

// One series per variant of `name`, in the order the variants first appear.
std::vector<plot::Series> series_of(const std::vector<SweepPoint>& points, const char* name,
                                    const std::string& suffix, plot::Dash dash) {
  std::vector<std::string> order;
  std::map<std::string, plot::Series> by_variant;
  for (const SweepPoint& p : points) {
    if (!by_variant.count(p.variant)) order.push_back(p.variant);
    plot::Series& s = by_variant[p.variant];
    s.label = (p.variant.empty() ? std::string("run") : p.variant) + suffix;
    s.x.push_back(p.value);
    s.y.push_back(metric_value(p.summary, name));
    s.markers = true;
    s.dash = dash;
  }
  std::vector<plot::Series> out;
  for (std::size_t k = 0; k < order.size(); ++k) {
    out.push_back(by_variant[order[k]]);
    out.back().color = plot::palette(int(k));
  }
  return out;
}

bool any_finite(const std::vector<plot::Series>& series) {
  for (const plot::Series& s : series)
    for (double y : s.y)
      if (std::isfinite(y)) return true;
  return false;
}

}  // namespace

std::vector<std::filesystem::path> write_sweep_plots(const std::string& key,
                                                     const std::vector<SweepPoint>& points,
                                                     const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> written;
  plot::LinePlot error;
  error.title = "Hand error against " + key;
  error.x = plot::linear_axis(key, "");
  error.y = plot::log_axis("hand error", "m");
  error.series = series_of(points, metric::hand_error_rms, " RMS", plot::Dash::solid);
  for (plot::Series& s : series_of(points, metric::hand_error_max, " max", plot::Dash::dashed))
    error.series.push_back(std::move(s));
  if (any_finite(error.series)) {
    written.push_back(folder / "sweep_hand_error.png");
    plot::write_png(error, written.back());
  }
  plot::LinePlot energy;
  energy.title = "Energy against " + key;
  energy.x = plot::linear_axis(key, "");
  energy.y = plot::log_axis("energy", "J");
  energy.series = series_of(points, metric::energy_in, " E_in", plot::Dash::solid);
  for (plot::Series& s : series_of(points, metric::joule, " Joule", plot::Dash::dashed))
    energy.series.push_back(std::move(s));
  written.push_back(folder / "sweep_energy.png");
  plot::write_png(energy, written.back());
  return written;
}

}  // namespace elbowsim::report
