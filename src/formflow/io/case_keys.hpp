// SPDX-License-Identifier: MIT
// The table of every case-file key: the one source of parsing, validation, defaults, JSON and docs.
#pragma once

#include "formflow/io/case.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace formflow::io {

/// The value types a case key can hold. Real keys also accept TOML integers.
/// Text is any string (a path); NameMap is a TOML table of strings whose
/// values are among the key's choices (`[mesh.boundaries]`).
enum class KeyType { Real, Integer, Enum, StringList, PointList, Text, NameMap, RealList };

/// Entries of a NameMap key: TOML key → string value.
using NameMap = std::map<std::string, std::string>;

/// A key's value as read from the case file, before it is stored in a Case:
/// Real → double, Integer → std::int64_t, Enum and Text → std::string,
/// StringList → std::vector<std::string>, PointList → a list of [x, y],
/// NameMap → NameMap, RealList (one number or a list of them) → std::vector<Real>.
using KeyPoints = std::vector<std::array<Real, 2>>;
using KeyValue = std::variant<Real, std::int64_t, std::string, std::vector<std::string>, KeyPoints,
                              NameMap, std::vector<Real>>;

/// A closed or open numeric bound; `std::nullopt` value means unbounded.
struct Bound {
  std::optional<Real> value;
  bool inclusive = false;
};

/// One case-file key: `name` is the dotted name "section.key" (the TOML table
/// and key, and the `--set` spelling). `choices` lists the valid strings of
/// an Enum key or of the entries of a StringList key. `constraint` states the
/// checks that involve other keys (applied by load_case after all keys are set).
/// `unit` is "—" for dimensionless keys; `doc` is one line.
struct CaseKey {
  std::string_view name;
  KeyType type = KeyType::Real;
  KeyValue default_value;
  Bound lower; ///< Real/Integer only
  Bound upper; ///< Real/Integer only
  /// Real only: when set, a value other than 0 must be at least this (0 itself
  /// is a special value, e.g. an exact constraint).
  std::optional<Real> smallest_nonzero;
  /// Why the range is what it is (every range keeps the solver's scales finite).
  std::string_view range_reason;
  /// PointList/StringList only: most entries accepted; 0 = no limit.
  std::size_t max_entries = 0;
  std::vector<std::string_view> choices;
  std::string_view constraint;
  std::string_view unit;
  std::string_view doc;
  /// Stores an already validated value of this key's type into the case.
  std::function<void(Case&, const KeyValue&)> set;
  /// Reads this key's value back from the case.
  std::function<KeyValue(const Case&)> get;

  /// The part before the dot ("friction" for "friction.mu").
  std::string_view section() const { return name.substr(0, name.find('.')); }
  /// The part after the dot ("mu" for "friction.mu").
  std::string_view leaf() const { return name.substr(name.find('.') + 1); }
};

/// A TOML table of the case file, with a one-line description.
struct CaseSection {
  std::string_view name;
  std::string_view doc;
};

/// Why a value is not valid for a key: `message` says what is wrong, `hint` what would be valid.
struct KeyProblem {
  std::string message;
  std::string hint;
};

/// Every key, grouped by section in `case_sections()` order.
const std::vector<CaseKey>& case_keys();

/// The sections, in the order they appear in the reference and in a case file.
const std::vector<CaseSection>& case_sections();

/// The key named `name` ("friction.mu"), or nullptr.
const CaseKey* find_case_key(std::string_view name);

/// Whether `name` is a section ("friction").
bool is_case_section(std::string_view name);

/// The valid key nearest to `name` (edit distance on the full name and on the
/// part after the dot), for "did you mean" hints.
std::string_view closest_case_key(std::string_view name);

/// The section nearest to `name` by edit distance.
std::string_view closest_case_section(std::string_view name);

/// The hint for an unknown key: "did you mean `friction.mu`?" when the closest
/// key is within a typo's distance of `name` (at most 2 edits, or a third of
/// the part after the dot for long names), otherwise a pointer to the reference
/// (a far-off name gets no arbitrary suggestion).
std::string unknown_key_hint(std::string_view name);

/// The hint for an unknown section, by the same rule as unknown_key_hint.
std::string unknown_section_hint(std::string_view name);

/// Checks `value` (already of the key's type) against the key's own range or
/// choices; std::nullopt when valid. Cross-key constraints are not checked here.
std::optional<KeyProblem> check_key_value(const CaseKey& key, const KeyValue& value);

/// The value as it would be written in a case file: 0.001, 500, "Q2", ["container", "die"].
std::string format_key_value(const KeyValue& value);

/// The human-readable name of a key type ("real", "integer", "string", "list of strings").
std::string_view key_type_name(KeyType type);

/// The valid-values text of a key: "> 0", "0 < value ≤ 1", `"Q1" | "Q2"`, plus its constraint.
std::string valid_values_text(const CaseKey& key);

/// Markdown reference of every key (docs/case-reference.md): one table per
/// section with key, type, default, valid values, unit and description.
std::string case_reference_markdown();

} // namespace formflow::io
