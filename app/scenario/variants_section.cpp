// variants: named sets of key overrides (elbow on / elbow off, ...). Each
// entry is "dotted.key: value", applied like --set after the file and before
// the command line's --set. study.axes: the same kind of named sets, one axis
// per dimension of a study (task, speed, ...), applied before a variant's.
// Here only their form is checked; the loader checks their content by loading
// the scenario with each variant and each level (scenario_loader.cpp).
#include <algorithm>
#include <cctype>
#include <set>

#include "app/scenario/sections.hpp"

namespace elbowsim::loader {

namespace {

// A variant's name becomes a folder name: letters, digits, _ and - only. A
// study's names join into a case's folder name with '-', so they may not
// hold one themselves.
std::string read_set_name(const Value& key, std::string_view what, bool dash) {
  const std::string name = key.text();
  auto allowed = [dash](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || (dash && c == '-');
  };
  if (name.empty() || !std::all_of(name.begin(), name.end(), allowed))
    key.fail("a " + std::string(what) + " name must be letters, digits, _" + (dash ? " or -" : "") +
             " only (got \"" + name + "\")");
  return name;
}

bool names_section(const std::string& path, std::string_view section) {
  return path == section || (path.starts_with(section) && (path[section.size()] == '.' ||
                                                           path[section.size()] == '['));
}

// One entry "key.path: value" -> the override "key.path=value".
VariantSpec::Entry read_entry(const Value& key, const Value& value, std::string_view what) {
  const std::string path = key.text();
  if (path.empty()) key.fail("expected a key path (e.g. effects.contact)");
  for (std::string_view section : {"variants", "study"})
    if (names_section(path, section))
      key.fail("a " + std::string(what) + " cannot change " + std::string(section));
  return {path + "=" + value.flow_yaml(), key.origin()};
}

// A map of name -> {key.path: value, ...}: variants, or one axis of a study.
std::vector<VariantSpec> read_override_sets(const Value& sets, std::string_view what, bool dash) {
  std::vector<VariantSpec> out;
  const auto entries = sets.entries();
  if (entries.empty())
    sets.fail("needs at least one " + std::string(what) + (dash ? " (or leave variants out)" : ""));
  std::set<std::string> names;
  for (const auto& [key, overrides] : entries) {
    VariantSpec spec{read_set_name(key, what, dash), {}};
    if (!names.insert(spec.name).second)
      key.fail("duplicate " + std::string(what) + " \"" + spec.name + "\"");
    if (overrides.present() && !overrides.is_map())
      overrides.fail("expected a map of key.path: value overrides (or {} for none)");
    std::set<std::string> paths;
    if (overrides.present())
      for (const auto& [path, value] : overrides.entries()) {
        spec.overrides.push_back(read_entry(path, value, what));
        if (!paths.insert(path.text()).second)
          path.fail("duplicate key in this " + std::string(what));
      }
    out.push_back(std::move(spec));
  }
  return out;
}

}  // namespace

std::vector<VariantSpec> read_variants(const Value& variants) {
  if (!variants.present()) return {};
  return read_override_sets(variants, "variant", true);
}

std::vector<StudyAxisSpec> read_study(const Value& study) {
  std::vector<StudyAxisSpec> out;
  if (!study.present()) return out;
  study.allow_keys({"axes"});
  const Value axes = study.require("axes");
  if (!axes.is_map()) axes.fail("expected a map of axes, each a map of levels (name: {key.path: value})");
  for (const auto& [key, levels] : axes.entries()) {
    const std::string name = read_set_name(key, "study axis", false);
    if (!levels.is_map()) levels.fail("expected a map of levels (name: {key.path: value} or {})");
    out.push_back({name, read_override_sets(levels, "study level", false)});
  }
  if (out.empty()) axes.fail("needs at least one axis (or leave study out)");
  return out;
}

}  // namespace elbowsim::loader
