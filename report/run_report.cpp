#include "report/run_report.hpp"

#include <cmath>

#include "engine/recording/number_text.hpp"
#include "report/energy_flow.hpp"
#include "report/headline.hpp"
#include "report/html.hpp"
#include "report/metrics.hpp"
#include "report/plots_aside.hpp"
#include "report/summary_keys.hpp"

namespace elbowsim::report {

namespace {

namespace fs = std::filesystem;
namespace key = summary_key;
using Rows = std::vector<std::pair<std::string, std::string>>;

constexpr std::size_t kMaxEventRows = 200;
constexpr std::size_t kWarningsShown = 6;  // more fold away, so the headline stays on screen

std::string joined(const nlohmann::ordered_json& list) {
  std::string out;
  if (list.is_array())
    for (const auto& item : list) out += (out.empty() ? "" : ", ") + item.get<std::string>();
  return out.empty() ? "(none)" : out;
}

std::string dynamics_name(const std::string& method) {
  if (method == "walker_orin")
    return "walker_orin: mass matrix by Walker-Orin method 1 (the paper's) + Cholesky";
  if (method == "crba") return "crba: mass matrix by the composite-rigid-body algorithm + Cholesky";
  if (method == "aba") return "aba: articulated-body algorithm";
  return method;
}

std::string status(const nlohmann::ordered_json& s) {
  const std::string steps = std::to_string(s.value(key::steps.name(), 0L)) +
                            " steps to t = " + significant(s.value(key::final_time.name(), 0.0)) +
                            " s";
  if (!s.value(key::completed.name(), false)) return "STOPPED EARLY after " + steps;
  return s.value(key::valid.name(), true) ? "completed: " + steps
                                          : "completed, NOT VALID: " + steps;
}

Rows run_rows(const RunData& run) {
  const nlohmann::ordered_json& s = run.summary;
  Rows rows{{"run folder", run.label}};
  if (!run.has_summary()) return rows;
  const auto& settings = s.value(key::settings.name(), nlohmann::ordered_json::object());
  const auto& model = s.value(key::model.name(), nlohmann::ordered_json::object());
  const double wall = s.value(key::wall_seconds.name(), 0.0);
  rows.push_back({"status", status(s)});
  rows.push_back({"scenario file", s.value(key::file.name(), "")});
  rows.push_back(
      {"active effects", joined(s.value(key::effects.name(), nlohmann::ordered_json::array()))});
  rows.push_back({"model", std::to_string(model.value(key::model_dof.name(), 0)) +
                               " joints, total mass " +
                               significant(model.value(key::model_total_mass.name(), 0.0)) + " kg" +
                               ", hand on link " +
                               std::to_string(model.value(key::model_hand_link.name(), 0))});
  for (const auto& row : run.model_rows) rows.push_back(row);
  std::string integrator = settings.value(key::settings_integrator.name(), "");
  if (settings.contains(
          key::settings_rtol.name()))  // adaptive: its tolerances; step is the recording interval
    integrator += ", rtol " + significant(settings.value(key::settings_rtol.name(), 0.0)) +
                  ", atol " + significant(settings.value(key::settings_atol.name(), 0.0)) +
                  ", rows every " + significant(settings.value(key::settings_step.name(), 0.0)) +
                  " s";
  else
    integrator += ", step " + significant(settings.value(key::settings_step.name(), 0.0)) + " s";
  rows.push_back(
      {"integrator", integrator + ", duration " +
                         significant(settings.value(key::settings_duration.name(), 0.0)) + " s"});
  rows.push_back({"dynamics", dynamics_name(settings.value(key::settings_dynamics.name(), ""))});
  if (s.contains(key::controller.name()) && s[key::controller.name()].is_string()) {
    std::string believes = "knows the plant exactly";
    if (s.contains(key::controller_model.name()) && s[key::controller_model.name()].is_array() &&
        !s[key::controller_model.name()].empty()) {
      believes = "believes";
      for (const auto& o : s[key::controller_model.name()]) believes += " " + o.get<std::string>();
      believes += " (the plant does not)";
    }
    rows.push_back({"controller", s[key::controller.name()].get<std::string>() + "; " + believes});
  }
  if (s.contains(key::control_loop.name()) && s[key::control_loop.name()].is_object()) {
    const auto& loop = s[key::control_loop.name()];
    std::string text = significant(loop.value(key::control_loop_sample_rate.name(), 0.0)) + " Hz" +
                       " sampling, delay " +
                       std::to_string(loop.value(key::control_loop_delay_samples.name(), 0)) +
                       " samples";
    if (const long counts = loop.value(key::control_loop_encoder_counts_per_rev.name(), 0L);
        counts > 0)
      text += ", encoder " + std::to_string(counts) + " counts/rev (" +
              loop.value(key::control_loop_encoder_side.name(), "") + " side)";
    if (const double noise = loop.value(key::control_loop_angle_noise.name(), 0.0); noise > 0)
      text += ", angle noise σ " + significant(noise) + " rad";
    if (const int bits = loop.value(key::control_loop_pwm_bits.name(), 0); bits > 0)
      text += ", " + std::to_string(bits) + "-bit amplifier";
    rows.push_back({"control loop", text});
  } else if (s.contains(key::control_loop.name())) {
    rows.push_back({"control loop", "continuous (the control law on the true state)"});
  }
  const auto& contact = s.value(key::contact.name(), nlohmann::ordered_json::object());
  if (contact.value(key::contact_enabled.name(), false))
    rows.push_back(
        {"contact",
         "events: " + contact.value(key::contact_events.name(), "") +
             ", stabilization: " + contact.value(key::contact_stabilization.name(), "") + ", " +
             std::to_string(contact.value(key::contact_landings.name(), 0)) + " landings, " +
             std::to_string(contact.value(key::contact_releases.name(), 0)) + " releases"});
  const long steps_per_second = wall > 0 ? std::lround(s.value(key::steps.name(), 0L) / wall) : 0;
  rows.push_back(
      {"wall time", significant(wall) + " s" +
                        (wall > 0 ? " (" + std::to_string(steps_per_second) + " steps/s)" : "")});
  rows.push_back({"recorded samples", std::to_string(run.trajectory.rows())});
  return rows;
}

std::string header(const RunData& run) {
  std::string out = "<header>\n<h1>" + html::escape(run_title(run)) + "</h1>\n";
  if (run.has_summary() && !run.summary.value(key::description.name(), "").empty())
    out += "<p class=\"description\">" +
           html::escape(run.summary[key::description.name()].get<std::string>()) + "</p>\n";
  return out +
         "<p class=\"meta\">elbowsim run report, rebuilt from the files in run folder <code>" +
         html::escape(run.label) + "</code> (<code>elbowsim report " + html::escape(run.label) +
         "</code> rebuilds it).</p>\n</header>\n";
}

// Failure, warnings and unreadable files, before anything else.
std::string notices(const RunData& run) {
  std::string out;
  const nlohmann::ordered_json& s = run.summary;
  if (run.has_summary() && s.value(key::completed.name(), true) &&
      !s.value(key::valid.name(), true))
    out += html::notice(
        "failure", "This run is not valid: do not use its numbers.",
        {"Failure: " + s.value(key::failure.name(), std::string("(no reason recorded)")),
         "It ran to t = " + significant(s.value(key::final_time.name(), 0.0)) + " s" +
             "; the plots show what it computed, for diagnosis."},
        "failure");
  if (run.has_summary() && !s.value(key::completed.name(), true))
    out += html::notice(
        "failure", "This run did not complete.",
        {"Failure: " + s.value(key::failure.name(), std::string("(no reason recorded)")),
         "What it recorded is kept: t = 0 to " + significant(s.value(key::final_time.name(), 0.0)) +
             " s" + ", " + std::to_string(run.trajectory.rows()) +
             " samples; the plots and totals cover that span only."},
        "failure");
  std::vector<std::string> warnings;
  if (run.has_summary() && s.contains(key::warnings.name()))
    for (const auto& w : s[key::warnings.name()]) warnings.push_back(w.get<std::string>());
  if (!warnings.empty())
    out += html::notice(
        "warnings", std::to_string(warnings.size()) + " warning(s): read them before the numbers",
        warnings, "warnings", kWarningsShown);
  if (!run.problems.empty())
    out += html::notice("problems", "Missing or unreadable files", run.problems, "problems");
  return out;
}

// The first screen: validity, one sentence, the headline numbers with units.
std::string headline_section(const RunData& run) {
  std::string out = "<section id=\"headline\">\n<h2>What this run shows</h2>\n<p class=\"lead\">" +
                    html::escape(headline_sentence(run)) +
                    "</p>\n<table class=\"headline\" id=\"headline-table\">\n";
  const std::string status = validity(run);
  out += "<tr data-metric=\"valid\"><th scope=\"row\">status</th><td class=\"value " +
         std::string(status == "valid" ? "status-valid" : "status-invalid") + "\">" +
         html::escape(status) + "</td></tr>\n";
  for (const HeadlineItem& item : headline_items({&run}))
    out += "<tr data-metric=\"" + html::escape(item.path) + "\"><th scope=\"row\">" +
           html::escape(item.label) + "</th><td class=\"value\">" +
           html::escape(headline_value(run, item)) + "</td></tr>\n";
  out += "<tr data-metric=\"step_check\"><th scope=\"row\">accuracy check</th><td>" +
         html::escape(accuracy_check(run)) + "</td></tr>\n";
  return out + "</table>\n</section>\n";
}

// Figures of one group (the lead figures), or of none (the rest).
std::string figures_of(const FigureSet& figures, const std::string& group) {
  std::string out;
  for (const Figure& f : figures.figures)
    if (f.group == group) out += html::figure(f);
  return out;
}

std::string hand_path_section(const FigureSet& figures) {
  const std::string body = figures_of(figures, "hand_path");
  if (body.empty()) return "";
  return "<section id=\"hand-path\">\n<h2>Hand path</h2>\n" + body + "</section>\n";
}

std::string energy_section(const RunData& run, const FigureSet& figures) {
  const std::string body = figures_of(figures, "energy");
  const auto flow = energy_flow(run.summary);
  if (body.empty() || !flow) return "";
  std::string out =
      "<section id=\"energy\">\n<h2>Where the energy went</h2>\n" + body + "<ul class=\"notes\">\n";
  for (const std::string& note : energy_flow_notes(*flow))
    out += "<li>" + html::escape(note) + "</li>\n";
  return out + "</ul>\n</section>\n";
}

std::string plots_section(const FigureSet& figures) {
  std::string out = "<section id=\"plots\">\n<h2>More plots</h2>\n" + figures_of(figures, "");
  if (!figures.skipped.empty()) {
    out += "<p class=\"meta\">Not plotted for this run:</p>\n<ul class=\"meta\">\n";
    for (const std::string& s : figures.skipped) out += "<li>" + html::escape(s) + "</li>\n";
    out += "</ul>\n";
  }
  return out + "</section>\n";
}

std::string events_section(const RunData& run) {
  if (run.events.empty()) return "";
  std::string out =
      "<section id=\"events\">\n<h2>Contact events</h2>\n<table>\n<tr><th>time [s]</th>"
      "<th>elbow</th><th>kind</th><th>speed [m/s]</th><th>impulse [N s]</th>"
      "<th>energy lost [J]</th></tr>\n";
  for (std::size_t k = 0; k < std::min(run.events.size(), kMaxEventRows); ++k) {
    const EventRow& e = run.events[k];
    out += "<tr><td class=\"num\">" + significant(e.t) + "</td><td>" + html::escape(e.elbow) +
           "</td><td>" + html::escape(e.kind) + "</td><td class=\"num\">" + significant(e.speed) +
           "</td><td class=\"num\">" + significant(e.impulse) + "</td><td class=\"num\">" +
           significant(e.energy_lost) + "</td></tr>\n";
  }
  out += "</table>\n";
  if (run.events.size() > kMaxEventRows)
    out += "<p class=\"meta\">First " + std::to_string(kMaxEventRows) + " of " +
           std::to_string(run.events.size()) + " events; all are in events.csv.</p>\n";
  return out + "</section>\n";
}

std::string contents(const RunData& run, const FigureSet& figures) {
  std::string links = "<a href=\"#headline\">Headline</a>";
  if (!figures_of(figures, "hand_path").empty()) links += " · <a href=\"#hand-path\">Hand path</a>";
  if (!figures_of(figures, "energy").empty()) links += " · <a href=\"#energy\">Energy</a>";
  if (run.has_video) links += " · <a href=\"#video\">Video</a>";
  links +=
      " · <a href=\"#plots\">More plots</a> · <a href=\"#run\">Run settings</a>"
      " · <a href=\"#summary-metrics\">All metrics</a>";
  if (!run.events.empty()) links += " · <a href=\"#events\">Contact events</a>";
  return "<nav class=\"meta\">" + links + " · <a href=\"#files\">Files</a></nav>\n";
}

std::string files_section(const RunData& run) {
  std::string out = "<section id=\"files\">\n<h2>Files</h2>\n<ul>\n";
  for (const std::string& name : run.files)
    out += "<li><a href=\"" + html::escape(name) + "\">" + html::escape(name) + "</a></li>\n";
  out += "</ul>\n";
  if (!run.scenario_yaml.empty())
    out += "<details>\n<summary>The scenario as run (scenario.yaml)</summary>\n<pre>" +
           html::escape(run.scenario_yaml) + "</pre>\n</details>\n";
  return out + "</section>\n";
}

}  // namespace

std::string run_report_html(const RunData& run, const FigureSet& figures) {
  std::string page = html::page_begin("elbowsim report: " + run_title(run)) + header(run) +
                     notices(run) + headline_section(run) + contents(run, figures);
  page += hand_path_section(figures) + energy_section(run, figures);
  if (run.has_video)
    page +=
        "<section id=\"video\">\n<h2>Video</h2>\n<video src=\"video.mp4\" controls "
        "preload=\"metadata\" width=\"960\">video.mp4</video>\n</section>\n";
  page += plots_section(figures);
  page += "<section id=\"run\">\n<h2>Run settings</h2>\n" + html::info_table(run_rows(run)) +
          "</section>\n";
  page += "<section id=\"summary-metrics\">\n<h2>All metrics (summary.json)</h2>\n";
  page += run.has_summary()
              ? "<p class=\"meta\">In summary.json's order, named as <code>--expect</code> "
                "names them.</p>\n" +
                    html::metrics_table(run_metrics(run), "metrics")
              : "<p>No summary.json in this run folder; the run's metrics, computed from "
                "trajectory.csv:</p>\n" +
                    html::metrics_table(run_metrics(run), "metrics");
  page += "</section>\n" + events_section(run) + files_section(run);
  return page + html::page_end();
}

ReportFiles write_run_report(const RunData& run) {
  ReportFiles files;
  PlotsAside aside(run.folder);
  files.figures = write_run_plots(run, run.folder);
  files.html = run.folder / "report.html";
  html::write_file(files.html, run_report_html(run, files.figures));
  aside.keep();
  return files;
}

}  // namespace elbowsim::report
