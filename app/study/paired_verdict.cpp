#include "app/study/paired_verdict.hpp"

#include <cstdio>

#include "report/statistics.hpp"

namespace elbowsim::study {

namespace {

std::string percent(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", 100 * x);
  return b;
}

std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

// A difference, or its absence, with the interval behind it.
std::string difference(const std::string& a, const std::string& b, const std::string& what,
                       const report::PairedRatio& r) {
  const std::string ci = "paired 95 % CI of " + a + "/" + b + ": " + num(r.ci.low) + "–" +
                         num(r.ci.high) + ", " + std::to_string(r.pairs) + " draws";
  if (r.ci.contains(1.0))
    return what + ": no significant difference between " + a + " and " + b + " (" + ci +
           ", contains 1)";
  const std::string change =
      r.ratio < 1 ? percent(1 - r.ratio) + " % lower" : percent(r.ratio - 1) + " % higher";
  return what + ": " + a + " " + change + " than " + b + " (" + ci + "; " + a + " lower in " +
         percent(r.win_rate) + " % of draws)";
}

}  // namespace

nlohmann::ordered_json paired_verdict(const PairedSamples& s, std::uint64_t seed) {
  nlohmann::ordered_json p;
  p["a"] = s.a;
  p["b"] = s.b;
  p["pairs_with_an_invalid_run"] = s.dropped;
  std::vector<std::string> verdict;
  const bool too_many_invalid =
      static_cast<double>(s.dropped) > kMaxInvalidShare * static_cast<double>(s.draws);
  for (const std::string m : {"energy_in", "hand_error_rms"}) {
    const std::string what = m == "energy_in" ? "electrical energy" : "RMS hand error";
    const auto ia = s.a_values.find(m), ib = s.b_values.find(m);
    if (ia == s.a_values.end() || ib == s.b_values.end() || ia->second.size() < 2) {
      verdict.push_back(what + ": no verdict (fewer than 2 draws where both runs are valid)");
      p[m] = {{"outcome", "no verdict"}};
      continue;
    }
    const report::PairedRatio r =
        report::paired_ratio(ia->second, ib->second, kConfidenceLevel, kBootstrapResamples, seed);
    p[m] = {{"pairs", r.pairs}, {"ratio", r.ratio}, {"ci95", {r.ci.low, r.ci.high}},
            {"win_rate", r.win_rate}, {"outcome", "no verdict"}};
    if (too_many_invalid) {
      verdict.push_back(what + ": no verdict (" + std::to_string(s.dropped) + " of " +
                        std::to_string(s.draws) + " draws have an invalid run)");
      continue;
    }
    if (m == "hand_error_rms") {
      const double ma = report::median(ia->second), mb = report::median(ib->second);
      if (!(ma > kFloorFactor * s.floor_a && mb > kFloorFactor * s.floor_b)) {
        verdict.push_back(what + ": no verdict: the medians (" + num(ma) + " m, " + num(mb) +
                          " m) are not above 10 x the accuracy floor (" + num(s.floor_a) + " m, " +
                          num(s.floor_b) + " m; step halving of the nominal runs): they measure "
                          "the integrator, not the arm");
        continue;
      }
    }
    p[m]["outcome"] = r.ci.contains(1.0) ? "no significant difference" : r.ratio < 1 ? "lower" : "higher";
    verdict.push_back(difference(s.a, s.b, what, r));
  }
  if (s.dropped > 0 && !too_many_invalid)
    verdict.push_back(std::to_string(s.dropped) + " of " + std::to_string(s.draws) +
                      " draws left out: a run of the pair was invalid (listed below)");
  p["verdict"] = verdict;
  return p;
}

}  // namespace elbowsim::study
