// SPDX-License-Identifier: MIT
// Builders of case-key table rows (io/keys/*_keys.cpp): one fluent KeySpec per key.
#pragma once

#include "formflow/io/case_keys.hpp"

#include <type_traits>
#include <utility>

namespace formflow::io::keys {

/// Fluent description of one key, read like a row of the table; converts to its CaseKey.
struct KeySpec {
  CaseKey key;

  KeySpec(std::string_view name, KeyType type, KeyValue default_value) {
    key.name = name;
    key.type = type;
    key.default_value = std::move(default_value);
    key.unit = "—";
  }
  KeySpec& above(Real value) { return lower({value, false}); }
  KeySpec& at_least(Real value) { return lower({value, true}); }
  KeySpec& below(Real value) { return upper({value, false}); }
  KeySpec& at_most(Real value) { return upper({value, true}); }
  /// 0, or a value ≥ `value` (0 is the key's special case, e.g. an exact constraint).
  KeySpec& zero_or_at_least(Real value) {
    key.smallest_nonzero = value;
    return lower({0.0, true});
  }
  /// Both bounds at once: low ≤ value ≤ high.
  KeySpec& within(Real low, Real high) { return at_least(low).at_most(high); }
  KeySpec& at_most_entries(std::size_t count) { return key.max_entries = count, *this; }
  KeySpec& why(std::string_view text) { return assign(key.range_reason, text); }
  KeySpec& unit(std::string_view text) { return assign(key.unit, text); }
  KeySpec& constraint(std::string_view text) { return assign(key.constraint, text); }
  KeySpec& doc(std::string_view text) { return assign(key.doc, text); }
  operator CaseKey() const { return key; } // NOLINT: implicit, so a table is a braced list

private:
  KeySpec& lower(Bound bound) { return key.lower = bound, *this; }
  KeySpec& upper(Bound bound) { return key.upper = bound, *this; }
  KeySpec& assign(std::string_view& field, std::string_view text) { return field = text, *this; }
};

// `access` is a generic lambda returning a reference to the field, so the same
// accessor serves `set` (Case&) and `get` (const Case&).
template <class Access> KeySpec real_key(std::string_view name, Real default_value, Access access) {
  KeySpec spec(name, KeyType::Real, default_value);
  spec.key.set = [access](Case& case_, const KeyValue& value) {
    access(case_) = std::get<Real>(value);
  };
  spec.key.get = [access](const Case& case_) -> KeyValue { return access(case_); };
  return spec;
}

template <class Access>
KeySpec integer_key(std::string_view name, std::int64_t default_value, Access access) {
  KeySpec spec(name, KeyType::Integer, default_value);
  spec.key.set = [access](Case& case_, const KeyValue& value) {
    access(case_) = static_cast<int>(std::get<std::int64_t>(value));
  };
  spec.key.get = [access](const Case& case_) -> KeyValue { return std::int64_t{access(case_)}; };
  return spec;
}

/// The type of the Case field that `access` refers to.
template <class Access>
using field_type = std::remove_cvref_t<decltype(std::declval<Access>()(std::declval<Case&>()))>;

template <class Access>
KeySpec enum_key(std::string_view name, std::string_view default_value,
                 std::vector<std::pair<std::string_view, field_type<Access>>> mapping,
                 Access access) {
  KeySpec spec(name, KeyType::Enum, std::string(default_value));
  for (const auto& [text, enumerator] : mapping) spec.key.choices.push_back(text);
  spec.key.set = [access, mapping](Case& case_, const KeyValue& value) {
    for (const auto& [text, enumerator] : mapping)
      if (text == std::get<std::string>(value)) access(case_) = enumerator;
  };
  spec.key.get = [access, mapping](const Case& case_) -> KeyValue {
    for (const auto& [text, enumerator] : mapping)
      if (enumerator == access(case_)) return std::string(text);
    return std::string("?");
  };
  return spec;
}

// Why the ranges are what they are; each range keeps every scale the solver
// forms (strain rates, viscosities σ_p/ε̄̇, penalties 1/d, areas, powers) a
// finite, normal double: no product of a few of them can overflow or underflow.
inline constexpr std::string_view length_range =
    "lengths within 1e-6…1e6 keep coordinates, Jacobians, areas and strain rates finite";
inline constexpr std::string_view rate_range =
    "strain rates within 1e-12…1e12 keep σ_p, σ_p/ε̄̇ and their products finite";
inline constexpr std::string_view stress_range =
    "stresses within 1e-12…1e12 keep viscosities, pressures and powers finite";
inline constexpr std::string_view penalty_range =
    "1/d ≤ 1e15: the penalty term stays finite next to the viscous one (0 is the exact "
    "constraint)";
inline constexpr std::string_view exponent_range =
    "a rate exponent in (0, 1] (condition 2.11); ≥ 1e-6 keeps ε̄̇^(exponent − 1) finite";
inline constexpr std::string_view factor_range =
    "a dimensionless factor within 1e-6…1e6 of its scale keeps the augmented terms finite";
inline constexpr std::string_view law_parameter_range =
    "bounded so that σ_p can be evaluated; a combination whose σ_p is not finite and "
    "positive over [rate1/10, 10 rate2] is refused at load time";
inline constexpr std::string_view tolerance_range =
    "a relative change below 1e-15 is round-off: no iteration could ever meet it";

/// The rows of one section, in reference order (each in io/keys/<section>_keys.cpp).
std::vector<CaseKey> process_keys();
std::vector<CaseKey> geometry_keys();
std::vector<CaseKey> mesh_keys();
std::vector<CaseKey> integration_keys();
std::vector<CaseKey> formulation_keys();
std::vector<CaseKey> material_keys();
std::vector<CaseKey> contact_keys();
std::vector<CaseKey> friction_keys();
std::vector<CaseKey> penalty_keys();
std::vector<CaseKey> thermal_keys();
std::vector<CaseKey> adapt_keys();
std::vector<CaseKey> solver_keys();
std::vector<CaseKey> verification_keys();

} // namespace formflow::io::keys
