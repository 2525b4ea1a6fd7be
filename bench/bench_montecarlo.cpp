// Monte Carlo throughput: the shipped experiment's nominal case
// (scenarios/elbow_experiment.yaml, loops-nominal-mid-sized: the resting and
// the held-up arm per draw, as the measurements before the third arm) as `elbowsim montecarlo` runs it, with --jobs 1 and --jobs 2
// alternately (so both see the same load), wall clock. Prints the medians,
// draws per second and the speed-up of two jobs.
//
// Run: build/bench/bench_montecarlo [repetitions (default 3)] [--samples N (default 8)] [--json FILE]
//   (outputs go to /tmp/elbowsim_bench_montecarlo)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands/commands.hpp"

namespace {

double median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  const std::size_t n = x.size();
  return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  double one = 0;
  in >> one;
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", one);
  return text;
}

// One study of `samples` draws with `jobs` threads: its wall time [s].
double one_study(int jobs, long samples) {
  elbowsim::MonteCarloArguments args;
  args.scenario = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_experiment.yaml";
  args.out = "/tmp/elbowsim_bench_montecarlo/jobs" + std::to_string(jobs);
  args.samples = samples;
  args.jobs = jobs;
  args.report = false;
  args.cases = "task=loops,speed=nominal,elbow=mid,motor=sized";
  args.variants = {"elbow_on", "elbow_off"};
  std::streambuf* quiet = std::cout.rdbuf(nullptr);  // the command's own lines
  const auto start = std::chrono::steady_clock::now();
  const int code = elbowsim::montecarlo_command(args);
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
  std::cout.rdbuf(quiet);
  if (code != 0) {
    std::fprintf(stderr, "bench_montecarlo: the study failed (exit %d)\n", code);
    std::exit(1);
  }
  return wall.count();
}

}  // namespace

int main(int argc, char** argv) {
  int repetitions = 3;
  long samples = 8;
  const char* json_path = nullptr;
  for (int k = 1; k < argc; ++k) {
    if (std::strcmp(argv[k], "--json") == 0 && k + 1 < argc) json_path = argv[++k];
    else if (std::strcmp(argv[k], "--samples") == 0 && k + 1 < argc) samples = std::max(2L, std::atol(argv[++k]));
    else if (argv[k][0] == '-') {
      std::fprintf(stderr, "usage: %s [repetitions (default 3)] [--samples N (default 8)] [--json FILE]\n", argv[0]);
      return 2;
    } else repetitions = std::max(1, std::atoi(argv[k]));
  }
  const std::string load = load_average();
  std::vector<double> one, two;
  for (int r = 0; r < repetitions; ++r) {  // paired: both under the same load
    one.push_back(one_study(1, samples));
    two.push_back(one_study(2, samples));
    std::fprintf(stderr, "repetition %d: jobs 1 %.2f s, jobs 2 %.2f s\n", r + 1, one.back(), two.back());
  }
  const double m1 = median(one), m2 = median(two);
  const double runs = 2.0 * static_cast<double>(samples);  // two variants per draw
  std::printf("montecarlo loops-nominal-mid, %ld draws x 2 variants, median of %d\n", samples, repetitions);
  std::printf("  jobs 1: %.2f s (%.2f draws/s)\n  jobs 2: %.2f s (%.2f draws/s)\n  speed-up %.2f\n", m1,
              static_cast<double>(samples) / m1, m2, static_cast<double>(samples) / m2, m1 / m2);
  if (!json_path) return 0;
  std::ofstream f(json_path);
  if (!f) {
    std::perror(json_path);
    return 1;
  }
  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  auto list = [](const std::vector<double>& x) {
    std::ostringstream s;
    for (std::size_t i = 0; i < x.size(); ++i) s << (i ? ", " : "") << x[i];
    return s.str();
  };
  f << "{\n  \"context\": {\"date\": \"" << date << "\", \"load_avg\": [" << load
    << "], \"case\": \"loops-nominal-mid\", \"samples\": " << samples << ", \"runs_per_study\": " << runs
    << ", \"repetitions\": " << repetitions << "},\n"
    << "  \"wall_seconds\": {\"jobs_1\": [" << list(one) << "], \"jobs_2\": [" << list(two) << "]},\n"
    << "  \"median_seconds\": {\"jobs_1\": " << m1 << ", \"jobs_2\": " << m2 << "},\n"
    << "  \"draws_per_second\": {\"jobs_1\": " << static_cast<double>(samples) / m1
    << ", \"jobs_2\": " << static_cast<double>(samples) / m2 << "},\n"
    << "  \"speed_up\": " << m1 / m2 << "\n}\n";
  return 0;
}
