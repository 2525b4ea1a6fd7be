// elbowsim montecarlo: the scenario's uncertain plant parameters drawn N
// times (its uncertainty: section), each draw applied to every variant (a
// paired comparison) while the controller keeps the nominal model; then
// samples.csv, montecarlo.json and a report with the verdict. With a study:
// section, the same for every case (one level of each axis) in its own
// folder, each case with plants drawn of its own (study::case_seed), and
// study.csv, study.json and a report over the cases. The same seed gives the
// same bytes, whatever --jobs.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <thread>

#include "app/commands/commands.hpp"
#include "app/commands/interrupt.hpp"
#include "app/commands/step_check.hpp"
#include "app/output/atomic_file.hpp"
#include "app/output/folder_lock.hpp"
#include "app/scenario/scenario.hpp"
#include "app/scenario/yaml_reader.hpp"
#include "app/study/cases.hpp"
#include "app/study/draws.hpp"
#include "app/study/paired_verdict.hpp"
#include "app/study/study_table.hpp"
#include "engine/control/inverse_kinematics.hpp"
#include "engine/recording/number_text.hpp"
#include "engine/run/simulator.hpp"
#include "engine/run/warnings.hpp"
#include "report/montecarlo_report.hpp"
#include "report/provenance.hpp"
#include "report/statistics.hpp"
#include "report/study_report.hpp"

namespace elbowsim {

namespace {

using Json = nlohmann::ordered_json;

// The metrics a study summarises, with their scales (their units are the
// vocabulary's): the net energy in can be negative (the motors feed back more
// than they draw), the others never are (their BCa interval, within the
// bootstrap means' range, never is either; its acceleration is taken on a log
// scale).
struct StudiedMetric {
  const char* name;
  report::Scale scale;
};
const StudiedMetric kMetrics[] = {
    {metric::energy_in, report::Scale::linear},       {metric::energy_drawn, report::Scale::log},
    {metric::energy_regenerated, report::Scale::log}, {metric::joule, report::Scale::log},
    {metric::hand_error_rms, report::Scale::log},     {metric::hand_error_max, report::Scale::log},
    {metric::hand_error_final, report::Scale::log}};

struct Sample {
  bool valid = false;
  std::string failure;
  std::map<std::string, double> metrics;
  UnplannedContact unplanned;  // the part the scene does not plan to rest that rested longest
  long slips = 0;              // slip events: a sticking contact that began to slide (any body)
};

// The elbows the task holds above the table (the plan's `held`): resting, they
// are unplanned contact as a link's own solid is.
std::vector<int> held_elbows(const Scenario& s) {
  std::vector<int> held;
  if (s.experiment.task.elbow_clearance <= 0) return held;
  for (const std::string& name : s.experiment.task.elbows)
    for (std::size_t k = 0; k < s.model.elbows.size(); ++k)
      if (s.model.elbows[k].name == name) held.push_back(int(k));
  return held;
}

// One variant as the study runs it: its nominal scenario and what its
// controller believes (the nominal plant, or its controller.model).
struct Variant {
  std::string name;  // "" without variants
  Scenario nominal;
  std::shared_ptr<const Model> believed;
};

// One case of the study (the whole scenario without a study): its variants,
// loaded before anything runs, and the folder it writes.
struct CasePlan {
  study::StudyCase study_case;
  std::vector<Variant> variants;
  std::filesystem::path folder;
};

Scenario load_variant(const MonteCarloArguments& args, const study::StudyCase& c,
                      const std::string& name, const std::vector<std::string>& extra) {
  std::vector<std::string> sets = args.sets;
  sets.insert(sets.end(), extra.begin(), extra.end());
  return load_scenario_case(args.scenario, c.levels, name, sets);
}

Sample run_one(const Scenario& scenario, const std::shared_ptr<const Model>& believed) {
  Sample s;
  Experiment x = scenario.experiment;
  x.controller_model = believed;
  try {
    const RunResult r = simulate(scenario.model, x, RunOptions{scenario.output.every, {}, &interrupt_flag()});
    s.valid = r.valid;
    s.failure = r.failure;
    for (const StudiedMetric& k : kMetrics)
      if (const Metric* m = r.metrics.find(k.name)) s.metrics[k.name] = m->values.front();
    s.unplanned = longest_unplanned_contact(r.metrics, held_elbows(scenario));
    for (const ContactEvent& e : r.events) s.slips += e.kind == ContactEvent::Kind::slip;
  } catch (const PlanError& e) {
    s.failure = std::string("the plan failed: ") + e.what();
  }
  return s;
}

// The seed of draw `d`'s sensor noise: sensors.seed + d, and for a study
// case mixed with the case's name as its plants are (study::case_seed).
std::uint64_t sensor_seed(const Scenario& nominal, const std::string& case_name, long d) {
  const std::uint64_t seed =
      nominal.experiment.controller.loop.sensors.seed + static_cast<std::uint64_t>(d);
  return study::case_seed(seed, case_name);
}

// Draw `d` of variant `v`: its drawn plant under the nominal controller. The
// sensors' noise differs from draw to draw too (sensor_seed).
Sample run_draw(const MonteCarloArguments& args, const study::StudyCase& c, const Variant& v,
                const study::Draw& d) {
  Scenario drawn;
  try {
    drawn = load_variant(args, c, v.name, study::draw_overrides(v.nominal.uncertainty, d));
  } catch (const ScenarioError& e) {
    Sample s;
    s.failure = std::string("the drawn values are not a valid scenario: ") + e.what();
    return s;
  }
  drawn.experiment.controller.loop.sensors.seed = sensor_seed(v.nominal, c.name, d.index);
  return run_one(drawn, v.believed);
}

// Calls task(k) for k = 0 .. count-1 on `jobs` threads (this one included).
template <class Task>
void parallel_for(std::size_t count, int jobs, const Task& task) {
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t k; (k = next++) < count;) task(k);
  };
  std::vector<std::thread> threads;
  for (int j = 1; j < jobs && static_cast<std::size_t>(j) < count; ++j) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
}

