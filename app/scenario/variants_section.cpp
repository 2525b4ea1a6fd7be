// variants: named sets of key overrides (elbow on / elbow off, ...). Each
// entry is "dotted.key: value", applied like --set after the file and before
// the command line's --set. Here only their form is checked; the loader checks
// their content by loading the scenario with each variant (scenario_loader.cpp).
#include <algorithm>
#include <cctype>
#include <set>

#include "app/scenario/sections.hpp"

namespace elbowsim::loader {

namespace {

// A variant's name becomes a folder name: letters, digits, _ and - only.
std::string read_variant_name(const Value& key) {
  const std::string name = key.text();
  auto allowed = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  };
  if (name.empty() || !std::all_of(name.begin(), name.end(), allowed))
    key.fail("a variant name must be letters, digits, _ or - only (got \"" + name + "\")");
  return name;
}

// One entry "key.path: value" -> the override "key.path=value".
VariantSpec::Entry read_entry(const Value& key, const Value& value) {
  const std::string path = key.text();
  if (path.empty()) key.fail("expected a key path (e.g. effects.contact)");
  if (path == "variants" || path.starts_with("variants.") || path.starts_with("variants["))
    key.fail("a variant cannot change variants");
  return {path + "=" + value.flow_yaml(), key.origin()};
}

}  // namespace

std::vector<VariantSpec> read_variants(const Value& variants) {
  std::vector<VariantSpec> out;
  if (!variants.present()) return out;
  const auto entries = variants.entries();
  if (entries.empty()) variants.fail("needs at least one variant (or leave variants out)");
  std::set<std::string> names;
  for (const auto& [key, overrides] : entries) {
    VariantSpec spec{read_variant_name(key), {}};
    if (!names.insert(spec.name).second) key.fail("duplicate variant \"" + spec.name + "\"");
    if (overrides.present() && !overrides.is_map())
      overrides.fail("expected a map of key.path: value overrides (or {} for none)");
    std::set<std::string> paths;
    if (overrides.present())
      for (const auto& [path, value] : overrides.entries()) {
        spec.overrides.push_back(read_entry(path, value));
        if (!paths.insert(path.text()).second) path.fail("duplicate key in this variant");
      }
    out.push_back(std::move(spec));
  }
  return out;
}

}  // namespace elbowsim::loader
