#include "app/study/study_table.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "app/output/atomic_file.hpp"
#include "app/study/draws.hpp"
#include "app/study/paired_verdict.hpp"
#include "engine/recording/number_text.hpp"
#include "report/statistics.hpp"
#include "report/provenance.hpp"

namespace elbowsim::study {

namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kOutcomes[] = {"lower", "higher", "no significant difference", "no verdict"};

// Per pair "a/b" and metric: how many cases had each outcome, and which.
Json tally(const Json& cases) {
  Json out = Json::array();
  std::map<std::string, std::size_t> index;  // "a/b" -> position in out
  for (const Json& c : cases)
    for (const Json& p : c["pairs"]) {
      const std::string key = p.value("a", "") + "/" + p.value("b", "");
      if (!index.count(key)) {
        index[key] = out.size();
        Json t{{"a", p.value("a", "")}, {"b", p.value("b", "")}};
        for (const ComparedQuantity& q : kCompared)
          for (const char* o : kOutcomes) t[q.metric][o] = Json::array();
        out.push_back(t);
      }
      Json& t = out[index[key]];
      for (const ComparedQuantity& q : kCompared) {
        const char* m = q.metric;
        const std::string outcome = p.contains(m) ? p[m].value("outcome", "no verdict") : "no verdict";
        t[m][outcome].push_back(c["case"]);
      }
    }
  return out;
}

// The family-wise error of the study's corrected verdict, over its cases.
constexpr double kFamilyError = 0.05;
constexpr const char* kCorrected[] = {"lower", "higher", "not significant"};

// Holm's correction over the cases, per pair "a/b" and metric: each case's
// exact sign test on its draws (paired_verdict's sign_test_p) is one test of
// the family; a case without a verdict (too many invalid runs, below the
// accuracy floor) is none. Writes "holm" into each case's pair metric and,
// per pair and metric, "corrected": the cases by corrected outcome and the
// draws of the tested cases that favour each side.
void correct_over_cases(Json& rows, Json& tallies) {
  for (Json& t : tallies)
    for (const ComparedQuantity& q : kCompared) {
      const char* m = q.metric;
      std::vector<Json*> tested;
      std::vector<std::string> names;  // the case of each test
      std::vector<double> p;
      std::size_t a_lower = 0, b_lower = 0;
      for (Json& c : rows)
        for (Json& pair : c["pairs"]) {
          if (pair.value("a", "") != t.value("a", "") || pair.value("b", "") != t.value("b", ""))
            continue;
          if (!pair.contains(m) || !pair[m].contains("sign_test_p")) continue;
          if (pair[m].value("outcome", "no verdict") == "no verdict") continue;
          a_lower += pair[m].value("a_lower_draws", std::size_t{0});
          b_lower += pair[m].value("b_lower_draws", std::size_t{0});
          tested.push_back(&pair[m]);
          names.push_back(c.value("case", ""));
          p.push_back(pair[m]["sign_test_p"].get<double>());
        }
      const std::vector<bool> rejected = report::holm_rejects(p, kFamilyError);
      Json by_outcome;
      for (const char* o : kCorrected) by_outcome[o] = Json::array();
      for (std::size_t k = 0; k < tested.size(); ++k) {
        Json& x = *tested[k];
        const bool a_side = x.value("a_lower_draws", 0L) > x.value("b_lower_draws", 0L);
        x["holm"] = rejected[k] ? (a_side ? "lower" : "higher") : "not significant";
        by_outcome[x["holm"].get<std::string>()].push_back(names[k]);
      }
      Json& c = t["corrected"][m];
      c = {{"tests", tested.size()}, {"family_error", kFamilyError}};
      for (const char* o : kCorrected) c[o] = by_outcome[o];
      c["draws"] = {{"a_lower", a_lower}, {"b_lower", b_lower}};
    }
}

std::string count_sentence(const Json& t, const char* metric, std::string what, std::size_t n) {
  if (!what.empty()) what[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(what[0])));
  const std::string a = t.value("a", ""), b = t.value("b", "");
  std::string s = what + ", " + a + " against " + b + ":";
  bool first = true;
  for (const char* o : kOutcomes) {
    const std::size_t k = t[metric][o].size();
    if (k == 0) continue;
    s += std::string(first ? " " : "; ") + o + " in " + std::to_string(k) + " of " + std::to_string(n) +
         " cases";
    first = false;
  }
  // Each case's interval at 95 % alone: over many cases some fall by chance.
  // The corrected count keeps the chance of any false "lower" or "higher" at 5 %.
  const Json& h = t["corrected"][metric];
  const std::size_t tests = h.value("tests", std::size_t{0});
  if (tests > 1) {
    s += " (each case's 95 % interval alone); with Holm's correction over the " +
         std::to_string(tests) + " cases with a verdict (exact sign test on each case's draws, " +
         "family-wise error 5 %): lower in " + std::to_string(h["lower"].size()) + ", higher in " +
         std::to_string(h["higher"].size()) + ", not significant in " +
         std::to_string(h["not significant"].size());
  }
  const Json& d = h["draws"];
  const std::size_t al = d.value("a_lower", std::size_t{0}), bl = d.value("b_lower", std::size_t{0});
  if (al + bl > 0)
    s += "; " + a + " lower in " + std::to_string(al) + " of " + std::to_string(al + bl) +
         " draws, " + b + " lower in " + std::to_string(bl);
  return s;
}

