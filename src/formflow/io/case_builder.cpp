// SPDX-License-Identifier: MIT
// The case builder: the table's defaults, keys set one by one with where each was set,
// and the errors that blame the key to change (io/case_builder.hpp).
#include "formflow/io/case_builder.hpp"

#include "formflow/core/error.hpp"
#include "formflow/io/toml_key_value.hpp"

#include <fmt/format.h>

namespace formflow::io {

CaseBuilder::CaseBuilder() {
  for (const CaseKey& key : case_keys()) key.set(case_, key.default_value);
}

void CaseBuilder::set(const CaseKey& key, const toml::value& value, const std::string& file,
                      int line, TomlLines& lines) {
  const std::string name(key.name);
  if (key.type == KeyType::NameMap && value.is_table() && file != "--set")
    check_table_entries(key, value, file, lines);
  if (const auto problem = clamped_number(value))
    throw InputError(file, line, name, *problem, "must be " + valid_values_text(key));
  const std::optional<KeyValue> converted = convert_toml_value(key, value);
  if (!converted) {
    const std::string example = format_key_value(key.default_value);
    throw InputError(
        file, line, name,
        fmt::format("expected {}, got {}", expected_type_text(key), describe_toml_value(value)),
        file == "--set" ? fmt::format("e.g. --set {}={}", name, example)
                        : fmt::format("e.g. {} = {}", name, example));
  }
  if (const auto problem = check_key_value(key, *converted))
    throw InputError(file, line, name, problem->message, problem->hint);
  key.set(case_, *converted);
  origins_[name] = Origin{file, line, ++n_set_};
  // Now, not at finish(): the checks read which keys were given (io/problem_shape.hpp).
  case_.key_locations[name] = Case::KeyLocation{file, line};
  if (value.is_table()) // entries of a table key, so later errors can name their line
    for (const auto& [entry, entry_value] : value.as_table())
      origins_[name + "." + entry] =
          Origin{file, file == "--set" ? line : line_of(lines, entry_value), n_set_};
}

void CaseBuilder::set_default(const CaseKey& key, const toml::value& value) {
  const std::optional<KeyValue> converted = convert_toml_value(key, value);
  // A caller's constant, not the user's input: wrong, it is formflow's bug.
  if (!converted || check_key_value(key, *converted))
    throw InternalError("an invalid default for " + std::string(key.name));
  key.set(case_, *converted);
}

void CaseBuilder::check_table_entries(const CaseKey& key, const toml::value& table,
                                      const std::string& file, TomlLines& lines) {
  for (const auto& [entry, pointer] : in_file_order(table, lines)) {
    const toml::value& entry_value = *pointer;
    const std::string name(key.name);
    if (!entry_value.is_string())
      throw InputError(
          file, line_of(lines, entry_value), name,
          fmt::format("entry \"{}\": expected a string, got {}", entry,
                      describe_toml_value(entry_value)),
          fmt::format("e.g. {} = \"{}\"", entry, key.choices.empty() ? "" : key.choices.front()));
    if (const auto problem = check_key_value(key, NameMap{{entry, entry_value.as_string().str}}))
      throw InputError(file, line_of(lines, entry_value), name, problem->message, problem->hint);
  }
}

Case CaseBuilder::finish(std::string source) {
  case_.source = std::move(source);
  for (const auto& [name, where] : origins_)
    case_.key_locations[name] = Case::KeyLocation{where.file, where.line};
  return case_;
}

CaseBuilder::Origin CaseBuilder::origin(const std::string& name) const {
  const auto found = origins_.find(name);
  return found == origins_.end() ? Origin{} : found->second;
}

std::string CaseBuilder::responsible(const std::string& primary,
                                     std::initializer_list<std::string> related) const {
  if (origin(primary).order > 0) return primary;
  std::string blamed = primary;
  for (const std::string& name : related)
    if (origin(name).order > origin(blamed).order) blamed = name;
  return blamed;
}

Real CaseBuilder::real_value(const std::string& name) const {
  return std::get<Real>(find_case_key(name)->get(case_));
}

void CaseBuilder::blame(const std::vector<std::string>& names, const std::string& message,
                        const std::string& hint) const {
  std::string blamed = names.front();
  for (const std::string& name : names)
    if (origin(name).order > origin(blamed).order) blamed = name;
  const Origin where = origin(blamed);
  throw InputError(
      where.file, where.line, blamed,
      fmt::format("value {}: {}", format_key_value(find_case_key(blamed)->get(case_)), message),
      hint);
}

void CaseBuilder::die_error(const std::string& name, const std::string& message,
                            const std::string& hint,
                            std::initializer_list<std::string> related) const {
  const std::string blamed = responsible(name, related);
  const Origin where = origin(blamed);
  const std::string text =
      blamed == name ? message
                     : fmt::format("with {} = {} (its default): {}", name,
                                   format_key_value(find_case_key(name)->get(case_)), message);
  throw InputError(where.file, where.line, blamed, text, hint);
}

} // namespace formflow::io
