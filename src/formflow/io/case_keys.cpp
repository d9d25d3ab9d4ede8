// SPDX-License-Identifier: MIT
// The case-key table (names, types, defaults, ranges, units, docs) and its lookups.
#include "formflow/io/case_keys.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <type_traits>
#include <utility>

namespace formflow::io {

namespace {

using physics::ProcessType;
using physics::RamCondition;
using physics::ViscousStrain;

Bound above(Real value) { return {value, false}; }
Bound at_least(Real value) { return {value, true}; }
Bound below(Real value) { return {value, false}; }
Bound at_most(Real value) { return {value, true}; }

// `access` is a generic lambda returning a reference to the field, so the same
// accessor serves `set` (Case&) and `get` (const Case&).
template <class Access>
CaseKey real_key(CaseKey key, Access access) {
  key.type = KeyType::Real;
  key.set = [access](Case& case_, const KeyValue& value) { access(case_) = std::get<Real>(value); };
  key.get = [access](const Case& case_) -> KeyValue { return access(case_); };
  return key;
}

template <class Access>
CaseKey integer_key(CaseKey key, Access access) {
  key.type = KeyType::Integer;
  key.set = [access](Case& case_, const KeyValue& value) {
    access(case_) = static_cast<int>(std::get<std::int64_t>(value));
  };
  key.get = [access](const Case& case_) -> KeyValue { return std::int64_t{access(case_)}; };
  return key;
}

template <class Enum, class Access>
CaseKey enum_key(CaseKey key, std::vector<std::pair<std::string_view, Enum>> mapping,
                 Access access) {
  key.type = KeyType::Enum;
  for (const auto& [text, enumerator] : mapping) key.choices.push_back(text);
  key.set = [access, mapping](Case& case_, const KeyValue& value) {
    for (const auto& [text, enumerator] : mapping)
      if (text == std::get<std::string>(value)) access(case_) = enumerator;
  };
  key.get = [access, mapping](const Case& case_) -> KeyValue {
    for (const auto& [text, enumerator] : mapping)
      if (enumerator == access(case_)) return std::string(text);
    return std::string("?");
  };
  return key;
}

bool contains(const std::vector<std::string>& list, std::string_view entry) {
  return std::find(list.begin(), list.end(), entry) != list.end();
}

CaseKey friction_parts_key() {
  CaseKey key{.name = "friction.on",
              .type = KeyType::StringList,
              .default_value = std::vector<std::string>{"container", "die"},
              .choices = {"container", "die"},
              .unit = "—",
              .doc = "parts of the contact boundary Γ3 with friction: the container wall "
                     "y = H_in and/or the die face x = Lc; [] = frictionless everywhere"};
  key.set = [](Case& case_, const KeyValue& value) {
    const auto& parts = std::get<std::vector<std::string>>(value);
    case_.friction.on_container = contains(parts, "container");
    case_.friction.on_die = contains(parts, "die");
  };
  key.get = [](const Case& case_) -> KeyValue {
    std::vector<std::string> parts;
    if (case_.friction.on_container) parts.emplace_back("container");
    if (case_.friction.on_die) parts.emplace_back("die");
    return parts;
  };
  return key;
}

std::vector<CaseKey> process_and_geometry_keys() {
  return {
      enum_key({.name = "process.type", .default_value = "extrusion", .unit = "—",
                .doc = "extrusion: the ram pushes the rear end Γ1 with the process speed; "
                       "drawing: the front end Γ5 is pulled"},
               {{"extrusion", ProcessType::Extrusion}, {"drawing", ProcessType::Drawing}},
               [](auto& c) -> auto& { return c.process.type; }),
      real_key({.name = "process.speed", .default_value = 1.0, .lower = above(0),
                .unit = "length/time",
                .doc = "prescribed normal speed u⁰ on Γ1 (extrusion) or Γ5 (drawing)"},
               [](auto& c) -> auto& { return c.process.speed; }),
      enum_key({.name = "process.ram", .default_value = "sliding", .unit = "—",
                .doc = "ram condition on Γ1 for extrusion: sliding = σ_T = 0, u_y free "
                       "(the paper's); sticking = u_y = 0 as well"},
               {{"sliding", RamCondition::Sliding}, {"sticking", RamCondition::Sticking}},
               [](auto& c) -> auto& { return c.process.ram; }),
      real_key({.name = "geometry.container_length", .default_value = 10.0, .lower = above(0),
                .constraint = "a multiple of mesh.size", .unit = "length",
                .doc = "L_c: the container part is x ∈ [0, L_c]"},
               [](auto& c) -> auto& { return c.geometry.container_length; }),
      real_key({.name = "geometry.entry_half_height", .default_value = 10.0, .lower = above(0),
                .constraint = "> geometry.exit_half_height; a multiple of mesh.size",
                .unit = "length", .doc = "H_in: half thickness of the billet in the container"},
               [](auto& c) -> auto& { return c.geometry.entry_half_height; }),
      real_key({.name = "geometry.exit_half_height", .default_value = 5.0, .lower = above(0),
                .constraint = "< geometry.entry_half_height; a multiple of mesh.size",
                .unit = "length", .doc = "H_out: half thickness of the product after the die"},
               [](auto& c) -> auto& { return c.geometry.exit_half_height; }),
      real_key({.name = "geometry.exit_length", .default_value = 10.0, .lower = above(0),
                .constraint = "a multiple of mesh.size", .unit = "length",
                .doc = "L_e: the exit part is x ∈ [L_c, L_c + L_e]"},
               [](auto& c) -> auto& { return c.geometry.exit_length; }),
  };
}

std::vector<CaseKey> discretisation_keys() {
  return {
      enum_key({.name = "mesh.element", .default_value = "Q2", .unit = "—",
                .doc = "velocity element: Q1 (4-node bilinear) or Q2 (9-node biquadratic)"},
               {{"Q1", fem::ElementKind::Q1}, {"Q2", fem::ElementKind::Q2}},
               [](auto& c) -> auto& { return c.element; }),
      real_key({.name = "mesh.size", .default_value = 1.0, .lower = above(0),
                .constraint = "divides every geometry length", .unit = "length",
                .doc = "side of the uniform square cells (mesh I: 10/6, mesh II: 1)"},
               [](auto& c) -> auto& { return c.mesh_size; }),
      integer_key({.name = "integration.volumetric", .default_value = std::int64_t{2},
                   .lower = at_least(1), .upper = at_most(3), .unit = "points",
                   .doc = "Gauss points per direction of the volumetric penalty term "
                          "(complete: 2 for Q1, 3 for Q2; reduced: 1, or 2 for Q2); the "
                          "viscous term always uses the complete rule"},
                  [](auto& c) -> auto& { return c.volumetric_points; }),
      enum_key({.name = "formulation.viscous_strain", .default_value = "full", .unit = "—",
                .doc = "strain rate in the viscous a-form: full ε̇ (paper eq. 3.3) or its "
                       "deviator ė (the same as d → 0)"},
               {{"full", ViscousStrain::Full}, {"deviatoric", ViscousStrain::Deviatoric}},
               [](auto& c) -> auto& { return c.viscous_strain; }),
  };
}

std::vector<CaseKey> material_and_contact_keys() {
  return {
      real_key({.name = "material.A", .default_value = 1.7320508075688772, .lower = above(0),
                .unit = "stress·time^α",
                .doc = "A of σ_p = A ε̄̇^α (paper eq. 5.4); √3 gives shear yield k ≈ 1"},
               [](auto& c) -> auto& { return c.material.A; }),
      real_key({.name = "material.alpha", .default_value = 1e-3, .lower = above(0),
                .upper = at_most(1), .unit = "—", .doc = "strain-rate sensitivity α"},
               [](auto& c) -> auto& { return c.material.alpha; }),
      real_key({.name = "material.rate1", .default_value = 1e-3, .lower = above(0),
                .constraint = "< material.rate2", .unit = "1/time",
                .doc = "ε̄̇₁: below it σ_p is continued linearly through the origin"},
               [](auto& c) -> auto& { return c.material.rate1; }),
      real_key({.name = "material.rate2", .default_value = 1e3, .lower = above(0),
                .constraint = "> material.rate1", .unit = "1/time",
                .doc = "ε̄̇₂: above it σ_p is continued linearly through the origin"},
               [](auto& c) -> auto& { return c.material.rate2; }),
      real_key({.name = "friction.mu", .default_value = 0.0, .lower = at_least(0), .unit = "—",
                .doc = "Coulomb coefficient μ_f of the nonlocal friction law τ_f = μ_f σ̄_N"},
               [](auto& c) -> auto& { return c.friction.mu; }),
      real_key({.name = "friction.radius", .default_value = 0.0, .lower = at_least(0),
                .unit = "length",
                .doc = "mollifier radius h of the mean contact pressure σ̄_N; 0 = local"},
               [](auto& c) -> auto& { return c.friction.radius; }),
      friction_parts_key(),
      real_key({.name = "penalty.d", .default_value = 1e-3, .lower = above(0),
                .unit = "1/(stress·time)",
                .doc = "incompressibility penalty: σ_H = ε̇_V/d (paper eq. 3.8)"},
               [](auto& c) -> auto& { return c.penalty.d; }),
      real_key({.name = "penalty.dN", .default_value = 1e-6, .lower = above(0),
                .unit = "length/(stress·time)",
                .doc = "contact penalty d_N: σ_N = −u_N/d_N on Γ3 (paper eq. 3.8)"},
               [](auto& c) -> auto& { return c.penalty.d_n; }),
      real_key({.name = "penalty.dT", .default_value = 1e-6, .lower = above(0),
                .unit = "length/time",
                .doc = "friction regularisation d_T: |u_T| → √(|u_T|² + d_T²) (paper eq. 3.14)"},
               [](auto& c) -> auto& { return c.friction.d_t; }),
  };
}

std::vector<CaseKey> solver_keys() {
  return {
      real_key({.name = "solver.tolerance", .default_value = 1e-4, .lower = above(0),
                .upper = below(1), .unit = "—",
                .doc = "δ: the secant iteration stops when ‖uⁿ⁺¹ − uⁿ‖/‖uⁿ⁺¹‖ < δ"},
               [](auto& c) -> auto& { return c.solver.tolerance; }),
      integer_key({.name = "solver.max_iterations", .default_value = std::int64_t{500},
                   .lower = at_least(1), .upper = at_most(1e9), .unit = "—",
                   .doc = "iteration limit; reaching it is a result (not converged, exit 3)"},
                  [](auto& c) -> auto& { return c.solver.max_iterations; }),
      real_key({.name = "solver.initial_rate", .default_value = 1.0, .lower = above(0),
                .unit = "1/time",
                .doc = "ε̄̇ whose secant viscosity σ_p(ε̄̇)/ε̄̇ gives the constant-viscosity "
                       "first iterate"},
               [](auto& c) -> auto& { return c.solver.initial_rate; }),
  };
}

std::vector<CaseKey> make_table() {
  std::vector<CaseKey> table;
  for (auto part : {process_and_geometry_keys(), discretisation_keys(),
                    material_and_contact_keys(), solver_keys()})
    for (CaseKey& key : part) table.push_back(std::move(key));
  // Group by section in case_sections() order; within a section keep the order above.
  const auto& sections = case_sections();
  auto rank = [&sections](const CaseKey& key) {
    return std::find_if(sections.begin(), sections.end(),
                        [&key](const CaseSection& s) { return s.name == key.section(); }) -
           sections.begin();
  };
  std::stable_sort(table.begin(), table.end(),
                   [&rank](const CaseKey& a, const CaseKey& b) { return rank(a) < rank(b); });
  return table;
}

char lower_case(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

/// Levenshtein distance, ignoring letter case (so `penalty.dn` is next to `penalty.dN`).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution =
          diagonal + (lower_case(a[i - 1]) == lower_case(b[j - 1]) ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

std::optional<KeyProblem> check_number(const CaseKey& key, Real value, const std::string& text) {
  const bool below_lower = key.lower.value && (key.lower.inclusive ? value < *key.lower.value
                                                                   : value <= *key.lower.value);
  const bool above_upper = key.upper.value && (key.upper.inclusive ? value > *key.upper.value
                                                                   : value >= *key.upper.value);
  if (!std::isfinite(value)) return KeyProblem{"value " + text + " is not finite", "must be " + valid_values_text(key)};
  if (below_lower || above_upper)
    return KeyProblem{"value " + text + " is out of range", "must be " + valid_values_text(key)};
  return std::nullopt;
}

std::string quoted_choices(const CaseKey& key) {
  std::string text;
  for (std::string_view choice : key.choices)
    text += (text.empty() ? "\"" : ", \"") + std::string(choice) + "\"";
  return text;
}

std::optional<KeyProblem> check_list(const CaseKey& key, const std::vector<std::string>& list) {
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

}  // namespace

const std::vector<CaseSection>& case_sections() {
  static const std::vector<CaseSection> sections = {
      {"process", "What drives the flow (SPEC §1)."},
      {"geometry", "The half model of the die channel (SPEC §4); lengths are dimensionless."},
      {"mesh", "Uniform square cells of one element kind."},
      {"integration", "Quadrature of the penalty terms (selective reduced integration, SPEC §3)."},
      {"material", "Flow law σ_p = A ε̄̇^α on [rate1, rate2], linear through the origin outside "
                   "(paper eq. 5.4)."},
      {"formulation", "Which form of the a-term is assembled (SPEC §2)."},
      {"friction", "Regularised nonlocal Coulomb friction on Γ3 (paper eq. 3.14–3.15)."},
      {"penalty", "Penalty and regularisation parameters (paper eq. 3.8, 3.14)."},
      {"solver", "The secant-modulus (Kachanov) iteration (paper eq. 5.2–5.3)."},
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

std::string_view closest_case_key(std::string_view name) {
  const std::string_view section = name.substr(0, name.find('.'));
  const std::string_view leaf =
      name.find('.') == std::string_view::npos ? name : name.substr(name.rfind('.') + 1);
  std::string_view best;
  std::size_t best_score = std::string_view::npos;
  for (const CaseKey& key : case_keys()) {
    // A right leaf in the wrong section (or no section) costs 2: `speed` → `process.speed`.
    const std::size_t leaf_score =
        edit_distance(leaf, key.leaf()) + (section == key.section() ? 0 : 2);
    const std::size_t score = std::min(edit_distance(name, key.name), leaf_score);
    if (score < best_score) {
      best_score = score;
      best = key.name;
    }
  }
  return best;
}

std::string_view closest_case_section(std::string_view name) {
  std::string_view best;
  std::size_t best_score = std::string_view::npos;
  for (const CaseSection& section : case_sections()) {
    const std::size_t score = edit_distance(name, section.name);
    if (score < best_score) {
      best_score = score;
      best = section.name;
    }
  }
  return best;
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
  }
  return std::nullopt;
}

}  // namespace formflow::io