// One case's runs, on `jobs` threads in one pool, results by index (the order
// of completion does not matter): first the accuracy floor's runs, each
// variant's nominal run at half its step (the longest runs: they go first,
// so that no thread is left with one at the end) and at its step, then every
// (draw, variant).
struct CaseRuns {
  std::vector<Sample> half, full;          // [variant] the floor's nominal runs
  std::vector<std::vector<Sample>> draws;  // [draw][variant]
};

CaseRuns run_case_runs(const MonteCarloArguments& args, const CasePlan& plan,
                       const std::vector<study::Draw>& draws) {
  const std::vector<Variant>& variants = plan.variants;
  const std::size_t nv = variants.size(), floor_runs = 2 * nv, total = floor_runs + draws.size() * nv;
  std::vector<Scenario> halved;  // loaded here: a ScenarioError leaves before any run
  for (const Variant& v : variants) halved.push_back(at_half_step(v.nominal));
  // The halved run's controller believes the halved scenario; its plan stays
  // sampled on the nominal step (task.plan_step): the floor is integration error.
  std::vector<std::shared_ptr<const Model>> halved_believed;
  for (const Scenario& h : halved)
    halved_believed.push_back(std::make_shared<const Model>(h.experiment.believed(h.model)));
  CaseRuns out{std::vector<Sample>(nv), std::vector<Sample>(nv),
               std::vector<std::vector<Sample>>(draws.size(), std::vector<Sample>(nv))};
  std::atomic<std::size_t> done{0};
  const std::string label = plan.study_case.name.empty() ? "" : " " + plan.study_case.name;
  parallel_for(total, args.jobs, [&](std::size_t k) {
    if (interrupt_flag().load(std::memory_order_relaxed)) return;  // start nothing more
    if (k < nv) {
      out.half[k] = run_one(halved[k], halved_believed[k]);
    } else if (k < floor_runs) {
      out.full[k - nv] = run_one(variants[k - nv].nominal, variants[k - nv].believed);
    } else {
      const std::size_t r = k - floor_runs;
      out.draws[r / nv][r % nv] = run_draw(args, plan.study_case, variants[r % nv], draws[r / nv]);
    }
    const std::size_t finished = ++done;
    if (finished % std::max<std::size_t>(1, total / 10) == 0)
      std::cerr << "montecarlo" + label + ": " << finished << " of " << total << " runs\n";
  });
  return out;
}

