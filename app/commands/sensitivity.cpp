// elbowsim sensitivity: the paired Monte Carlo comparison with every parameter
// drawn (the centre), then again with each uncertain parameter held at either
// end of its range (app/study/sensitivity.hpp). Each point is a montecarlo run
// of its own (DIR/points/<point>/, same seed, same draws of the others); the
// verdicts' response goes to DIR/sensitivity.json, sensitivity.csv, a tornado
// chart per ratio (plots/) and report.html.
#include <cctype>
#include <filesystem>
#include <iostream>

#include "app/commands/commands.hpp"
#include "app/output/atomic_file.hpp"
#include "app/output/folder_lock.hpp"
#include "app/scenario/scenario.hpp"
#include "app/study/cases.hpp"
#include "app/study/paired_verdict.hpp"
#include "app/study/sensitivity.hpp"
#include "engine/recording/number_text.hpp"
#include "report/html.hpp"
#include "report/provenance.hpp"
#include "report/sensitivity_report.hpp"

namespace elbowsim {

namespace {

using Json = nlohmann::ordered_json;

int usage_error(const std::string& message) {
  std::cerr << "error: sensitivity: " << message << '\n';
  return exit_bad_input;
}

// A folder name from a parameter as given: "robot.planar.links[*].mass" ->
// "robot_planar_links_mass".
std::string slug(const std::string& given) {
  std::string out;
  for (char c : given) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) != 0;
    if (keep) out += c;
    else if (!out.empty() && out.back() != '_') out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

struct Point {
  std::string name;  // its folder under points/
  std::vector<std::pair<std::string, double>> held;
  std::string what;  // "every parameter drawn", "<given> held at <value>"
};

void write_csv(const std::filesystem::path& path, const Json& doc) {
  write_atomically(path, [&](std::ostream& out) {
    out << "metric,rank,parameter,law,end,value,ratio,ci95_low,ci95_high,outcome,swing,effect\n";
    for (const Json& m : doc["metrics"]) {
      const auto cell = [](const Json& j, const char* key, int index = -1) {
        if (!j.contains(key)) return std::string();
        const Json& v = index < 0 ? j[key] : j[key][index];
        return v.is_number() ? round_trip(v.get<double>()) : std::string();
      };
      const Json& n = m["nominal"];
      out << m["metric"].get<std::string>() << ",0,(every parameter drawn),,,," << cell(n, "ratio") << ','
          << cell(n, "ci95", 0) << ',' << cell(n, "ci95", 1) << ',' << n["outcome"].get<std::string>()
          << ",,\n";
      int rank = 0;
      for (const Json& f : m["factors"]) {
        ++rank;
        for (const char* end : {"low", "high"}) {
          const Json& e = f[end];
          out << m["metric"].get<std::string>() << ',' << rank << ",\"" << f["given"].get<std::string>()
              << "\",\"" << f["law"].get<std::string>() << "\"," << end << ',' << cell(e, "value") << ','
              << cell(e, "ratio") << ',' << cell(e, "ci95", 0) << ',' << cell(e, "ci95", 1) << ','
              << e["outcome"].get<std::string>() << ',' << round_trip(f["swing"].get<double>()) << ','
              << f["effect"].get<std::string>() << '\n';
        }
      }
    }
  });
}

}  // namespace

int sensitivity_command(const MonteCarloArguments& args) {
  if (args.samples < 2) return usage_error("--samples must be at least 2");
  Scenario base;
  std::string case_name;
  std::filesystem::path folder;
  try {
    base = load_scenario(args.scenario, args.sets);
    if (base.uncertainty.parameters.empty())
      return usage_error(args.scenario +
                         " has no uncertainty: parameters to hold (scenarios/README.md, uncertainty)");
    if (base.variants.size() < 2)
      return usage_error("a verdict's sensitivity needs two variants to compare (" + args.scenario + " has " +
                         std::to_string(base.variants.size()) + ")");
    if (!args.variants.empty() && args.variants.size() != 2)
      return usage_error("sensitivity: --variants needs two variants, A,B (got " +
                         std::to_string(args.variants.size()) + ")");
    const std::vector<study::StudyCase> cases = study::select_cases(base, args.cases);
    if (cases.size() != 1)
      return usage_error("one case at a time: name it with --case AXIS=LEVEL,... (the selection has " +
                         std::to_string(cases.size()) + " cases)");
    case_name = cases.front().name;
    folder = args.out.value_or(base.output.folder + "/sensitivity");
  } catch (const ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_bad_input;
  } catch (const std::invalid_argument& e) {
    return usage_error(e.what());
  }

  const std::vector<study::SensitivityFactor> factors = study::sensitivity_factors(base.uncertainty);
  std::vector<Point> points{{"every_parameter_drawn", {}, "every parameter drawn"}};
  for (const study::SensitivityFactor& f : factors)
    for (const auto& [end, u] : {std::pair{"low", f.low}, std::pair{"high", f.high}})
      points.push_back({slug(f.given) + "-" + end, {{f.given, u}},
                        f.given + " held at " + study::factor_value(f, u)});

  std::vector<Json> pairs;  // [point] montecarlo.json's pairs[0]
  try {
    const FolderLock lock(folder);
    for (std::size_t k = 0; k < points.size(); ++k) {
      std::cout << "sensitivity: point " << k + 1 << " of " << points.size() << ": " << points[k].what << '\n';
      MonteCarloArguments point = args;
      // One pair: the two named, else the scenario's first two (the others are not run).
      if (point.variants.empty())
        point.variants = {base.variants[0].first, base.variants[1].first};
      point.out = (folder / "points" / points[k].name).string();
      point.held = points[k].held;
      point.report = false;
      const int code = montecarlo_command(point);
      if (code != exit_ok) {
        std::cerr << "error: sensitivity: the point " << points[k].what << " stopped (exit " << code
                  << "); nothing written in " << folder.string() << " but its points/\n";
        return code;
      }
      std::filesystem::path result = *point.out;
      if (!case_name.empty()) result /= case_name;
      const Json doc = report::html::read_json(result / "montecarlo.json");
      if (doc["pairs"].empty()) return usage_error("montecarlo wrote no pair to compare");
      pairs.push_back(doc["pairs"][0]);
    }
    const std::string a = pairs.front()["a"].get<std::string>(), b = pairs.front()["b"].get<std::string>();
    Json doc;
    doc["provenance"] = report::provenance_json();
    doc["scenario"] = base.model.name;
    doc["file"] = args.scenario;
    if (!case_name.empty()) doc["case"] = case_name;
    doc["seed"] = args.seed.value_or(base.uncertainty.seed);
    doc["samples"] = args.samples;
    doc["held_at"] = "each parameter alone at either end of its range (a normal law at ±2σ), the "
                     "others drawn as usual, on the same draws";
    Json listed = Json::array();
    for (std::size_t k = 0; k < points.size(); ++k)
      listed.push_back({{"point", points[k].name}, {"what", points[k].what}});
    doc["points"] = listed;
    doc["metrics"] = Json::array();
    std::cout << base.model.name << (case_name.empty() ? "" : " " + case_name) << ": sensitivity of "
              << counted(static_cast<long long>(factors.size()), "parameter") << " in " << folder.string()
              << "\n";
    for (const study::ComparedQuantity& q : study::kCompared) {
      if (!q.ratio) continue;
      std::vector<study::FactorPoints> at;
      for (std::size_t f = 0; f < factors.size(); ++f)
        at.push_back({factors[f], study::ratio_at(pairs[1 + 2 * f], q.metric),
                      study::ratio_at(pairs[2 + 2 * f], q.metric)});
      doc["metrics"].push_back(
          study::sensitivity_of(q.metric, q.what, a, b, study::ratio_at(pairs[0], q.metric), at));
      for (const Json& line : doc["metrics"].back()["sentences"])
        std::cout << "  " << line.get<std::string>() << '\n';
    }
    write_atomically(folder / "sensitivity.json", [&](std::ostream& out) { out << doc.dump(2) << '\n'; });
    write_csv(folder / "sensitivity.csv", doc);
    report::write_sensitivity_plots(folder);
    if (args.report) report::write_sensitivity_report(folder);
  } catch (const ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_bad_input;
  } catch (const std::exception& e) {
    std::cerr << "error: sensitivity: " << e.what() << '\n';
    return exit_io;
  }
  return exit_ok;
}

}  // namespace elbowsim
