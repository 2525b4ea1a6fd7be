#include "app/study/study_table.hpp"

#include <cctype>
#include <cmath>
#include <map>

#include "app/output/atomic_file.hpp"
#include "app/study/draws.hpp"
#include "app/study/paired_verdict.hpp"
#include "engine/recording/number_text.hpp"
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

std::string count_sentence(const Json& t, const char* metric, std::string what, std::size_t n) {
  if (!what.empty()) what[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(what[0])));
  std::string s = what + ", " + t.value("a", "") + " against " + t.value("b", "") + ":";
  bool first = true;
  for (const char* o : kOutcomes) {
    const std::size_t k = t[metric][o].size();
    if (k == 0) continue;
    s += std::string(first ? " " : "; ") + o + " in " + std::to_string(k) + " of " + std::to_string(n) +
         " cases";
    first = false;
  }
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
  doc["cases"] = rows;
  doc["tally"] = tally(rows);
  Json verdict = Json::array();
  for (const Json& t : doc["tally"])
    for (const ComparedQuantity& q : kCompared)
      verdict.push_back(count_sentence(t, q.metric, q.what, rows.size()));
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
      out << "," << m << " a lower share," << m << " outcome," << m << " reason," << m << " mean a"
          << unit << "," << m << " mean b" << unit;
    }
    out << ",hand_error_rms floor a [m],hand_error_rms floor b [m]\n";
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
              << "," << r.value("outcome", "no verdict") << ","
              << csv_text(r.value("reason", "") + draw_list(r.value("draws", Json::array())));
          for (const std::string& v : {a, b}) {
            const Json mv = c.value("metrics", Json::object()).value(v, Json::object()).value(m, Json::object());
            out << "," << number(mv.value("mean", Json()));
          }
        }
        for (const std::string& v : {a, b})
          out << "," << number(c.value("accuracy_floor", Json::object()).value(v, Json()));
        out << "\n";
      }
    }
  });
}

}  // namespace elbowsim::study
