#include "app/study/sensitivity.hpp"

#include <algorithm>
#include <cmath>

#include "engine/recording/number_text.hpp"

namespace elbowsim::study {

namespace {

using Json = nlohmann::ordered_json;

bool significant_outcome(const std::string& outcome) { return outcome == "lower" || outcome == "higher"; }

// What holding a factor at one end does to the verdict: "flips" (the other
// side, significant), "removes" (no significant difference any more), "decides"
// (a difference where there was none), "no verdict" or "none".
std::string effect_at(const RatioAt& nominal, const RatioAt& end) {
  if (end.outcome == "no verdict") return nominal.outcome == "no verdict" ? "none" : "no verdict";
  if (significant_outcome(nominal.outcome)) {
    if (significant_outcome(end.outcome) && end.outcome != nominal.outcome) return "flips";
    if (end.outcome == "no significant difference") return "removes";
    return "none";
  }
  return significant_outcome(end.outcome) ? "decides" : "none";
}

int effect_rank(const std::string& effect) {
  return effect == "flips" ? 4 : effect == "removes" || effect == "decides" ? 3 : effect == "no verdict" ? 2 : 1;
}

// A factor's effect: the stronger of its two ends'.
std::string factor_effect(const FactorPoints& f, const RatioAt& nominal) {
  const std::string low = effect_at(nominal, f.low), high = effect_at(nominal, f.high);
  return effect_rank(high) > effect_rank(low) ? high : low;
}

// The extent of ln ratio over the centre and both ends: a factor whose ends
// both lie on one side of the centre (a V) swings as far as its farther end.
double swing_of(const FactorPoints& f, const RatioAt& nominal) {
  double lo = 0, hi = 0;
  bool any = false;
  for (const RatioAt* r : {&nominal, &f.low, &f.high}) {
    if (!r->ratio || *r->ratio <= 0) {
      if (r != &nominal) return 0;
      continue;
    }
    const double l = std::log(*r->ratio);
    lo = any ? std::min(lo, l) : l, hi = any ? std::max(hi, l) : l, any = true;
  }
  return hi - lo;
}

// Both ends on the same side of the centre, each by more than its interval's
// half-width at the centre: the response is not monotone over the range.
bool not_monotone(const FactorPoints& f, const RatioAt& nominal) {
  if (!nominal.ratio || !f.low.ratio || !f.high.ratio || !nominal.ci_low || !nominal.ci_high) return false;
  const bool low_above = *f.low.ratio > *nominal.ci_high, high_above = *f.high.ratio > *nominal.ci_high;
  const bool low_below = *f.low.ratio < *nominal.ci_low, high_below = *f.high.ratio < *nominal.ci_low;
  return (low_above && high_above) || (low_below && high_below);
}

Json ratio_json(const RatioAt& r) {
  Json j = Json::object();
  if (r.ratio) j["ratio"] = *r.ratio;
  if (r.ci_low && r.ci_high) j["ci95"] = {*r.ci_low, *r.ci_high};
  j["outcome"] = r.outcome;
  return j;
}

// "0.67 (0.60–0.75)", or "no estimate".
std::string ratio_text(const RatioAt& r) {
  if (!r.ratio) return "no estimate";
  std::string out = significant(*r.ratio, 3);
  if (r.ci_low && r.ci_high) out += " (" + significant(*r.ci_low, 3) + "–" + significant(*r.ci_high, 3) + ")";
  return out;
}

std::string outcome_text(const std::string& outcome, const std::string& a) {
  if (outcome == "lower") return a + " lower";
  if (outcome == "higher") return a + " higher";
  return outcome;
}

// Where ln ratio, linear between the centre and an end, crosses 0.
std::optional<double> crossing(const SensitivityFactor& f, const RatioAt& nominal, const RatioAt& end,
                               double at) {
  if (!nominal.ratio || !end.ratio || *nominal.ratio <= 0 || *end.ratio <= 0) return std::nullopt;
  const double l0 = std::log(*nominal.ratio), l1 = std::log(*end.ratio);
  if (l0 == 0 || (l0 > 0) == (l1 > 0) || l1 == 0) return std::nullopt;
  return f.centre + (at - f.centre) * l0 / (l0 - l1);
}

}  // namespace

std::vector<SensitivityFactor> sensitivity_factors(const Uncertainty& uncertainty) {
  std::vector<SensitivityFactor> out;
  for (const UncertainParameter& p : uncertainty.parameters) {
    if (std::any_of(out.begin(), out.end(), [&](const SensitivityFactor& f) { return f.given == p.given; }))
      continue;
    SensitivityFactor f;
    f.given = p.given;
    switch (p.law) {
      case UncertainParameter::Law::uniform:
        f.low = -p.spread, f.high = p.spread;
        f.law = "uniform ±" + significant(100 * p.spread, 3) + " %";
        break;
      case UncertainParameter::Law::normal:
        f.low = -2 * p.spread, f.high = 2 * p.spread;
        f.law = "normal σ " + significant(100 * p.spread, 3) + " %, held at ±2σ";
        break;
      case UncertainParameter::Law::range:
        f.relative = false;
        f.low = p.low, f.high = p.high, f.centre = (p.low + p.high) / 2;
        f.law = "range [" + significant(p.low, 6) + ", " + significant(p.high, 6) + "]";
        break;
    }
    out.push_back(f);
  }
  return out;
}

std::string factor_value(const SensitivityFactor& f, double u) {
  if (!f.relative) return u < 0 ? "−" + significant(-u, 6) : significant(u, 6);
  const std::string pct = significant(100 * std::abs(u), 3) + " %";
  return u > 0 ? "+" + pct : u < 0 ? "−" + pct : "0 %";
}

RatioAt ratio_at(const Json& pair, const std::string& metric) {
  RatioAt r;
  if (!pair.contains(metric)) return r;
  const Json& m = pair[metric];
  if (m.contains("ratio") && m["ratio"].is_number()) r.ratio = m["ratio"].get<double>();
  if (m.contains("ci95") && m["ci95"].size() == 2)
    r.ci_low = m["ci95"][0].get<double>(), r.ci_high = m["ci95"][1].get<double>();
  if (m.contains("outcome")) r.outcome = m["outcome"].get<std::string>();
  return r;
}

Json sensitivity_of(const std::string& metric, const std::string& what, const std::string& a,
                    const std::string& b, const RatioAt& nominal, const std::vector<FactorPoints>& factors) {
  // Ranked by what they do to the verdict (flips, then removes or decides a
  // difference), then by swing, largest first; ties keep the file's order.
  std::vector<std::size_t> order(factors.size());
  std::vector<int> rank(factors.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    order[k] = k, rank[k] = effect_rank(factor_effect(factors[k], nominal));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    if (rank[x] != rank[y]) return rank[x] > rank[y];
    return swing_of(factors[x], nominal) > swing_of(factors[y], nominal);
  });