// The integration floor of the hand error: each variant's nominal run at its
// step and at half of it.
Json accuracy_floors(const std::vector<Variant>& variants, const CaseRuns& runs) {
  const auto rms = [](const Sample& s) {
    const auto it = s.metrics.find(metric::hand_error_rms);
    return s.valid && it != s.metrics.end() ? it->second : std::nan("");
  };
  Json floors;
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const Sample &full = runs.full[i], &half = runs.half[i];
    Json f;
    f["step"] = variants[i].nominal.model.options.step;
    f["hand_error_rms_step"] = rms(full);
    f["hand_error_rms_half_step"] = rms(half);
    f["floor"] = std::abs(rms(full) - rms(half));
    f["nominal_valid"] = full.valid && half.valid;
    floors[variants[i].name.empty() ? "run" : variants[i].name] = f;
  }
  return floors;
}

// The samples of variants ia and ib as a pair: the draws where both are valid.
Json pair_json(const std::vector<Variant>& variants, std::size_t ia, std::size_t ib,
               const std::vector<study::Draw>& draws,
               const std::vector<std::vector<Sample>>& samples, const Json& floors,
               std::uint64_t seed) {
  study::PairedSamples pair;
  pair.a = variants[ia].name;
  pair.b = variants[ib].name;
  pair.draws = static_cast<long>(samples.size());
  pair.floor_a = floors[pair.a.empty() ? "run" : pair.a].value("floor", NAN);
  pair.floor_b = floors[pair.b.empty() ? "run" : pair.b].value("floor", NAN);
  for (std::size_t d = 0; d < samples.size(); ++d) {
    const Sample &sa = samples[d][ia], &sb = samples[d][ib];
    if (!sa.valid || !sb.valid) {
      ++pair.dropped;
      continue;
    }
    for (const study::ComparedQuantity& q : study::kCompared)
      if (sa.metrics.count(q.metric) && sb.metrics.count(q.metric)) {
        pair.a_values[q.metric].push_back(sa.metrics.at(q.metric));
        pair.b_values[q.metric].push_back(sb.metrics.at(q.metric));
        pair.draw_index[q.metric].push_back(draws[d].index);
      }
  }
  return study::paired_verdict(pair, seed);
}

void write_samples_csv(const std::filesystem::path& path, const std::string& case_name,
                       const std::vector<Variant>& variants, const std::vector<study::Draw>& draws,
                       const std::vector<std::vector<Sample>>& samples) {
  write_atomically(path, [&](std::ostream& out) {
    out << "draw,variant,valid,sensor_seed";
    for (const UncertainParameter& p : variants.front().nominal.uncertainty.parameters)
      out << "," << p.key;
    for (const StudiedMetric& k : kMetrics)
      out << "," << k.name << " [" << metric_unit(k.name) << "]";
    out << ",unplanned_contact_share,unplanned_contact_body,slips,failure\n";
    for (std::size_t d = 0; d < draws.size(); ++d)
      for (std::size_t v = 0; v < variants.size(); ++v) {
        const Sample& s = samples[d][v];
        out << draws[d].index << "," << variants[v].name << "," << (s.valid ? "true" : "false")
            << "," << sensor_seed(variants[v].nominal, case_name, draws[d].index);
        const auto& params = variants[v].nominal.uncertainty.parameters;
        for (std::size_t j = 0; j < params.size(); ++j)
          out << "," << round_trip(study::drawn_value(params[j], draws[d].u[j]));
        for (const StudiedMetric& k : kMetrics) {
          const auto it = s.metrics.find(k.name);
          out << "," << (it == s.metrics.end() ? std::string() : round_trip(it->second));
        }
        out << "," << round_trip(s.unplanned.share) << "," << s.unplanned.body << "," << s.slips;
        std::string failure = s.failure;
        std::replace(failure.begin(), failure.end(), '"', '\'');
        out << ",\"" << failure << "\"\n";
      }
  });
}

