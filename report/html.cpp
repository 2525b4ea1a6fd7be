#include "report/html.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "engine/recording/number_text.hpp"
#include "report/provenance.hpp"

namespace elbowsim::report::html {

namespace {

constexpr const char* kStyle = R"(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; color: #1a1a1a;
       max-width: 980px; margin: 1.5em auto; padding: 0 1em; line-height: 1.45; }
h1 { margin-bottom: 0.2em; }
h2 { border-bottom: 1px solid #ddd; padding-bottom: 0.2em; margin-top: 1.8em; }
.description { font-size: 1.1em; color: #333; margin-top: 0; }
.meta { color: #666; font-size: 0.9em; }
.failure { background: #fde8e8; border: 2px solid #c0392b; padding: 0.6em 1em; }
.warnings { background: #fff6d6; border: 2px solid #d4a017; padding: 0.6em 1em; }
.problems { background: #eef2f7; border: 2px solid #7f8c9d; padding: 0.6em 1em; }
.verdict { background: #e9f5ec; border: 2px solid #3c8d50; padding: 0.6em 1em; font-size: 1.05em; }
.failure ul, .warnings ul, .problems ul, .verdict ul { margin: 0.3em 0; }
table { border-collapse: collapse; margin: 0.5em 0; font-size: 0.92em; }
th, td { border: 1px solid #ddd; padding: 0.25em 0.6em; text-align: left; vertical-align: top; }
th { background: #f3f3f3; }
tr:nth-child(even) td { background: #fafafa; }
td.num { text-align: right; font-family: "DejaVu Sans Mono", monospace; white-space: nowrap; }
td.differs, tr.differs code { font-weight: bold; }
code { font-family: "DejaVu Sans Mono", monospace; font-size: 0.95em; }
figure { margin: 1.2em 0; }
figure img { max-width: 100%; height: auto; border: 1px solid #e3e3e3; }
figcaption { color: #444; font-size: 0.92em; }
nav { margin: 0.8em 0; }
video { max-width: 100%; border: 1px solid #ccc; }
pre { background: #f6f6f6; padding: 0.8em; overflow-x: auto; font-size: 0.85em; }
.lead { font-size: 1.12em; margin: 0.4em 0 0.6em; }
table.headline { font-size: 1em; min-width: 60%; }
table.headline th[scope=row] { font-weight: normal; white-space: nowrap; }
table.headline td.value { font-weight: bold; }
td.same { color: #777; }
.status-valid { color: #2d7a3e; font-weight: bold; }
.status-invalid { color: #b03a2e; font-weight: bold; }
ul.notes li { margin: 0.25em 0; }
footer.provenance { color: #777; font-size: 0.85em; margin-top: 2.5em; border-top: 1px solid #ddd;
                    padding-top: 0.4em; }
)";

}  // namespace

std::string escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string display_value(const nlohmann::ordered_json& value) {
  if (value.is_null()) return "NaN";
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_number_integer()) return value.dump();
  if (!value.is_number()) return value.dump();
  return significant(value.get<double>());
}

std::string exact_value(const nlohmann::ordered_json& value) {
  if (!value.is_number_float()) return display_value(value);
  return round_trip(value.get<double>());
}

std::string page_begin(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<meta name=\"generator\" content=\"elbowsim\">\n<title>" +
         escape(title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
}

// The footer names the program that wrote the page (a run's own is in its summary.json).
std::string page_end() {
  return "<footer class=\"provenance\">This page was written by " + escape(provenance_line()) +
         ".</footer>\n</body>\n</html>\n";
}

std::string notice(const std::string& css_class, const std::string& heading,
                   const std::vector<std::string>& items, const std::string& id,
                   std::size_t shown) {
  std::string out = "<div class=\"" + css_class + "\"" + (id.empty() ? "" : " id=\"" + id + "\"") +
                    " role=\"alert\">\n<strong>" + escape(heading) + "</strong>\n";
  if (!items.empty()) {
    out += "<ul>\n";
    for (std::size_t k = 0; k < items.size() && k < shown; ++k)
      out += "<li>" + escape(items[k]) + "</li>\n";
    out += "</ul>\n";
  }
  if (items.size() > shown) {
    out +=
        "<details><summary>and " + std::to_string(items.size() - shown) + " more</summary>\n<ul>\n";
    for (std::size_t k = shown; k < items.size(); ++k) out += "<li>" + escape(items[k]) + "</li>\n";
    out += "</ul>\n</details>\n";
  }
  return out + "</div>\n";
}

std::string info_table(const std::vector<std::pair<std::string, std::string>>& rows) {
  std::string out = "<table class=\"info\">\n";
  for (const auto& [label, value] : rows)
    out += "<tr><th scope=\"row\">" + escape(label) + "</th><td>" + escape(value) + "</td></tr>\n";
  return out + "</table>\n";
}

std::string metrics_table(const std::vector<Metric>& metrics, const std::string& id) {
  std::string out = "<table id=\"" + id +
                    "\" class=\"metrics\">\n"
                    "<tr><th>metric</th><th>value</th><th>unit</th></tr>\n";
  for (const Metric& m : metrics)
    out += "<tr><td><code>" + escape(m.path) + "</code></td><td class=\"num\" data-metric=\"" +
           escape(m.path) + "\" data-value=\"" + exact_value(m.value) + "\">" +
           escape(display_value(m.value)) + "</td><td>" + escape(m.unit) + "</td></tr>\n";
  return out + "</table>\n";
}

std::string figure(const Figure& f) {
  return "<figure>\n<img src=\"" + escape(f.file) + "\" alt=\"" + escape(f.title) + "\" width=\"" +
         std::to_string(f.width) + "\" height=\"" + std::to_string(f.height) + "\">\n<figcaption>" +
         escape(f.caption) + "</figcaption>\n</figure>\n";
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  const std::filesystem::path partial = path.string() + ".tmp";
  std::error_code error;
  {
    std::ofstream out(partial, std::ios::binary);
    out << text;
    out.close();
    if (!out) {
      const int why = errno;
      std::filesystem::remove(partial, error);
      throw std::runtime_error(path.string() + ": cannot write" +
                               (why ? std::string(": ") + std::strerror(why) : std::string()));
    }
  }
  std::filesystem::rename(partial, path, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(partial, ignored);
    throw std::runtime_error(path.string() + ": " + error.message());
  }
}

nlohmann::ordered_json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  try {
    return nlohmann::ordered_json::parse(in);
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

}  // namespace elbowsim::report::html
