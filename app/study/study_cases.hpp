// The cases of a study (elbowsim study): every combination of a grid's
// levels or each item of a list, each repeated over the draws of a Monte
// Carlo design; their folder names and the study's manifest (cases.json),
// which maps each folder to the keys it sets. A case's folder name is its
// index and a short label of shell-safe characters ([A-Za-z0-9._+-]):
// 003-duration_2-at_0.3, 017-near-d04.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "app/scenario/study_file.hpp"

namespace elbowsim::study {

struct CaseSpec {
  long index = 0;                      // 0 .. cases-1, in grid order (first axis slowest), draws fastest
  std::string folder;                  // index and label
  std::vector<std::string> overrides;  // the case's own "key=value", applied after the study's set
  std::vector<std::string> values;     // [columns] what the case sets there ("" where a list case does not)
  long draw = -1;                      // the Monte Carlo draw; -1 without draws
};

// The columns that tell cases apart: the grid's axes (key paths or axis
// names), or every key a list sets, in order of first appearance.
std::vector<std::string> case_columns(const StudyDesign& design);

std::vector<CaseSpec> enumerate_cases(const StudyDesign& design);

// A value as a piece of a folder name: characters other than letters,
// digits, '.', '+' and '-' become '_' (runs of them one), none at the ends.
std::string safe_label(const std::string& text);

// Shard `shard` of `shards` (1-based): cases shard-1, shard-1+shards, ...
// (round robin, so that a grid's slow and fast corners spread out).
bool in_shard(long index, int shard, int shards);

// cases.json: the study (name, scenario, set, columns, variants, draws,
// seed) and per case its index, folder, overrides, values and draw.
nlohmann::ordered_json cases_manifest(const StudyDesign& design, const std::vector<CaseSpec>& cases,
                                      const std::vector<std::string>& variants,
                                      std::uint64_t seed);

}  // namespace elbowsim::study