// A CSV field, quoted (a reason holds commas).
std::string csv_text(const std::string& s) {
  if (s.empty()) return s;
  std::string out = "\"";
  for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

// ": draws 3, 17" after a reason, or "".
std::string draw_list(const Json& draws) {
  std::string out;
  for (const Json& d : draws) out += (out.empty() ? ": draws " : ", ") + d.dump();
  return out;
}

// Per variant whose contacts slipped in any case: a verdict line counting the
// cases and draws with slips and the most slip events a run (each case's
// montecarlo.json "slips"). Slips are a result, not a failure: coarse sensors
// make a resting elbow chatter on the table, and the plan no longer holds it.
void slip_sentences(const Json& rows, Json& verdict) {
  struct Count {
    std::size_t cases = 0, draws = 0;
    long most = 0;
    std::vector<std::string> where;
  };
  std::map<std::string, Count> counts;
  std::vector<std::string> order;
  for (const Json& c : rows) {
    if (!c.contains("slips")) continue;
    for (const auto& [variant, s] : c["slips"].items()) {
      if (!counts.count(variant)) order.push_back(variant);
      Count& k = counts[variant];
      const std::size_t with = s.value("draws_with_slips", std::size_t{0});
      if (with == 0) continue;
      ++k.cases;
      k.draws += with;
      k.most = std::max(k.most, s.value("max", 0L));
      k.where.push_back(c.value("case", ""));
    }
  }
  for (const std::string& v : order) {
    const Count& k = counts[v];
    if (k.cases == 0) continue;
    std::string s = v + ": its contacts slipped in " + std::to_string(k.cases) + " of " +
                    std::to_string(rows.size()) + " cases (" + std::to_string(k.draws) +
                    " draws in all, at most " + std::to_string(k.most) + " slip events a run";
    if (k.where.size() <= 6) {
      s += ": ";
      for (std::size_t i = 0; i < k.where.size(); ++i) s += (i ? ", " : "") + k.where[i];
    }
    verdict.push_back(s + "); study.csv slips, each case's montecarlo.json slips");
  }
}

}  // namespace

