// SPDX-License-Identifier: MIT
// Reading a TOML case file and `--set` overrides into a validated Case (toml11 v3).
#include "formflow/core/error.hpp"
#include "formflow/core/printable_text.hpp"
#include "formflow/io/case.hpp"
#include "formflow/io/case_builder.hpp"
#include "formflow/io/case_document.hpp"
#include "formflow/io/case_keys.hpp"
#include "formflow/io/toml_key_value.hpp"
#include "formflow/io/toml_lines.hpp"

#include <fmt/format.h>
#include <toml.hpp>

namespace formflow::io {

namespace {

std::string did_you_mean(std::string_view name) {
  return unknown_key_hint(name);
}

void apply_document(CaseBuilder& builder, const toml::value& document, const std::string& path) {
  TomlLines lines;
  for (const auto& [section, table] : in_file_order(document, lines)) {
    const int line = line_of(lines, *table);
    if (!is_case_section(section)) {
      if (table->is_table())
        throw InputError(path, line, section, "unknown section", unknown_section_hint(section));
      throw InputError(path, line, section, "unknown key (every key belongs in a section)",
                       did_you_mean(section));
    }
    if (!table->is_table())
      throw InputError(path, line, section,
                       "expected a section, got " + describe_toml_value(*table),
                       fmt::format("write `[{}]` on its own line, then its keys", section));
    for (const auto& [leaf, value] : in_file_order(*table, lines)) {
      const std::string name = section + "." + leaf;
      const CaseKey* key = find_case_key(name);
      const int key_line = line_of(lines, *value);
      if (!key) throw InputError(path, key_line, name, "unknown key", did_you_mean(name));
      builder.set(*key, *value, path, key_line, lines);
    }
  }
}

std::string_view first_key_of(std::string_view section) {
  for (const CaseKey& key : case_keys())
    if (key.section() == section) return key.name;
  return section;
}

void apply_override(CaseBuilder& builder, const Override& assignment) {
  const std::string file = "--set";
  const std::string name = trimmed(assignment.first);
  const CaseKey* key = find_case_key(name);
  if (!key && is_case_section(name))
    throw InputError(file, 0, name, "is a section, not a key",
                     fmt::format("set one of its keys, e.g. `{}`", first_key_of(name)));
  if (!key) throw InputError(file, 0, name, "unknown key", did_you_mean(name));
  TomlLines lines; // a --set value has no lines worth naming: all errors say `--set`
  builder.set(*key, parse_override_value(name, assignment.second), file, 0, lines);
}

} // namespace

namespace {

Case build_case(const toml::value* document, const std::string& path,
                const std::vector<Override>& overrides,
                const std::vector<Override>& defaults = {}) {
  CaseBuilder builder;
  for (const auto& [name, text] : defaults) {
    const CaseKey* key = find_case_key(name);
    if (!key) throw InternalError("a default for an unknown key: " + name);
    builder.set_default(*key, parse_override_value(name, text));
  }
  if (document) apply_document(builder, *document, path);
  for (const Override& assignment : overrides) apply_override(builder, assignment);
  builder.resolve_dependent_defaults();
  builder.check_cross_keys();
  return builder.finish(path.empty() ? "<default>" : path);
}

} // namespace

Case load_case(const std::string& path, const std::vector<Override>& overrides,
               const std::vector<Override>& defaults) {
  if (path.empty()) return build_case(nullptr, path, overrides, defaults);
  const toml::value document = read_case_document(path);
  return build_case(&document, path, overrides, defaults);
}

Case load_case_text(const std::string& text, const std::string& source,
                    const std::vector<Override>& overrides) {
  const toml::value document = parse_case_document(text, source);
  return build_case(&document, source, overrides);
}

} // namespace formflow::io
