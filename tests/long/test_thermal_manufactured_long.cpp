// SPDX-License-Identifier: MIT
// The coupled manufactured solution of hot forming on three-rung ladders (issue 18;
// docs/verification.md shows the table it prints).
#include "verification/thermal_manufactured_support.hpp"

#include <string>
#include <vector>

namespace formflow {
namespace {

void ladder(fem::ElementKind element, const std::vector<Real>& sizes) {
  std::vector<testing::Errors> errors;
  for (const Real size : sizes) {
    errors.push_back(testing::errors_of(element, size));
    const testing::Errors& e = errors.back();
    std::printf("%s h = 1/%.0f: velocity V %.3e L2 %.3e, temperature H1 %.3e L2 %.3e",
                std::string(fem::element_name(element)).c_str(), 1.0 / size, e.velocity_v,
                e.velocity_l2, e.temperature_h1, e.temperature_l2);
    if (errors.size() > 1) {
      const testing::Errors& c = errors[errors.size() - 2];
      std::printf("; orders %.2f %.2f %.2f %.2f", testing::order(c.velocity_v, e.velocity_v),
                  testing::order(c.velocity_l2, e.velocity_l2),
                  testing::order(c.temperature_h1, e.temperature_h1),
                  testing::order(c.temperature_l2, e.temperature_l2));
    }
    std::printf("\n");
  }
  // Every pair, not only the finest: the orders hold over the ladder.
  for (std::size_t k = 1; k < errors.size(); ++k)
    testing::expect_orders(fem::element_order(element), errors[k - 1], errors[k]);
}

TEST(ThermalManufacturedLong, Q1LadderTo64) {
  ladder(fem::ElementKind::Q1, {1.0 / 8, 1.0 / 16, 1.0 / 32, 1.0 / 64});
}

TEST(ThermalManufacturedLong, Q2LadderTo32) {
  ladder(fem::ElementKind::Q2, {1.0 / 4, 1.0 / 8, 1.0 / 16, 1.0 / 32});
}

} // namespace
} // namespace formflow
