// SPDX-License-Identifier: MIT
#include "formflow/app/rank_agreement.hpp"

#include "formflow/app/distributed_run.hpp"
#include "formflow/core/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace formflow::app {

namespace {

/// The longest error text sent from a failing rank to rank 0 (file, key, message, hint).
constexpr std::size_t max_message_bytes = 4096;

/// A 64-bit value as four 16-bit pieces, each exact in a double and in any sum of up to
/// 2³⁷ of them: the ranks' sums compare it without rounding.
std::array<Real, 4> pieces(std::uint64_t value) {
  std::array<Real, 4> out{};
  for (int k = 0; k < 4; ++k) out[k] = static_cast<Real>((value >> (16 * k)) & 0xffffu);
  return out;
}

/// The lowest rank whose `failed` is true, or -1 (collective).
int lowest_failing_rank(bool failed) {
  const assembly::Distribution& run = distribution();
  // One slot per rank: a sum of one-hot vectors names every rank that failed.
  std::vector<Real> slots(static_cast<std::size_t>(run.size), 0.0);
  if (failed) slots[static_cast<std::size_t>(run.rank)] = 1.0;
  run.sum_over_ranks(std::span<Real>(slots));
  for (int rank = 0; rank < run.size; ++rank)
    if (slots[static_cast<std::size_t>(rank)] > 0) return rank;
  return -1;
}

} // namespace

std::uint64_t text_fingerprint(std::string_view text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return hash;
}

int ranks_differing_from_rank_zero(std::uint64_t value) {
  const assembly::Distribution& run = distribution();
  if (!run.distributed()) return 0;
  // Rank 0's value to every rank by a sum to which the others add zeros.
  std::array<Real, 4> first = pieces(value);
  if (run.rank != 0) first.fill(0.0);
  run.sum_over_ranks(std::span<Real>(first));
  Real differing = pieces(value) == first ? 0.0 : 1.0;
  run.sum_over_ranks(std::span<Real>(&differing, 1));
  return static_cast<int>(std::lround(differing));
}

void agree_on_input(const std::function<ReadInput()>& read) {
  const assembly::Distribution& run = distribution();
  if (!run.distributed()) {
    read();
    return;
  }
  std::optional<InputError> refused;
  ReadInput input;
  try {
    input = read();
  } catch (const InputError& error) {
    refused = error;
  }
  if (const int failing = lowest_failing_rank(refused.has_value()); failing >= 0) {
    // The failing rank's error to every rank (rank 0 alone prints): its fields, then
    // its line, sent as a sum to which the others add zeros.
    std::vector<Real> text(max_message_bytes + 1, 0.0);
    if (run.rank == failing) {
      const std::string fields = refused->file + '\x1f' + refused->key + '\x1f' + refused->message +
                                 '\x1f' + refused->hint;
      for (std::size_t k = 0; k < std::min(fields.size(), max_message_bytes); ++k)
        text[k] = static_cast<unsigned char>(fields[k]);
      text[max_message_bytes] = refused->line;
    }
    run.sum_over_ranks(std::span<Real>(text));
    std::string fields;
    for (std::size_t k = 0; k < max_message_bytes && text[k] != 0; ++k)
      fields.push_back(static_cast<char>(static_cast<unsigned char>(text[k])));
    std::array<std::string, 4> part;
    std::size_t at = 0;
    for (std::string& piece : part) {
      const std::size_t end_of = std::min(fields.find('\x1f', at), fields.size());
      piece = fields.substr(std::min(at, fields.size()), end_of - std::min(at, fields.size()));
      at = end_of + 1;
    }
    const std::string where = failing == 0 ? "" : fmt::format("(MPI rank {}) ", failing);
    throw InputError(part[0], static_cast<int>(text[max_message_bytes]), part[1], where + part[2],
                     part[3]);
  }
  const int differing = ranks_differing_from_rank_zero(text_fingerprint(input.resolved));
  if (differing > 0)
    throw InputError(input.source.empty() ? "command line" : input.source, 0, "mpirun",
                     fmt::format("{} of the {} MPI ranks read a case that differs from rank 0's "
                                 "(its resolved keys): they would take different branches and "
                                 "wait for each other",
                                 differing, run.size),
                     "give every rank the same case file and --set values (a file that differs "
                     "between hosts, or a rank started with other arguments)");
}

} // namespace formflow::app