// Per variant, how often its contacts slipped (a sticking contact that began
// to slide: coarse sensors make a resting elbow chatter), into doc["slips"],
// and a verdict line for each variant that slipped: its elbow did not stay put.
void slip_counts(const std::vector<Variant>& variants, const std::vector<std::vector<Sample>>& samples,
                 Json& doc, Json& verdict) {
  doc["slips"] = Json::object();
  for (std::size_t v = 0; v < variants.size(); ++v) {
    std::vector<long> counts;
    for (const auto& draw : samples) counts.push_back(draw[v].slips);
    std::sort(counts.begin(), counts.end());
    const long with = std::count_if(counts.begin(), counts.end(), [](long n) { return n > 0; });
    const long median = counts.empty() ? 0 : counts[counts.size() / 2];
    const long most = counts.empty() ? 0 : counts.back();
    const std::string name = variants[v].name.empty() ? "run" : variants[v].name;
    doc["slips"][name] = {{"draws_with_slips", with}, {"median", median}, {"max", most}};
    if (with == 0) continue;
    verdict.push_back(name + ": its contacts slipped in " + std::to_string(with) + " of " +
                      std::to_string(counts.size()) + " draws (median " + std::to_string(median) +
                      (median == 1 ? " slip event" : " slip events") + " a run, at most " +
                      std::to_string(most) +
                      "): a resting elbow that slips does not stay where the plan put it "
                      "(montecarlo.json slips; samples.csv slips)");
  }
}

// Per variant, the draws in which a part the scene does not plan to rest
// (a link's own solid, an elbow held up) rested on the table for more than
// warnings.unplanned_contact_share of the run, into doc["unplanned_contact"];
// and a verdict line for each variant that has any: those draws compare an
// arm leaning on that part.
void unplanned_contact(const std::vector<Variant>& variants, const std::vector<study::Draw>& draws,
                       const std::vector<std::vector<Sample>>& samples, Json& doc, Json& verdict) {
  doc["unplanned_contact"] = Json::object();
  for (std::size_t v = 0; v < variants.size(); ++v) {
    const double threshold = variants[v].nominal.model.warn.unplanned_contact_share;
    Json entry{{"threshold", threshold}, {"draws", Json::array()}, {"largest_share", 0.0}, {"body", ""}};
    std::set<std::string> bodies;
    for (std::size_t d = 0; d < samples.size(); ++d) {
      const UnplannedContact& u = samples[d][v].unplanned;
      if (!(u.share > threshold)) continue;
      entry["draws"].push_back(draws[d].index);
      bodies.insert(u.body);
      if (u.share > entry["largest_share"].get<double>()) entry["largest_share"] = u.share, entry["body"] = u.body;
    }
    const std::string name = variants[v].name.empty() ? "run" : variants[v].name;
    doc["unplanned_contact"][name] = entry;
    if (entry["draws"].empty()) continue;
    std::string names;
    for (const std::string& b : bodies) names += (names.empty() ? "" : ", ") + b;
    verdict.push_back(name + ": in " + std::to_string(entry["draws"].size()) + " of " +
                      std::to_string(samples.size()) +
                      " draws a part the scene does not plan to "
                      "rest lay on the table for more than " +
                      percent(threshold) + " of the run (" + names + "; up to " +
                      percent(entry["largest_share"].get<double>()) +
                      "): those draws compare an arm leaning on it (montecarlo.json "
                      "unplanned_contact lists them)");
  }
}

// One variant's metric over its valid draws (`from`: the draw of each value):
// mean, median and the interval of the mean, or why there is none.
Json metric_json(const StudiedMetric& k, const std::vector<double>& x,
                 const std::vector<long>& from, std::uint64_t seed) {
  const report::Estimate e =
      report::estimate_mean(x, k.scale, study::kConfidenceLevel, study::kBootstrapResamples, seed);
  Json m{{"unit", metric_unit(k.name)},
         {"scale", k.scale == report::Scale::log ? "log" : "linear"},
         {"valid", e.n},
         {"mean", e.mean},
         {"median", e.median}};
  if (e.ci)
    m["ci95"] = {e.ci->low, e.ci->high};
  else
    m["no_interval"] = e.no_interval;
  if (!e.involved.empty()) {
    Json involved = Json::array();
    for (std::size_t i : e.involved) involved.push_back(from[i]);
    m["draws"] = involved;
  }
  return m;
}

