// report/statistics.cpp: mean, median, the bootstrap-t interval (its coverage
// checked on a distribution with a known mean) and paired ratios.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "report/statistics.hpp"

using namespace elbowsim::report;

TEST_CASE("mean and median") {
  CHECK(mean({1, 2, 6}) == 3);
  CHECK(median({5, 1, 3}) == 3);
  CHECK(median({4, 1, 3, 2}) == 2.5);
  CHECK(std::isnan(mean({})));
}

TEST_CASE("bootstrap: the 95 % interval of the mean covers the true mean in 90-99 % of repetitions") {
  // 200 repetitions of 30 draws from a normal (mean 5, sigma 2) and a skewed
  // exponential (mean 1); 200 repetitions have a standard error of 1.6 %. (A
  // percentile interval covered the exponential's mean in 88 % only.)
  for (int distribution : {0, 1}) {
    CAPTURE(distribution);
    std::mt19937_64 gen(12345);
    std::normal_distribution<double> normal(5.0, 2.0);
    std::exponential_distribution<double> exponential(1.0);
    const double truth = distribution == 0 ? 5.0 : 1.0;
    int covered = 0;
    for (int rep = 0; rep < 200; ++rep) {
      std::vector<double> x(30);
      for (double& v : x) v = distribution == 0 ? normal(gen) : exponential(gen);
      covered += bootstrap_mean(x, 0.95, 2000, static_cast<std::uint64_t>(rep)).contains(truth);
    }
    MESSAGE("coverage ", covered / 2.0, " %");
    CHECK(covered >= 180);
    CHECK(covered <= 198);
  }
}

TEST_CASE("bootstrap: the same values and seed give the same interval; another seed barely moves it") {
  const std::vector<double> x = {1, 4, 2, 8, 5, 7, 3, 6};
  const Interval a = bootstrap_mean(x, 0.95, 2000, 1), b = bootstrap_mean(x, 0.95, 2000, 1);
  CHECK(a.low == b.low);
  CHECK(a.high == b.high);
  const Interval c = bootstrap_mean(x, 0.95, 2000, 2);
  CHECK(c.low != a.low);
  CHECK(std::abs(c.low - a.low) < 0.3);
  CHECK(a.low < mean(x));
  CHECK(a.high > mean(x));
  CHECK_THROWS(bootstrap_mean({1}, 0.95, 100, 1));
}

TEST_CASE("paired ratio: identical variants give 1 with an interval [1, 1]; a constant factor is found") {
  const std::vector<double> a = {1.0, 2.0, 3.5, 0.7};
  const PairedRatio same = paired_ratio(a, a, 0.95, 1000, 3);
  CHECK(same.ratio == doctest::Approx(1.0));
  CHECK(same.ci.contains(1.0));
  CHECK(same.win_rate == 0);
  std::vector<double> half;
  for (double v : a) half.push_back(0.5 * v);
  const PairedRatio r = paired_ratio(half, a, 0.95, 1000, 3);
  CHECK(r.ratio == doctest::Approx(0.5));
  CHECK(r.ci.low == doctest::Approx(0.5));
  CHECK(r.ci.high == doctest::Approx(0.5));
  CHECK(r.win_rate == 1.0);
  CHECK(r.pairs == 4);
  CHECK_THROWS(paired_ratio({1.0}, {1.0, 2.0}, 0.95, 100, 1));
  CHECK_THROWS(paired_ratio({0.0}, {1.0}, 0.95, 100, 1));
}
