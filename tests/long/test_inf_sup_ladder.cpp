// SPDX-License-Identifier: MIT
// The full inf-sup table of docs/mixed.md (h = 1/4 … 1/16; about a minute).
#include "verification/inf_sup_table.hpp"

#include <gtest/gtest.h>

namespace formflow::testing {
namespace {

TEST(InfSupLadder, TableOfDocsMixed) {
  const auto table = inf_sup_table({4, 8, 16});
  // Q2–P1disc stays bounded over the whole ladder; Q1–P0 keeps decaying.
  EXPECT_GT(table[0][2].beta, 0.9 * table[0][0].beta);
  EXPECT_LT(table[4][2].beta, 0.6 * table[4][0].beta);
}

} // namespace
} // namespace formflow::testing