int usage_error(const std::string& message) {
  std::cerr << "error: montecarlo: " << message << '\n';
  return exit_bad_input;
}

// Loads every case's variants (nothing runs before all of them load).
std::vector<CasePlan> plan_cases(const MonteCarloArguments& args, const Scenario& base,
                                 const std::vector<study::StudyCase>& cases,
                                 const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& [name, overrides] : base.variants) names.push_back(name);
  if (!args.variants.empty()) {  // --variants: these, in this order
    for (const std::string& name : args.variants)
      if (std::find(names.begin(), names.end(), name) == names.end())
        throw std::invalid_argument(
            "--variants: " + args.scenario + " has no variant \"" + name + "\" (" +
            (names.empty() ? "it has none)" : "it has " + loader::join({names.begin(), names.end()}) + ")"));
    for (std::size_t k = 0; k < args.variants.size(); ++k)
      if (std::find(args.variants.begin(), args.variants.begin() + long(k), args.variants[k]) !=
          args.variants.begin() + long(k))
        throw std::invalid_argument("--variants names " + args.variants[k] + " twice");
    names = args.variants;
  }
  if (names.empty()) names.push_back("");
  std::vector<std::string> base_keys;
  for (const auto& p : base.uncertainty.parameters) base_keys.push_back(p.key);
  std::vector<CasePlan> plans;
  for (const study::StudyCase& c : cases) {
    CasePlan plan{c, {}, c.name.empty() ? folder : folder / c.name};
    for (const std::string& name : names) {
      Scenario nominal = load_variant(args, c, name, {});
      std::vector<std::string> keys;
      for (const auto& p : nominal.uncertainty.parameters) keys.push_back(p.key);
      if (keys != base_keys)
        throw std::invalid_argument((c.name.empty() ? "" : "case " + c.name + ", ") + "variant " + name +
                                    " changes which keys are uncertain; a paired study needs the "
                                    "same parameters in every variant and case");
      auto believed = std::make_shared<const Model>(nominal.experiment.believed(nominal.model));
      plan.variants.push_back({name, std::move(nominal), std::move(believed)});
    }
    plans.push_back(std::move(plan));
  }
  return plans;
}

