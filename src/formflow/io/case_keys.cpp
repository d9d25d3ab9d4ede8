// SPDX-License-Identifier: MIT
// The case-key table (names, types, defaults, ranges, units, docs) and its lookups.
#include "formflow/io/case_keys.hpp"
#include "formflow/io/keys/key_spec.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace formflow::io {

namespace {

std::vector<CaseKey> make_table() {
  using namespace keys;
  std::vector<CaseKey> table;
  // Section order = case_sections() order (the reference and the JSON follow it).
  for (auto part :
       {process_keys(), geometry_keys(), mesh_keys(), integration_keys(), formulation_keys(),
        material_keys(), contact_keys(), friction_keys(), penalty_keys(), solver_keys(),
        adapt_keys(), thermal_keys(), verification_keys()})
    for (CaseKey& key : part) table.push_back(std::move(key));
  return table;
}

/// ASCII lower case (keys are ASCII; no locale lookup in the edit-distance loop).
char lower_case(char c) {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

/// Levenshtein distance, ignoring letter case (so `penalty.dn` is next to `penalty.dN`),
/// or any value above `limit` once the distance is known to exceed it: a hint
/// only needs the keys nearer than the best so far, and an unknown key (every
/// typo, and most fuzz inputs) compares against every key.
std::size_t edit_distance(std::string_view a, std::string_view b,
                          std::size_t limit = std::string_view::npos - 1) {
  const std::size_t length_gap = a.size() > b.size() ? a.size() - b.size() : b.size() - a.size();
  if (length_gap > limit) return limit + 1; // at least one edit per missing character
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    std::size_t row_minimum = row[0];
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution =
          diagonal + (lower_case(a[i - 1]) == lower_case(b[j - 1]) ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min(std::min(row[j], row[j - 1]) + 1, substitution);
      row_minimum = std::min(row_minimum, row[j]);
    }
    if (row_minimum > limit) return limit + 1; // rows never decrease below their minimum
  }
  return row[b.size()];
}

std::optional<KeyProblem> check_number(const CaseKey& key, Real value, const std::string& text) {
  const bool below_lower = key.lower.value && (key.lower.inclusive ? value < *key.lower.value
                                                                   : value <= *key.lower.value);
  const bool above_upper = key.upper.value && (key.upper.inclusive ? value > *key.upper.value
                                                                   : value >= *key.upper.value);
  if (!std::isfinite(value))
    return KeyProblem{"value " + text + " is not finite", "must be " + valid_values_text(key)};
  const bool too_small = key.smallest_nonzero && value != 0 && value < *key.smallest_nonzero;
  if (below_lower || above_upper || too_small)
    return KeyProblem{"value " + text + " is out of range", "must be " + valid_values_text(key)};
  return std::nullopt;
}

std::string quoted_choices(const CaseKey& key) {
  std::string text;
  for (std::string_view choice : key.choices)
    text += (text.empty() ? "\"" : ", \"") + std::string(choice) + "\"";
  return text;
}

std::optional<KeyProblem> check_entry_count(const CaseKey& key, std::size_t count) {
  if (key.max_entries == 0 || count <= key.max_entries) return std::nullopt;
  return KeyProblem{fmt::format("{} entries, more than the limit of {}", count, key.max_entries),
                    "must be " + valid_values_text(key)};
}

std::optional<KeyProblem> check_list(const CaseKey& key, const std::vector<std::string>& list) {
  if (auto problem = check_entry_count(key, list.size())) return problem;
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (std::find(key.choices.begin(), key.choices.end(), list[i]) == key.choices.end())
      return KeyProblem{"invalid entry \"" + list[i] + "\"",
                        "valid entries: " + quoted_choices(key)};
    if (std::find(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(i), list[i]) !=
        list.begin() + static_cast<std::ptrdiff_t>(i))
      return KeyProblem{"duplicate entry \"" + list[i] + "\"",
                        "list each of " + quoted_choices(key) + " at most once"};
  }
  return std::nullopt;
}

} // namespace