  Json doc{{"metric", metric}, {"what", what}, {"a", a}, {"b", b}, {"nominal", ratio_json(nominal)}};
  Json ranked = Json::array(), sentences = Json::array();
  sentences.push_back(std::string(1, static_cast<char>(std::toupper(what[0]))) + what.substr(1) + ", " + a +
                      " ÷ " + b + ", every parameter drawn: " + ratio_text(nominal) + ", " +
                      outcome_text(nominal.outcome, a) + ".");
  bool changed = false;
  for (std::size_t k : order) {
    const FactorPoints& p = factors[k];
    const SensitivityFactor& f = p.factor;
    Json j{{"given", f.given}, {"law", f.law}};
    Json crosses = nullptr;
    for (const auto& [end, at, r] : {std::tuple{"low", f.low, p.low}, std::tuple{"high", f.high, p.high}}) {
      Json e = ratio_json(r);
      e["value"] = at;
      j[end] = e;
      const std::string here = effect_at(nominal, r);
      if (here == "flips" || here == "removes" || here == "decides") {
        changed = true;
        std::string s = f.given + " held at " + factor_value(f, at) + ": " + ratio_text(r) + ", " +
                        outcome_text(r.outcome, a);
        s += here == "flips" ? ": the verdict flips" : here == "removes" ? ": the difference is gone" : ": a difference appears";
        if (const auto x = crossing(f, nominal, r, at)) {
          crosses = Json{{"end", end}, {"at", *x}};
          s += "; the ratio crosses 1 near " + factor_value(f, *x) +
               " (interpolated between the draws' centre and this end)";
        }
        sentences.push_back(s + ".");
      }
    }
    const bool monotone = !not_monotone(p, nominal);
    j["swing"] = swing_of(p, nominal);
    j["monotone"] = monotone;
    if (!monotone)
      sentences.push_back(f.given + ": both ends move the ratio the same way (" + ratio_text(p.low) + " at " +
                          factor_value(f, f.low) + ", " + ratio_text(p.high) + " at " + factor_value(f, f.high) +
                          "; " + ratio_text(nominal) +
                          " with it drawn): not monotone over its range; a narrower range shows where it turns.");
    j["effect"] = factor_effect(p, nominal);
    j["crosses"] = crosses;
    ranked.push_back(j);
  }
  if (!changed && !order.empty()) {
    const FactorPoints& top = factors[order.front()];
    sentences.push_back("No parameter held at either end of its range changes the verdict; the largest swing: " +
                        top.factor.given + " (" + ratio_text(top.low) + " at " +
                        factor_value(top.factor, top.factor.low) + ", " + ratio_text(top.high) + " at " +
                        factor_value(top.factor, top.factor.high) + ").");
  }
  doc["factors"] = ranked;
  doc["sentences"] = sentences;
  return doc;
}

}  // namespace elbowsim::study