// One case's study: its runs, then montecarlo.json (returned), samples.csv and
// the report in its folder.
Json run_case(const MonteCarloArguments& args, const Scenario& base, const CasePlan& plan,
              const std::vector<study::Draw>& draws, std::uint64_t seed) {
  const std::vector<Variant>& variants = plan.variants;
  const CaseRuns runs = run_case_runs(args, plan, draws);
  // Interrupted: some runs stopped early; statistics of them would be wrong,
  // so this case writes nothing (the cases done before it are kept).
  if (interrupt_exit_code()) return Json();
  const Json floors = accuracy_floors(variants, runs);
  const auto& samples = runs.draws;
  // The samples first: whatever the statistics make of them, they are kept.
  std::filesystem::create_directories(plan.folder);
  write_samples_csv(plan.folder / "samples.csv", plan.study_case.name, variants, draws, samples);

  Json doc;
  doc["provenance"] = report::provenance_json();
  doc["scenario"] = base.model.name;
  doc["file"] = args.scenario;
  if (!plan.study_case.name.empty()) {
    doc["case"] = plan.study_case.name;
    for (std::size_t a = 0; a < base.study.size(); ++a)
      doc["levels"][base.study[a].name] = plan.study_case.levels[a];
  }
  doc["seed"] = seed;
  doc["case_seed"] = study::case_seed(seed, plan.study_case.name);  // of this case's draws
  doc["samples"] = args.samples;
  doc["confidence_level"] = study::kConfidenceLevel;
  doc["bootstrap_resamples"] = study::kBootstrapResamples;
  doc["min_interval_draws"] = report::kMinIntervalValues;
  Json names = Json::array();
  for (const Variant& v : variants) names.push_back(v.name.empty() ? "run" : v.name);
  doc["variants"] = names;
  Json params = Json::array();
  for (std::size_t j = 0; j < base.uncertainty.parameters.size(); ++j) {
    const UncertainParameter& p = base.uncertainty.parameters[j];
    Json q{{"key", p.key}, {"given", p.given}};
    q["law"] = p.law == UncertainParameter::Law::uniform  ? "uniform"
               : p.law == UncertainParameter::Law::normal ? "normal"
                                                           : "range";
    if (p.law == UncertainParameter::Law::range) q["range"] = {p.low, p.high};
    else q["spread"] = p.spread;
    for (const Variant& v : variants)
      q["nominal"][v.name.empty() ? "run" : v.name] = v.nominal.uncertainty.parameters[j].nominal;
    params.push_back(q);
  }
  doc["parameters"] = params;
  if (!args.held.empty()) {
    Json held = Json::object();  // given -> the deviation or value every draw has
    for (const auto& [given, u] : args.held) held[given] = u;
    doc["held"] = held;
  }
  doc["accuracy_floor"] = floors;
  Json invalid = Json::array();
  doc["metrics"] = Json::object();  // stays empty when every run is invalid
  for (std::size_t v = 0; v < variants.size(); ++v) {
    const std::string vname = names[v].get<std::string>();
    for (const StudiedMetric& k : kMetrics) {
      std::vector<double> x;
      std::vector<long> from;  // the draw of each value
      Json all = Json::array();
      for (std::size_t d = 0; d < samples.size(); ++d) {
        const Sample& s = samples[d][v];
        const auto it = s.metrics.find(k.name);
        const bool ok = s.valid && it != s.metrics.end();
        if (ok) x.push_back(it->second), from.push_back(draws[d].index);
        all.push_back(ok ? Json(it->second) : Json(nullptr));
      }
      doc["draws"][vname][k.name] = all;
      if (x.empty()) continue;
      doc["metrics"][vname][k.name] = metric_json(k, x, from, seed);
    }
    for (std::size_t d = 0; d < samples.size(); ++d)
      if (!samples[d][v].valid)
        invalid.push_back({{"draw", draws[d].index}, {"variant", vname}, {"failure", samples[d][v].failure}});
  }
  Json pairs = Json::array(), verdict = Json::array();
  for (std::size_t a = 0; a < variants.size(); ++a)
    for (std::size_t b = a + 1; b < variants.size(); ++b) {
      pairs.push_back(pair_json(variants, a, b, draws, samples, floors, seed));
      for (const Json& line : pairs.back()["verdict"]) verdict.push_back(line);
    }
  if (variants.size() < 2) verdict.push_back("one variant: nothing to compare (distributions only)");
  unplanned_contact(variants, draws, samples, doc, verdict);
  slip_counts(variants, samples, doc, verdict);
  doc["pairs"] = pairs;
  doc["invalid"] = invalid;
  doc["verdict"] = verdict;

  write_atomically(plan.folder / "montecarlo.json", [&](std::ostream& out) { out << doc.dump(2) << '\n'; });
  if (args.report) report::write_montecarlo_report(plan.folder);
  return doc;
}

}  // namespace

