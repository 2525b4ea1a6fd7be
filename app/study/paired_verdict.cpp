#include "app/study/paired_verdict.hpp"

#include <cmath>

#include "engine/recording/number_text.hpp"
#include "report/statistics.hpp"

namespace elbowsim::study {

namespace {

using Json = nlohmann::ordered_json;

std::string draw_list(const std::vector<long>& draws) {
  std::string out = draws.size() == 1 ? "draw " : "draws ";
  for (std::size_t k = 0; k < draws.size(); ++k) {
    if (k == 8) return out + " and " + std::to_string(draws.size() - 8) + " more";
    out += (k ? ", " : "") + std::to_string(draws[k]);
  }
  return out;
}

// The interval as a sentence writes it: a ratio's "0.113–0.130", a
// difference's "−14.1 J to −13.0 J" (a dash between negatives misreads).
std::string interval(const ComparedQuantity& q, const report::Interval& ci) {
  return q.ratio ? quantity(ci.low, "") + "–" + quantity(ci.high, "")
                 : quantity(ci.low, q.unit()) + " to " + quantity(ci.high, q.unit());
}

// A difference, or its absence, with the interval behind it.
std::string difference(const std::string& a, const std::string& b, const ComparedQuantity& q,
                       const report::PairedStatistic& r) {
  const std::string of = q.ratio ? a + "/" + b : a + " − " + b;
  const std::string ci = "paired 95 % CI of " + of + ": " + interval(q, *r.ci) + ", " +
                         std::to_string(r.pairs) + " draws";
  const double none = q.ratio ? 1.0 : 0.0;
  if (r.ci->contains(none))
    return std::string(q.what) + ": no significant difference between " + a + " and " + b + " (" +
           ci + ", contains " + (q.ratio ? "1" : "0") + ")";
  const bool lower = r.value < none;
  const std::string size =
      q.ratio ? percent(std::abs(r.value - 1)) : quantity(std::abs(r.value), q.unit());
  return std::string(q.what) + ": " + a + " " + size + (lower ? " lower" : " higher") + " than " +
         b + " (" + ci + "; " + a + " lower in " + percent(r.win_rate) + " of draws)";
}

std::vector<long> draws_of(const std::vector<std::size_t>& positions,
                           const std::vector<long>& index) {
  std::vector<long> out;
  for (std::size_t p : positions) out.push_back(p < index.size() ? index[p] : -1);
  return out;
}

// The statistic of one quantity as montecarlo.json holds it.
Json statistic_json(const ComparedQuantity& q, const report::PairedStatistic& r) {
  Json j{{"statistic", q.ratio ? "ratio" : "difference"}};
  if (!q.ratio) j["unit"] = q.unit();
  j["pairs"] = r.pairs;
  if (r.computed()) j[q.ratio ? "ratio" : "difference"] = r.value;
  if (r.ci) j["ci95"] = {r.ci->low, r.ci->high};
  if (std::isfinite(r.win_rate)) j["win_rate"] = r.win_rate;
  if (std::isfinite(r.sign_test_p)) {  // the exact sign test on the draws (report/statistics.hpp)
    j["a_lower_draws"] = r.a_lower;
    j["b_lower_draws"] = r.b_lower;
    j["sign_test_p"] = r.sign_test_p;
  }
  j["outcome"] = "no verdict";
  return j;
}

}  // namespace

nlohmann::ordered_json paired_verdict(const PairedSamples& s, std::uint64_t seed) {
  Json p;
  p["a"] = s.a;
  p["b"] = s.b;
  p["pairs_with_an_invalid_run"] = s.dropped;
  std::vector<std::string> verdict;
  const bool too_many_invalid =
      static_cast<double>(s.dropped) > kMaxInvalidShare * static_cast<double>(s.draws);
  for (const ComparedQuantity& q : kCompared) {
    const std::string m = q.metric;
    auto no_verdict = [&](const std::string& reason, const std::vector<long>& draws) {
      p[m]["outcome"] = "no verdict";
      p[m]["reason"] = reason;
      if (!draws.empty()) p[m]["draws"] = draws;
      // Named by its pair: a study of three variants prints three of each.
      verdict.push_back(std::string(q.what) + ", " + s.a + " against " + s.b + ": no verdict (" + reason +
                        (draws.empty() ? "" : ": " + draw_list(draws)) + ")");
    };
    const auto ia = s.a_values.find(m), ib = s.b_values.find(m);
    if (ia == s.a_values.end() || ib == s.b_values.end() || ia->second.empty()) {
      p[m] = {{"statistic", q.ratio ? "ratio" : "difference"}, {"pairs", 0}};
      no_verdict(s.draws > s.dropped ? m + " is not recorded in these runs"
                                     : "no draw where both runs are valid",
                 {});
      continue;
    }
    const auto index = s.draw_index.find(m);
    const std::vector<long> draws =
        index == s.draw_index.end() ? std::vector<long>() : index->second;
    const report::PairedStatistic r =
        q.ratio ? report::paired_ratio(ia->second, ib->second, kConfidenceLevel,
                                       kBootstrapResamples, seed)
                : report::paired_difference(ia->second, ib->second, kConfidenceLevel,
                                            kBootstrapResamples, seed);
    p[m] = statistic_json(q, r);
    if (!r.computed() || !r.ci) {
      no_verdict(r.problem, draws_of(r.involved, draws));
      continue;
    }
    if (too_many_invalid) {
      no_verdict(std::to_string(s.dropped) + " of " + std::to_string(s.draws) +
                     " draws have an invalid run; a verdict allows 10 %",
                 {});
      continue;
    }
    if (m == metric::hand_error_rms) {
      const double ma = report::median(ia->second), mb = report::median(ib->second);
      if (!(ma > kFloorFactor * s.floor_a && mb > kFloorFactor * s.floor_b)) {
        no_verdict("the medians (" + quantity(ma, "m") + ", " + quantity(mb, "m") +
                       ") are not above 10 x the accuracy floor (" + quantity(s.floor_a, "m") +
                       ", " + quantity(s.floor_b, "m") +
                       "; step halving of the nominal runs): they measure the integrator, not "
                       "the arm",
                   {});
        continue;
      }
    }
    const double none = q.ratio ? 1.0 : 0.0;
    p[m]["outcome"] = r.ci->contains(none) ? "no significant difference"
                      : r.value < none     ? "lower"
                                           : "higher";
    verdict.push_back(difference(s.a, s.b, q, r));
  }
  if (s.dropped > 0 && !too_many_invalid)
    verdict.push_back(std::to_string(s.dropped) + " of " + std::to_string(s.draws) +
                      " draws left out: a run of the pair was invalid (listed below)");
  p["verdict"] = verdict;
  return p;
}

}  // namespace elbowsim::study
