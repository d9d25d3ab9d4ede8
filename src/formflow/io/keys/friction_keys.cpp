// SPDX-License-Identifier: MIT
// Case keys of the [friction] section (Friction on the contact boundary): rows of the table in
// io/case_keys.cpp.
#include "formflow/io/keys/key_spec.hpp"

#include <algorithm>

namespace formflow::io::keys {

namespace {

bool contains(const std::vector<std::string>& list, std::string_view entry) {
  return std::find(list.begin(), list.end(), entry) != list.end();
}

KeySpec friction_parts_key() {
  KeySpec spec("friction.on", KeyType::StringList, std::vector<std::string>{"container", "die"});
  spec.key.choices = {"container", "die"};
  spec.key.set = [](Case& case_, const KeyValue& value) {
    const auto& parts = std::get<std::vector<std::string>>(value);
    case_.friction.on_container = contains(parts, "container");
    case_.friction.on_die = contains(parts, "die");
  };
  spec.key.get = [](const Case& case_) -> KeyValue {
    std::vector<std::string> parts;
    if (case_.friction.on_container) parts.emplace_back("container");
    if (case_.friction.on_die) parts.emplace_back("die");
    return parts;
  };
  return spec.doc("parts of the contact boundary Γ3 with friction: the container wall y = H_in "
                  "and/or the die (its face and its land); [] = frictionless everywhere");
}

} // namespace

std::vector<CaseKey> friction_keys() {
  using physics::FrictionLaw;
  return {
      // The registration of the friction laws (physics/friction.hpp visit_threshold).
      enum_key(
          "friction.law", "coulomb",
          {{"coulomb", FrictionLaw::Coulomb},
           {"tresca", FrictionLaw::Tresca},
           {"hybrid", FrictionLaw::Hybrid}},
          [](auto& c) -> auto& { return c.friction.law; })
          .doc("threshold τ_f of the friction law: coulomb = μ_f max(σ̄_N, 0) (the paper's, "
               "nonlocal with friction.radius); tresca = m k, k = σ_p(max(ε̄̇, rate1))/√3 the "
               "shear yield stress at the surface point; hybrid = min(coulomb, tresca)"),
      real_key(
          "friction.mu", 0.0, [](auto& c) -> auto& { return c.friction.mu; })
          .within(0, 10)
          .why("μ_f σ̄_N beyond 10 σ̄_N exceeds any shear the metal can carry: the contact sticks; "
               "the bound keeps τ_f finite")
          .doc("Coulomb coefficient μ_f of the nonlocal friction law τ_f = μ_f σ̄_N "
               "(friction.law = \"coulomb\" or \"hybrid\")"),
      real_key(
          "friction.m", 0.0, [](auto& c) -> auto& { return c.friction.m; })
          .within(0, 1)
          .why("a fraction of the shear yield stress k: 0 frictionless, 1 the interface shears "
               "like the metal")
          .doc("Tresca friction factor m of τ_f = m k (friction.law = \"tresca\" or "
               "\"hybrid\"): 0 frictionless, 1 the interface shears like the metal"),
      real_key(
          "friction.radius", 0.0, [](auto& c) -> auto& { return c.friction.radius; })
          .zero_or_at_least(1e-6)
          .at_most(1e6)
          .why(length_range)
          .unit("length")
          .doc("mollifier radius h of the mean contact pressure σ̄_N; 0 = local pressure"),
      friction_parts_key(),
      enum_key(
          "friction.regularization", "regularized",
          {{"regularized", physics::FrictionRegularization::Regularized},
           {"none", physics::FrictionRegularization::None}},
          [](auto& c) -> auto& { return c.friction.regularization; })
          .doc("regularized: the paper's |u_T| → √(|u_T|² + d_T²) with penalty.dT (eq. 3.14); "
               "none: exact Coulomb law by an augmented Lagrangian on the friction traction "
               "(docs/friction.md)"),
      real_key(
          "friction.augmentation", 1.0, [](auto& c) -> auto& { return c.friction.augmentation; })
          .within(1e-6, 1e6)
          .why(factor_range)
          .unit("1/penalty.dN")
          .doc("exact friction with solver.method = \"secant\" (or a mixed formulation): "
               "augmentation r = value/d_N of λ_T = proj(λ_T + r u_T); "
               "any value converges, larger takes fewer multiplier updates"),
      real_key(
          "friction.newton_augmentation", 100.0,
          [](auto& c) -> auto& { return c.friction.newton_augmentation; })
          .within(1e-6, 1e6)
          .why(factor_range)
          .unit("1/penalty.dN")
          .doc("exact friction solved by Newton (solver.method = \"newton\"; penalty, or mixed "
               "with a condensed pressure): r = value/d_N; Newton's tangent carries the stick "
               "penalty, and a stiffer one settles the multipliers in fewer updates "
               "(docs/friction.md)"),
      enum_key(
          "friction.stick", "auto",
          {{"auto", StickEnforcement::Auto},
           {"augmented", StickEnforcement::Augmented},
           {"exact", StickEnforcement::Exact}},
          [](auto& c) -> auto& { return c.friction_stick; })
          .doc("how exact friction's Newton loop holds stuck points: exact = a semismooth "
               "Newton with u_T = 0 imposed in every step at the stuck Γ3 nodes (on nodal "
               "contact points: contact.normals not given becomes \"nodes\"; r then only "
               "predicts the active set and is 1/d_N unless friction.newton_augmentation is "
               "given); augmented = the stick penalty r and a multiplier update per iteration "
               "(on face points unless contact.normals = \"nodes\"); auto = exact for the exact "
               "law under Newton unless contact.normals = \"faces\" is given, augmented "
               "otherwise (summary.json contact.stick says which ran; docs/friction.md)"),
  };
}

} // namespace formflow::io::keys
