// SPDX-License-Identifier: MIT
// Case keys of the [penalty] section (Penalty and regularisation parameters): rows of the table in
// io/case_keys.cpp.
#include "formflow/io/keys/key_spec.hpp"

namespace formflow::io::keys {

std::vector<CaseKey> penalty_keys() {
  return {
      real_key(
          "penalty.d", 1e-3, [](auto& c) -> auto& { return c.penalty.d; })
          .zero_or_at_least(1e-15)
          .at_most(1e3)
          .why(penalty_range)
          .constraint("0 (exact incompressibility) only with formulation.type = \"mixed\"")
          .unit("1/(stress·time)")
          .doc("incompressibility penalty: σ_H = ε̇_V/d (paper eq. 3.8); 0 = exact constraint "
               "(Uzawa steps)"),
      real_key(
          "penalty.dN", 1e-6, [](auto& c) -> auto& { return c.penalty.d_n; })
          .zero_or_at_least(1e-15)
          .at_most(1e3)
          .why(penalty_range)
          .unit("length/(stress·time)")
          .doc("contact penalty d_N: σ_N = −u_N/d_N on Γ3 (paper eq. 3.8); 0 = exact u_N = 0 "
               "(Uzawa steps)"),
      real_key(
          "penalty.dT", 1e-6, [](auto& c) -> auto& { return c.friction.d_t; })
          .within(1e-15, 1e3)
          .why("d_T within 1e-15…1e3 keeps √(|u_T|² + d_T²) and its inverse finite")
          .unit("length/time")
          .doc("friction regularisation d_T: |u_T| → √(|u_T|² + d_T²) (paper eq. 3.14)"),
  };
}

} // namespace formflow::io::keys
