#include "report/energy_flow.hpp"

#include <algorithm>
#include <cmath>

#include "engine/recording/energy_terms.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim::report {

namespace {

using Json = nlohmann::ordered_json;

// Below this share of the energy that flowed a value is rounding: "≈ 0".
constexpr double kNegligible = 1e-9;

double number(const Json& node, const char* key) {
  return node.is_object() && node.contains(key) && node[key].is_number() ? node[key].get<double>()
                                                                         : 0.0;
}

// A term's labels, from engine/recording/energy_terms.hpp by its member name; the two
// kinetic terms are booked as one, "kinetic".
struct Labels {
  std::string in, out, short_in, short_out;
};

Labels labels(const std::string& key) {
  if (key == "kinetic")
    return {"kinetic energy given up", "kinetic energy gained", "KE given up", "KE gained"};
  for (const EnergyTermInfo& t : kEnergyTerms) {
    if (key != t.name) continue;
    const std::string name = t.short_label;
    if (t.role == EnergyRole::stored) return {t.label_in, t.label_out, name + " given up", name + " gained"};
    return {t.label_in, t.label_out, name, name};
  }
  return {key, key, key, key};
}

// A term on its side. `amount` is counted in the term's own direction (into
// the arm when `supplied`, out of it otherwise); a negative amount is booked
// on the other side, a zero on its own.
void book(EnergyFlow& flow, const std::string& key, double amount, bool supplied) {
  const bool into = supplied ? !(amount < 0) : amount < 0;
  const Labels l = labels(key);
  (into ? flow.in : flow.out)
      .push_back({key, into ? l.in : l.out, std::abs(amount), into ? l.short_in : l.short_out});
}

// A loss, or the increase of a stored energy: out of the arm. A negative one
// (a stored energy given up, a loss negative by rounding) is booked in, and
// its label says so.
void outgoing(EnergyFlow& flow, const std::string& key, double amount) {
  book(flow, key, amount, false);
}

double sum(const std::vector<EnergyTerm>& terms) {
  double s = 0;
  for (const EnergyTerm& t : terms) s += t.value;
  return s;
}

// The first term stays first (the supply's); the rest largest first.
void order(std::vector<EnergyTerm>& terms, const char* first) {
  std::stable_sort(terms.begin(), terms.end(), [first](const EnergyTerm& a, const EnergyTerm& b) {
    if ((a.key == first) != (b.key == first)) return a.key == first;
    return a.value > b.value;
  });
}

// "(12 %)"; "(< 0.01 %)" for a sliver; nothing for 0 or a negligible value.
std::string share(double value, double total) {
  if (!(total > 0) || std::abs(value) < kNegligible * total) return "";
  if (std::abs(value) < 1e-4 * total) return "(< 0.01 %)";
  return "(" + percent(std::abs(value) / total) + ")";
}

std::string shown(double value, double scale) {
  if (value != 0 && std::abs(value) < kNegligible * scale) return "≈ 0 J";
  return quantity(value, "J");
}

}  // namespace

double EnergyFlow::term(const std::string& key) const {
  for (const auto* side : {&in, &out})
    for (const EnergyTerm& t : *side)
      if (t.key == key) return t.value;
  return 0;
}

