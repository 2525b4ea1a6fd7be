// Small pieces of HTML5 shared by the run report and the comparison report.
// Pages are one file plus relative links (plots/*.png, video.mp4): readable
// from disk without a server, portable as a folder (docs/cli.md, "Reports").
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "report/metrics.hpp"
#include "report/run_plots.hpp"

namespace elbowsim::report::html {

// Text made safe inside elements and quoted attributes.
std::string escape(const std::string& text);

// A metric as people read it: 6 significant digits, "true"/"false", "NaN" for null.
std::string display_value(const nlohmann::ordered_json& value);

// A metric exactly (for data-value attributes): round-trip digits.
std::string exact_value(const nlohmann::ordered_json& value);

// <!DOCTYPE html> ... <body>, with the shared style sheet; page_end: the footer
// naming the program that wrote the page (report/provenance.hpp), </body></html>.
std::string page_begin(const std::string& title);
std::string page_end();

// A boxed notice (class "failure", "warnings", "problems" or "verdict") with
// a heading and items; `id` (unique in the page) when not empty. Items after
// the first `shown` are folded into a <details> ("and 12 more").
std::string notice(const std::string& css_class, const std::string& heading,
                   const std::vector<std::string>& items, const std::string& id = "",
                   std::size_t shown = 1000);

// A two-column table of label / value rows (values are escaped).
std::string info_table(const std::vector<std::pair<std::string, std::string>>& rows);

// <table id=...> of metric, value, unit; each value cell carries data-value.
std::string metrics_table(const std::vector<Metric>& metrics, const std::string& id);

// <figure> with the image (width and height attributes) and its caption.
std::string figure(const Figure& f);

// Writes text to path under a temporary name, then renames it. Throws
// std::runtime_error naming the path on failure.
void write_file(const std::filesystem::path& path, const std::string& text);

// A JSON file a report is made from (montecarlo.json, study.json). Throws
// std::runtime_error naming the file when it cannot be read or parsed.
nlohmann::ordered_json read_json(const std::filesystem::path& path);

}  // namespace elbowsim::report::html
