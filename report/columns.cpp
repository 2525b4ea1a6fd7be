#include "report/columns.hpp"

#include <algorithm>
#include <cmath>

namespace elbowsim::report {

std::vector<double> column(const Recording& rec, const std::string& name) {
  const int c = rec.column(name);
  if (c < 0) return {};
  std::vector<double> values(rec.rows());
  for (std::size_t row = 0; row < rec.rows(); ++row) values[row] = rec.at(row, c);
  return values;
}

std::string column_unit(const Recording& rec, const std::string& name) {
  const int c = rec.column(name);
  return c < 0 ? "" : rec.columns[c].unit;
}

std::vector<std::string> indexed_columns(const Recording& rec, const std::string& prefix) {
  std::vector<std::string> names;
  while (rec.column(prefix + std::to_string(names.size())) >= 0)
    names.push_back(prefix + std::to_string(names.size()));
  return names;
}

std::vector<std::string> elbow_names(const Recording& rec) {
  std::vector<std::string> names;
  for (const Column& c : rec.columns) {
    for (const char* prefix : {"fn_", "d_", "rest_"}) {
      const std::string p = prefix;
      if (c.name.rfind(p, 0) != 0 || c.name.size() == p.size()) continue;
      const std::string elbow = c.name.substr(p.size());
      bool known = false;
      for (const std::string& n : names) known = known || n == elbow;
      if (!known) names.push_back(elbow);
    }
  }
  return names;
}

std::vector<double> electrical_power(const Recording& rec) {
  const auto volts = indexed_columns(rec, "v");
  const auto amps = indexed_columns(rec, "i");
  if (volts.empty() || volts.size() != amps.size()) return {};
  std::vector<double> power(rec.rows(), 0.0);
  for (std::size_t j = 0; j < volts.size(); ++j) {
    const auto v = column(rec, volts[j]), i = column(rec, amps[j]);
    for (std::size_t row = 0; row < power.size(); ++row) power[row] += v[row] * i[row];
  }
  return power;
}

std::vector<double> running_integral(const std::vector<double>& t, const std::vector<double>& y) {
  std::vector<double> sum(std::min(t.size(), y.size()), 0.0);
  for (std::size_t k = 1; k < sum.size(); ++k) {
    const double area = 0.5 * (y[k] + y[k - 1]) * (t[k] - t[k - 1]);
    sum[k] = sum[k - 1] + (std::isfinite(area) ? area : 0.0);
  }
  return sum;
}

std::vector<plot::Interval> intervals_on(const std::vector<double>& t,
                                         const std::vector<double>& state) {
  std::vector<plot::Interval> on;
  const std::size_t n = std::min(t.size(), state.size());
  for (std::size_t k = 0; k < n; ++k) {
    if (!(state[k] >= 0.5)) continue;
    const double end = k + 1 < n ? t[k + 1] : t[k];
    if (k > 0 && state[k - 1] >= 0.5 && !on.empty())
      on.back().end = end;
    else
      on.push_back({t[k], end});
  }
  return on;
}

}  // namespace elbowsim::report