std::optional<EnergyFlow> energy_flow(const Json& summary) {
  if (!summary.is_object() || !summary.contains("energy_final") ||
      !summary["energy_final"].is_object())
    return std::nullopt;
  const Json& f = summary["energy_final"];
  const Json empty = Json::object();
  const Json& i = summary.contains("energy_initial") ? summary["energy_initial"] : empty;
  const auto delta = [&](const char* key) { return number(f, key) - number(i, key); };
  EnergyFlow flow;
  flow.electrical_in = number(f, "electrical_in");
  flow.motors = number(f, "drawn") != 0 || number(f, "regenerated") != 0;
  if (flow.motors) {
    // E_in's two parts, each on its side as recorded (each >= 0).
    const Labels drawn = labels("drawn"), regenerated = labels("regenerated");
    flow.in.push_back({"drawn", drawn.in, number(f, "drawn"), drawn.short_in});
    flow.out.push_back({"regenerated", regenerated.out, number(f, "regenerated"), regenerated.short_out});
  } else if (flow.electrical_in != 0) {
    book(flow, "electrical_in", flow.electrical_in, true);
  }
  outgoing(flow, "potential", delta("potential"));
  outgoing(flow, "kinetic", delta("kinetic_links") + delta("kinetic_rotors"));
  if (flow.motors) outgoing(flow, "magnetic", delta("magnetic"));
  if (f.contains("pad_elastic")) outgoing(flow, "pad_elastic", delta("pad_elastic"));
  if (f.contains("spring")) outgoing(flow, "spring", delta("spring"));
  // The losses in list order: those every run has, those of contact in a
  // contact run, the others where they are not 0.
  const bool contact = summary.contains("contact") && summary["contact"].is_object() &&
                       summary["contact"].value("enabled", false);
  for (const EnergyTermInfo& t : kEnergyTerms) {
    if (t.role != EnergyRole::lost || !*t.summary_key) continue;
    const double value = number(f, t.summary_key);
    const bool shown = t.group == EnergyGroup::always     ? true
                       : t.group == EnergyGroup::contact ? contact
                                                         : value != 0;
    if (shown) outgoing(flow, t.summary_key, value);
  }
  flow.residual = summary.value("balance_residual", 0.0);
  const double scale = std::max(sum(flow.in), sum(flow.out));
  for (const char* key : {"normal_work", "projection"})
    if (std::abs(delta(key)) > kNegligible * scale) book(flow, key, delta(key), true);
  // The work of a hand force is in the balance but not in summary.json: what
  // the recorded terms leave over beyond the residual.
  const double external = flow.residual - (sum(flow.in) - sum(flow.out));
  if (std::abs(external) > 1e-7 * std::max(scale, 1e-300))
    book(flow, "external", external, true);
  order(flow.in, flow.motors ? "drawn" : "electrical_in");
  order(flow.out, "regenerated");
  flow.total_in = sum(flow.in);
  return flow;
}

plot::Waterfall energy_waterfall(const EnergyFlow& flow, const std::string& title) {
  plot::Waterfall chart;
  chart.title = title;
  chart.x = plot::linear_axis("energy", "J");
  chart.empty_message = "no data: no energy flowed";
  const double total = flow.total_in;
  const plot::Color source{0.349, 0.631, 0.310}, sink{0.882, 0.341, 0.349},
      supply{0.306, 0.475, 0.655};
  for (const EnergyTerm& t : flow.in)
    chart.steps.push_back(
        {t.label, t.value, source, false, share(t.value, total), shown(t.value, total)});
  chart.steps.push_back({"energy in", 0, std::nullopt, true, "", shown(total, total)});
  for (const EnergyTerm& t : flow.out)
    chart.steps.push_back({t.label, -t.value, t.key == "regenerated" ? supply : sink, false,
                           share(t.value, total), shown(t.value, total)});
  chart.steps.push_back({"residual", 0, plot::Color{0.55, 0.55, 0.55}, true,
                         share(std::abs(flow.residual), total), shown(flow.residual, total)});
  return chart;
}

std::vector<std::string> energy_flow_notes(const EnergyFlow& flow) {
  std::vector<std::string> notes;
  const double drawn = flow.term("drawn"), regenerated = flow.term("regenerated");
  if (flow.motors)
    notes.push_back("Electrical energy in, E_in = drawn − regenerated = " + quantity(drawn, "J") +
                    " − " + quantity(regenerated, "J") + " = " + quantity(flow.electrical_in, "J") +
                    ". Regenerated energy is what motors fed back while braking (their power v·i "
                    "negative); a supply that cannot take energy back still pays the " +
                    quantity(drawn, "J") + " drawn.");
  const double joule = flow.term("joule");
  if (flow.motors && joule > flow.electrical_in) {
    std::string others;
    for (const EnergyTerm& t : flow.in)
      if (t.key != "drawn" && t.value > 0)
        others += (others.empty() ? "" : ", ") + t.label + " (" + quantity(t.value, "J") + ")";
    notes.push_back("The Joule loss (" + quantity(joule, "J") +
                    ") exceeds the electrical energy in (" + quantity(flow.electrical_in, "J") +
                    ") because electricity is not its only source" +
                    (others.empty() ? "" : ": " + others) +
                    ". A motor that holds or lowers the arm against gravity brakes it; the energy "
                    "the arm gives up becomes current, which heats the windings like any other.");
  }
  if (flow.total_in > 0)
    notes.push_back(
        "Residual " + quantity(flow.residual, "J") + " (" +
        percent(std::abs(flow.residual) / flow.total_in) +
        " of the energy in): what the account leaves unexplained, the integration "
        "error; exact integration would make it 0 (docs/model.md, \"Energy balance\").");
  if (flow.term("external") > 0)
    notes.push_back(
        "The work of the hand force is not recorded on its own: it is what the "
        "recorded terms leave over beyond summary.json's balance_residual.");
  return notes;
}

}  // namespace elbowsim::report