Json study_document(const Scenario& base, const std::string& file, const std::vector<StudyCase>& cases,
                    const std::vector<Json>& case_docs) {
  Json doc;
  doc["provenance"] = report::provenance_json();
  doc["scenario"] = base.model.name;
  doc["file"] = file;
  if (!case_docs.empty()) {
    doc["seed"] = case_docs.front().value("seed", 0UL);
    doc["samples"] = case_docs.front().value("samples", 0L);
    doc["min_interval_draws"] = case_docs.front().value("min_interval_draws", 0L);
    doc["variants"] = case_docs.front()["variants"];
  }
  Json axes = Json::array();
  for (const Scenario::StudyAxis& a : base.study) {
    Json levels = Json::array();
    for (const auto& [name, overrides] : a.levels) levels.push_back(name);
    axes.push_back({{"name", a.name}, {"levels", levels}});
  }
  doc["axes"] = axes;
  Json rows = Json::array();
  for (std::size_t k = 0; k < cases.size() && k < case_docs.size(); ++k) {
    const Json& d = case_docs[k];
    Json c{{"case", cases[k].name}, {"folder", cases[k].name}};
    c["levels"] = d.value("levels", Json::object());
    c["invalid_runs"] = d["invalid"].size();
    const Json measured = d.value("metrics", Json::object());  // none: every run invalid
    for (const auto& [variant, metrics] : measured.items())
      for (const ComparedQuantity& q : kCompared)
        if (metrics.contains(q.metric)) {
          const Json& x = metrics[q.metric];
          Json& y = c["metrics"][variant][q.metric];
          y = {{"mean", x["mean"]}, {"median", x["median"]}};
          if (x.contains("ci95"))
            y["ci95"] = x["ci95"];
          else
            y["no_interval"] = x.value("no_interval", "");
        }
    for (const auto& [variant, f] : d["accuracy_floor"].items()) c["accuracy_floor"][variant] = f["floor"];
    if (d.contains("slips")) c["slips"] = d["slips"];
    Json pairs = Json::array();
    for (const Json& p : d["pairs"]) {
      Json q{{"a", p["a"]}, {"b", p["b"]}, {"pairs_with_an_invalid_run", p["pairs_with_an_invalid_run"]}};
      for (const ComparedQuantity& k : kCompared)
        if (p.contains(k.metric)) q[k.metric] = p[k.metric];
      pairs.push_back(q);
    }
    c["pairs"] = pairs;
    rows.push_back(c);
  }
  Json tallies = tally(rows);
  correct_over_cases(rows, tallies);
  doc["cases"] = rows;
  doc["tally"] = tallies;
  Json verdict = Json::array();
  for (const Json& t : doc["tally"])
    for (const ComparedQuantity& q : kCompared)
      verdict.push_back(count_sentence(t, q.metric, q.what, rows.size()));
  slip_sentences(rows, verdict);
  doc["verdict"] = verdict;
  return doc;
}

void write_study_csv(const std::filesystem::path& path, const Json& study) {
  write_atomically(path, [&](std::ostream& out) {
    out << "case";
    for (const Json& a : study["axes"]) out << "," << a.value("name", "");
    out << ",a,b,invalid_runs";
    for (const ComparedQuantity& q : kCompared) {
      const std::string m = q.metric, unit = std::string(" [") + q.unit() + "]";
      if (q.ratio)
        out << "," << m << " ratio a/b," << m << " ratio low," << m << " ratio high";
      else
        out << "," << m << " difference a-b" << unit << "," << m << " difference low" << unit << ","
            << m << " difference high" << unit;
      out << "," << m << " a lower share," << m << " outcome," << m << " outcome (Holm)," << m
          << " sign test p," << m << " reason," << m << " mean a"
          << unit << "," << m << " mean b" << unit;
    }
    out << ",hand_error_rms floor a [m],hand_error_rms floor b [m],slips draws a,slips draws b,"
           "slips median a,slips median b\n";
    const auto number = [](const Json& x) {
      return x.is_number() ? round_trip(x.get<double>()) : std::string();
    };
    for (const Json& c : study["cases"]) {
      for (const Json& p : c["pairs"]) {
        const std::string a = p.value("a", ""), b = p.value("b", "");
        out << c.value("case", "");
        for (const Json& axis : study["axes"])
          out << "," << c["levels"].value(axis.value("name", ""), "");
        out << "," << a << "," << b << "," << c.value("invalid_runs", 0);
        for (const ComparedQuantity& q : kCompared) {
          const char* m = q.metric;
          const Json r = p.value(m, Json::object());
          const Json ci = r.value("ci95", Json::array());
          out << "," << number(r.value(q.ratio ? "ratio" : "difference", Json())) << ","
              << (ci.size() == 2 ? number(ci[0]) : "") << ","
              << (ci.size() == 2 ? number(ci[1]) : "") << "," << number(r.value("win_rate", Json()))
              << "," << r.value("outcome", "no verdict") << "," << r.value("holm", "")
              << "," << number(r.value("sign_test_p", Json())) << ","
              << csv_text(r.value("reason", "") + draw_list(r.value("draws", Json::array())));
          for (const std::string& v : {a, b}) {
            const Json mv = c.value("metrics", Json::object()).value(v, Json::object()).value(m, Json::object());
            out << "," << number(mv.value("mean", Json()));
          }
        }
        for (const std::string& v : {a, b})
          out << "," << number(c.value("accuracy_floor", Json::object()).value(v, Json()));
        const Json slips = c.value("slips", Json::object());
        for (const char* k : {"draws_with_slips", "median"})
          for (const std::string& v : {a, b}) {
            const Json n = slips.value(v, Json::object()).value(k, Json());
            out << "," << (n.is_number() ? std::to_string(n.get<long>()) : std::string());
          }
        out << "\n";
      }
    }
  });
}

}  // namespace elbowsim::study
