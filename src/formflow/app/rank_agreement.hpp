// SPDX-License-Identifier: MIT
// Before any collective call of a run on several MPI ranks, the ranks agree that they
// read the same case and that none of them refused its input: ranks that read different
// case files (a file that differs between hosts) would otherwise take different branches
// and wait for each other for ever, and an input error seen by one rank only (a file
// missing on its host) would leave the others waiting in the solve.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace formflow::app {

/// FNV-1a, 64 bits: a fingerprint of text (not a cryptographic hash: it detects
/// accidental differences between the ranks' cases, which is all it is for).
std::uint64_t text_fingerprint(std::string_view text);

/// How many ranks hold a `value` other than rank 0's (collective; 0 on one rank).
int ranks_differing_from_rank_zero(std::uint64_t value);

/// What a rank read: where from (a case file's path, for the message) and the resolved
/// input as text (the ranks compare its fingerprint).
struct ReadInput {
  std::string source;
  std::string resolved;
};

/// Runs `read` (the front end's loading and checks of the case) on every rank and agrees
/// on the outcome (collective; on one rank it just runs `read`). When some rank's `read`
/// threw InputError, every rank throws the lowest such rank's error (its file, line, key,
/// message and hint, sent to all, the message prefixed "(MPI rank k)" when k ≠ 0): rank 0
/// prints it once and every rank exits 2 at once. When every rank read its input, one
/// whose resolved text differs from rank 0's is refused.
void agree_on_input(const std::function<ReadInput()>& read);

} // namespace formflow::app