const std::vector<CaseSection>& case_sections() {
  static const std::vector<CaseSection> sections = {
      {"process", "What drives the flow (SPEC §1)."},
      {"geometry", "The half model of the die channel (SPEC §4); lengths are dimensionless."},
      {"mesh", "Where the cells come from (a uniform grid, Gmsh, or a .msh file) and their "
               "element kind."},
      {"integration",
       "Quadrature of the volumetric penalty term (selective integration, SPEC §3)."},
      {"formulation", "Which form of the a-term is assembled, and penalty or mixed (pressure) form "
                      "of the constraints (SPEC §2, docs/mixed.md)."},
      {"material", "Flow law σ_p(ε̄̇) on [rate1, rate2], linear through the origin outside "
                   "(paper eq. 5.4 by default; material.law picks another)."},
      {"contact", "How the contact boundary Γ3 is discretised: the normal of the penalty and "
                  "of the friction law."},
      {"friction", "Nonlocal Coulomb friction on Γ3: regularised (paper eq. 3.14–3.15) or "
                   "exact."},
      {"penalty", "Penalty and regularisation parameters (paper eq. 3.8, 3.14)."},
      {"solver", "The nonlinear iteration: Newton, or the paper's secant-modulus (Kachanov) "
                 "iteration (eq. 5.2–5.3)."},
      {"adapt", "Adaptive refinement driven by the load's error indicators: remesh where they "
                "are largest until the estimate meets a target (docs/error-estimation.md)."},
      {"thermal", "Hot forming: the steady heat equation in the workpiece, coupled to a "
                  "temperature-dependent flow law (docs/thermal.md)."},
      {"verification",
       "Manufactured solutions for the convergence studies (docs/verification.md)."},
  };
  return sections;
}

const std::vector<CaseKey>& case_keys() {
  static const std::vector<CaseKey> table = make_table();
  return table;
}

const CaseKey* find_case_key(std::string_view name) {
  const auto& table = case_keys();
  const auto found = std::find_if(table.begin(), table.end(),
                                  [name](const CaseKey& key) { return key.name == name; });
  return found == table.end() ? nullptr : &*found;
}

bool is_case_section(std::string_view name) {
  const auto& sections = case_sections();
  return std::any_of(sections.begin(), sections.end(),
                     [name](const CaseSection& section) { return section.name == name; });
}

namespace {

/// A suggestion and how many edits away from the name it is.
struct Nearest {
  std::string_view name;
  std::size_t score = std::string_view::npos;
};

std::string_view leaf_of(std::string_view name) {
  return name.find('.') == std::string_view::npos ? name : name.substr(name.rfind('.') + 1);
}

Nearest nearest_key(std::string_view name) {
  // Longer names than any key cannot be typos of one; the distance would cost O(length).
  if (name.size() > 64) return {};
  const std::string_view section = name.substr(0, name.find('.'));
  const std::string_view leaf = leaf_of(name);
  Nearest best;
  for (const CaseKey& key : case_keys()) {
    if (best.score == 0) break; // the name itself (up to letter case)
    // A right leaf in the wrong section (or no section) costs 2: `speed` → `process.speed`.
    // Only distances below the best so far matter (limit = best − 1).
    const std::size_t penalty = section == key.section() ? 0 : 2;
    const std::size_t limit = best.score - 1;
    const std::size_t leaf_score =
        penalty > limit ? limit + 1 : edit_distance(leaf, key.leaf(), limit - penalty) + penalty;
    const std::size_t score = std::min(edit_distance(name, key.name, limit), leaf_score);
    if (score < best.score) best = {key.name, score};
  }
  return best;
}

Nearest nearest_section(std::string_view name) {
  if (name.size() > 64) return {};
  Nearest best;
  for (const CaseSection& section : case_sections()) {
    if (best.score == 0) break;
    const std::size_t score = edit_distance(name, section.name, best.score - 1);
    if (score < best.score) best = {section.name, score};
  }
  return best;
}

/// A typo: two edits, or a third of the (leaf) name for long names.
bool is_typo_distance(const Nearest& nearest, std::string_view typed) {
  return nearest.score <= std::max<std::size_t>(2, typed.size() / 3);
}

} // namespace

