// SPDX-License-Identifier: MIT
// Case keys of the [process] section (What drives the flow): rows of the table in io/case_keys.cpp.
#include "formflow/io/keys/key_spec.hpp"

namespace formflow::io::keys {

using physics::ProcessType;
using physics::RamCondition;

std::vector<CaseKey> process_keys() {
  return {
      enum_key(
          "process.type", "extrusion",
          {{"extrusion", ProcessType::Extrusion}, {"drawing", ProcessType::Drawing}},
          [](auto& c) -> auto& { return c.process.type; })
          .doc("extrusion: the ram pushes the rear end Γ1 with the process speed; "
               "drawing: the front end Γ5 is pulled"),
      real_key(
          "process.speed", 1.0, [](auto& c) -> auto& { return c.process.speed; })
          .within(1e-6, 1e6)
          .why("with lengths within 1e-6…1e6 it keeps strain rates within 1e-12…1e12, where "
               "σ_p and σ_p/ε̄̇ are finite")
          .unit("length/time")
          .doc("prescribed normal speed u⁰ on Γ1 (extrusion) or Γ5 (drawing)"),
      enum_key(
          "process.ram", "sliding",
          {{"sliding", RamCondition::Sliding}, {"sticking", RamCondition::Sticking}},
          [](auto& c) -> auto& { return c.process.ram; })
          .doc("ram condition on Γ1 for extrusion: sliding = σ_T = 0, u_y free (the paper's); "
               "sticking = u_y = 0 as well"),
  };
}

} // namespace formflow::io::keys