int montecarlo_command(const MonteCarloArguments& args) {
  if (args.samples < 2) return usage_error("--samples must be at least 2");
  if (args.jobs < 1) return usage_error("--jobs must be at least 1");
  Scenario base;
  std::vector<CasePlan> plans;
  std::filesystem::path folder;
  try {
    base = load_scenario(args.scenario, args.sets);
    if (base.uncertainty.parameters.empty())
      return usage_error(args.scenario + " has no uncertainty: parameters to draw (scenarios/README.md, uncertainty)");
    folder = args.out.value_or(base.output.folder + "/montecarlo");
    for (const auto& [given, u] : args.held)
      if (std::none_of(base.uncertainty.parameters.begin(), base.uncertainty.parameters.end(),
                       [&](const UncertainParameter& p) { return p.given == given; }))
        return usage_error("no uncertain parameter " + given + " to hold");
    const std::vector<study::StudyCase> cases = study::select_cases(base, args.cases);
    plans = plan_cases(args, base, cases, folder);
  } catch (const ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_bad_input;
  } catch (const std::invalid_argument& e) {
    return usage_error(e.what());
  }
  const std::uint64_t seed = args.seed.value_or(base.uncertainty.seed);
  // Each case draws its own plants (study::case_seed).
  const auto draws_of = [&](const CasePlan& plan) {
    const std::uint64_t s = study::case_seed(seed, plan.study_case.name);
    std::vector<study::Draw> draws;
    for (long i = 0; i < args.samples; ++i) {
      draws.push_back(study::draw_parameters(base.uncertainty, s, i));
      // Held after the draw: the other parameters keep the values they draw without it.
      for (std::size_t j = 0; j < base.uncertainty.parameters.size(); ++j)
        for (const auto& [given, u] : args.held)
          if (base.uncertainty.parameters[j].given == given) draws.back().u[j] = u;
    }
    return draws;
  };

  std::vector<Json> docs;
  try {
    const FolderLock lock(folder);  // one study at a time in a folder
    install_interrupt_handlers();
    for (std::size_t k = 0; k < plans.size(); ++k) {
      const auto started = std::chrono::steady_clock::now();
      Json doc = run_case(args, base, plans[k], draws_of(plans[k]), seed);
      if (interrupt_exit_code()) {
        // A case whose files were begun is whole (the signal came while they were written).
        const std::size_t complete = k + (doc.is_null() ? 0 : 1);
        std::cerr << "interrupted: " << complete << " of "
                  << counted(static_cast<long long>(plans.size()), "case") << " complete in "
                  << folder.string();
        if (complete < plans.size())
          std::cerr << "; case "
                    << (plans[complete].study_case.name.empty() ? "(the study)"
                                                                : plans[complete].study_case.name)
                    << " and the rest not written";
        std::cerr << (base.study.empty() ? "" : ", nor the study's tables") << '\n';
        return interrupt_exit_code();
      }
      docs.push_back(std::move(doc));
      const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - started;
      const std::string& name = plans[k].study_case.name;
      std::cout << base.model.name << (name.empty() ? "" : " " + name) << ": " << args.samples
                << " draws x "
                << counted(static_cast<long long>(plans[k].variants.size()), "variant") << " (seed "
                << seed << ", "
                << counted(static_cast<long long>(docs.back()["invalid"].size()), "invalid run")
                << ") in " << plans[k].folder.string();
      if (plans.size() > 1) std::cout << " [case " << k + 1 << " of " << plans.size() << "]";
      char took[32];  // printed only: the files stay byte-identical
      std::snprintf(took, sizeof took, ", %.1f s wall\n", wall.count());
      std::cout << took;
      for (const Json& line : docs.back()["verdict"]) std::cout << "  " << line.get<std::string>() << "\n";
    }
    if (!base.study.empty() && interrupt_exit_code()) {
      std::cerr << "interrupted: every case is complete in " << folder.string()
                << "; the study's tables not written\n";
      return interrupt_exit_code();
    }
    if (!base.study.empty()) {
      std::vector<study::StudyCase> cases;
      for (const CasePlan& p : plans) cases.push_back(p.study_case);
      const Json table = study::study_document(base, args.scenario, cases, docs);
      write_atomically(folder / "study.json", [&](std::ostream& out) { out << table.dump(2) << '\n'; });
      study::write_study_csv(folder / "study.csv", table);
      if (args.report) report::write_study_report(folder);
      std::cout << base.model.name << ": study of "
                << counted(static_cast<long long>(plans.size()), "case") << " in "
                << folder.string() << " (study.csv, study.json"
                << (args.report ? ", report.html" : "") << ")\n";
    }
  } catch (const ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_bad_input;
  } catch (const std::exception& e) {
    std::cerr << "error: montecarlo: " << e.what() << '\n';
    return exit_io;
  }
  return exit_ok;
}

}  // namespace elbowsim
