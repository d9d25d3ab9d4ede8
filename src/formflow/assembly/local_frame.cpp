// SPDX-License-Identifier: MIT
// Orthonormal changes of basis of a few unknowns each.
#include "formflow/assembly/local_frame.hpp"

#include "formflow/core/error.hpp"

namespace formflow::assembly {

namespace {

/// The entries of `x` on the frame's rows.
VectorX frame_entries(const LocalFrame& frame, const VectorX& x) {
  VectorX entries(static_cast<Index>(frame.rows.size()));
  for (std::size_t i = 0; i < frame.rows.size(); ++i) {
    FF_ASSERT(frame.rows[i] < x.size(), "a frame row inside the vector");
    entries[static_cast<Index>(i)] = x[frame.rows[i]];
  }
  return entries;
}

void put_frame_entries(const LocalFrame& frame, const VectorX& entries, VectorX& x) {
  for (std::size_t i = 0; i < frame.rows.size(); ++i)
    x[frame.rows[i]] = entries[static_cast<Index>(i)];
}

} // namespace

void to_frames(std::span<const LocalFrame> frames, VectorX& x) {
  for (const LocalFrame& frame : frames)
    put_frame_entries(frame, frame.basis.transpose() * frame_entries(frame, x), x);
}

void from_frames(std::span<const LocalFrame> frames, VectorX& y) {
  for (const LocalFrame& frame : frames)
    put_frame_entries(frame, frame.basis * frame_entries(frame, y), y);
}

SparseMatrix frame_matrix(std::span<const LocalFrame> frames, Index n) {
  std::vector<Eigen::Triplet<Real, Index>> entries;
  std::vector<bool> in_frame(static_cast<std::size_t>(n), false);
  for (const LocalFrame& frame : frames)
    for (std::size_t i = 0; i < frame.rows.size(); ++i) {
      FF_ASSERT(frame.rows[i] < n && !in_frame[frame.rows[i]], "frames on distinct rows");
      in_frame[frame.rows[i]] = true;
      for (std::size_t j = 0; j < frame.rows.size(); ++j)
        entries.emplace_back(frame.rows[i], frame.rows[j],
                             frame.basis(static_cast<Index>(i), static_cast<Index>(j)));
    }
  for (Index row = 0; row < n; ++row)
    if (!in_frame[row]) entries.emplace_back(row, row, 1.0);
  SparseMatrix q(n, n);
  q.setFromTriplets(entries.begin(), entries.end());
  return q;
}

} // namespace formflow::assembly