std::string_view closest_case_key(std::string_view name) {
  return nearest_key(name).name;
}

std::string_view closest_case_section(std::string_view name) {
  return nearest_section(name).name;
}

std::string unknown_key_hint(std::string_view name) {
  const Nearest nearest = nearest_key(name);
  if (!is_typo_distance(nearest, leaf_of(name)))
    return "no key is close to it: `formflow case-reference` lists every key";
  return "did you mean `" + std::string(nearest.name) + "`?";
}

std::string unknown_section_hint(std::string_view name) {
  const Nearest nearest = nearest_section(name);
  if (!is_typo_distance(nearest, name)) {
    std::string sections;
    for (const CaseSection& section : case_sections())
      sections += (sections.empty() ? "" : ", ") + std::string(section.name);
    return "no section is close to it; the sections are " + sections;
  }
  return "did you mean `[" + std::string(nearest.name) + "]`?";
}

std::optional<KeyProblem> check_key_value(const CaseKey& key, const KeyValue& value) {
  switch (key.type) {
  case KeyType::Real: {
    const Real number = std::get<Real>(value);
    return check_number(key, number, format_key_value(value));
  }
  case KeyType::Integer: {
    const auto number = static_cast<Real>(std::get<std::int64_t>(value));
    return check_number(key, number, format_key_value(value));
  }
  case KeyType::Enum: {
    const std::string& text = std::get<std::string>(value);
    if (std::find(key.choices.begin(), key.choices.end(), text) == key.choices.end())
      return KeyProblem{"invalid value \"" + text + "\"", "valid values: " + quoted_choices(key)};
    return std::nullopt;
  }
  case KeyType::StringList: return check_list(key, std::get<std::vector<std::string>>(value));
  case KeyType::RealList: {
    const auto& list = std::get<std::vector<Real>>(value);
    if (auto problem = check_entry_count(key, list.size())) return problem;
    for (std::size_t k = 0; k < list.size(); ++k)
      if (auto problem = check_number(key, list[k], format_key_value(KeyValue{list[k]}))) {
        if (list.size() > 1) problem->message = fmt::format("entry {}: {}", k, problem->message);
        return problem;
      }
    return std::nullopt;
  }
  case KeyType::PointList:
    if (auto problem = check_entry_count(key, std::get<KeyPoints>(value).size())) return problem;
    for (const auto& point : std::get<KeyPoints>(value))
      if (!std::isfinite(point[0]) || !std::isfinite(point[1]))
        return KeyProblem{"a point is not finite", "give finite [x, y] pairs"};
    return std::nullopt;
  case KeyType::Text:
    // A path (mesh.file) or PETSc's option text ends at a NUL for every C interface it
    // reaches: the rest would be dropped without a word.
    if (const std::string& text = std::get<std::string>(value);
        text.find('\0') != std::string::npos)
      return KeyProblem{fmt::format("contains a NUL byte (at byte {}), which would silently end "
                                    "the text there",
                                    text.find('\0')),
                        "a path or option text without NUL (\\u0000)"};
    return std::nullopt;
  case KeyType::NameMap:
    for (const auto& [entry, text] : std::get<NameMap>(value))
      if (std::find(key.choices.begin(), key.choices.end(), text) == key.choices.end())
        return KeyProblem{"invalid value \"" + text + "\" for \"" + entry + "\"",
                          "valid values: " + quoted_choices(key)};
    return std::nullopt;
  }
  return std::nullopt;
}

} // namespace formflow::io
