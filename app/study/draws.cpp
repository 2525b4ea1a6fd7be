#include "app/study/draws.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "engine/recording/number_text.hpp"

namespace elbowsim::study {

namespace {

// Uniform in [0, 1) from the top 53 bits: the same numbers on every platform
// (the standard distributions are implementation-defined).
double unit(std::mt19937_64& gen) { return static_cast<double>(gen() >> 11) * 0x1.0p-53; }

// Standard normal by Box-Muller, truncated at 3 (redrawn beyond).
double normal3(std::mt19937_64& gen) {
  for (;;) {
    const double a = 1.0 - unit(gen), b = unit(gen);  // a in (0, 1]
    const double z = std::sqrt(-2.0 * std::log(a)) * std::cos(2 * std::numbers::pi * b);
    if (std::abs(z) <= 3) return z;
  }
}

}  // namespace

Draw draw_parameters(const Uncertainty& uncertainty, std::uint64_t seed, long index) {
  const auto i = static_cast<std::uint64_t>(index);
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i >> 32)};
  std::mt19937_64 gen(seq);
  Draw d{index, {}};
  for (const UncertainParameter& p : uncertainty.parameters) {
    switch (p.law) {
      case UncertainParameter::Law::uniform: d.u.push_back(p.spread * (2 * unit(gen) - 1)); break;
      case UncertainParameter::Law::normal: d.u.push_back(p.spread * normal3(gen)); break;
      case UncertainParameter::Law::range: d.u.push_back(p.low + (p.high - p.low) * unit(gen)); break;
    }
  }
  return d;
}

std::uint64_t case_seed(std::uint64_t seed, const std::string& case_name) {
  if (case_name.empty()) return seed;
  std::uint64_t h = 14695981039346656037ULL;  // FNV-1a of the name
  for (unsigned char ch : case_name) h = (h ^ ch) * 1099511628211ULL;
  std::uint64_t z = seed ^ h;  // then SplitMix64's finaliser: every bit of both moves the result
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double drawn_value(const UncertainParameter& p, double u) {
  return p.law == UncertainParameter::Law::range ? u : p.nominal * (1 + u);
}

std::vector<std::string> draw_overrides(const Uncertainty& uncertainty, const Draw& draw) {
  std::vector<std::string> out;
  for (std::size_t j = 0; j < uncertainty.parameters.size(); ++j) {
    const UncertainParameter& p = uncertainty.parameters[j];
    out.push_back(p.key + "=" + round_trip(drawn_value(p, draw.u[j])));
  }
  return out;
}

}  // namespace elbowsim::study
