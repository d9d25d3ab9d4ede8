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
std::vector<CaseKey> solver_keys();
std::vector<CaseKey> verification_keys();

} // namespace formflow::io::keys
