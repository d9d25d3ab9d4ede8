// SPDX-License-Identifier: MIT
// Case keys of the [integration] section (Quadrature of the volumetric term): rows of the table in
// io/case_keys.cpp.
#include "formflow/io/keys/key_spec.hpp"

namespace formflow::io::keys {

std::vector<CaseKey> integration_keys() {
  return {
      integer_key(
          "integration.volumetric", 2, [](auto& c) -> auto& { return c.volumetric_points; })
          .at_least(1)
          .at_most(3)
          .unit("points")
          .doc("Gauss points per direction of the volumetric penalty term (complete: 2 for "
               "Q1, 3 for Q2; reduced: 1, or 2 for Q2); the viscous term always uses the "
               "complete rule. Not set: the element's reduced rule, 2 for Q2 and 1 for Q1 (the "
               "complete rule locks Q1: asked for explicitly, it is kept with a warning); "
               "summary.json's case records the rule used"),
  };
}

} // namespace formflow::io::keys
