#include "report/columns.hpp"

#include <algorithm>
#include <cmath>

namespace elbowsim::report {

std::vector<double> column(const Recording& rec, int index) { return rec.series(index); }

std::string column_name(const Recording& rec, int index) {
  return index < 0 ? "" : rec.columns()[static_cast<std::size_t>(index)].name;
}

std::string column_unit(const Recording& rec, int index) {
  return index < 0 ? "" : rec.columns()[static_cast<std::size_t>(index)].unit;
}

std::vector<double> electrical_power(const Recording& rec) {
  const TrajectoryLayout& L = rec.layout;
  if (!L.has_motors()) return {};
  std::vector<double> power(rec.rows(), 0.0);
  for (int j = 0; j < L.dof(); ++j) {
    const auto v = column(rec, L.voltage(j)), i = column(rec, L.current(j));
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
