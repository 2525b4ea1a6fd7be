// The merged results of a study (elbowsim study, then elbowsim merge): one
// row per case and variant with the case's keys, its state and every number
// of its summary.json except timings (so the table is the same bytes however
// and wherever the cases ran), written as table.csv; with repeats (the draws
// of a Monte Carlo design) the mean of each headline metric per point and
// variant with its 95 % bootstrap interval (from 15 draws), points.csv; and report.html with
// plots over every numeric swept key.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "report/metrics.hpp"
#include "report/statistics.hpp"

namespace elbowsim::report {

struct MergedRow {
  long index = 0;                   // the case's
  std::string folder;               // the case's folder name
  std::vector<std::string> values;  // [columns]
  long draw = -1;                   // -1 without draws
  std::string variant;              // "" without variants
  std::string status;               // "done", "failed" or "missing"
  std::string failure;              // why, when failed
  bool valid = false;               // summary.json "valid"
  std::filesystem::path run;        // the run folder (absent when missing)
  std::vector<Metric> metrics;      // summary.json's numbers, timings left out
};

struct MergedStudy {
  std::string name;                  // the study's
  std::string scenario;              // its scenario file
  std::vector<std::string> columns;  // the keys (or axis names) that tell cases apart
  std::vector<std::string> variants; // "" without variants
  long draws = 0;
  std::vector<MergedRow> rows;       // case by case, variants in order
};

// The headline metrics a point is summarised by: summary.json paths.
const std::vector<std::string>& headline_paths();  // metrics.energy_in, .joule, .hand_error_rms, .hand_error_max

// One point of the design (a case without its draw) in one variant, and the
// valid values of each headline metric over its draws.
struct MergedPoint {
  std::size_t row = 0;  // its first row in MergedStudy::rows (the column values)
  std::string variant;
  long runs = 0, valid = 0;
  std::vector<std::vector<double>> values;  // [headline_paths()] the valid runs' values
};
std::vector<MergedPoint> merged_points(const MergedStudy& study);

// The mean of headline metric h over a point's valid draws with its 95 %
// BCa bootstrap interval: on a log scale (never below 0) except for the net
// energy in, which can be negative; none below kMinIntervalValues draws.
Estimate headline_estimate(const std::vector<double>& values, std::size_t h);

// table.csv: case, the columns, draw (with draws), variant, status,
// failure, then every metric (valid among them) ("path [unit]", the union in order of first
// appearance); numbers in their shortest round-trip form.
void write_merged_table(std::ostream& out, const MergedStudy& study);

// points.csv (draws only): per point and variant the runs, the valid ones,
// and each headline metric's mean, 95 % interval low and high (empty without
// an interval: headline_estimate), median.
void write_points_table(std::ostream& out, const MergedStudy& study);

// report.html and plots/ into `out`: the state of the cases and their
// failures, a plot of each headline metric against every numeric column
// (one line per variant and level of the other columns; mean and 95 %
// interval bars with draws), and the table with links to the run folders.
// Returns report.html's path. Throws std::runtime_error naming a file that
// cannot be written.
std::filesystem::path write_merged_report(const MergedStudy& study, const std::filesystem::path& out);

}  // namespace elbowsim::report
