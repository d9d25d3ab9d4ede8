// SPDX-License-Identifier: MIT
// The saddle point as a MATNEST of four AIJ blocks filled through ValueMaps.
#include "formflow/solvers/petsc/saddle_point_nest.hpp"

#include "formflow/core/error.hpp"

#include <span>
#include <type_traits>
#include <vector>

namespace formflow::solvers::petsc {

SaddlePointNest::~SaddlePointNest() {
  if (nest_) MatDestroy(&nest_);
  for (Mat& block : blocks_)
    if (block) MatDestroy(&block);
}

bool SaddlePointNest::build(const CsrPattern& pattern, Index n_first, PetscInt block_size,
                            const assembly::SparseMatrix& input, bool lower_only,
                            const assembly::SparseMatrix& frames, const NodeBlockLayout& layout,
                            Index n_velocity) {
  const auto n = static_cast<Index>(pattern.outer.size()) - 1;
  FF_ASSERT(n_first > 0 && n_first < n, "a saddle point with both fields");
  static_assert(std::is_same_v<PetscInt, Index>, "PETSc's CSR indices are formflow's");
  const std::array<Index, 2> first = {0, n_first}, size = {n_first, n - n_first};
  for (int b = 0; b < 4; ++b) {
    const int row_field = b / 2, column_field = b % 2;
    const Index r0 = first[row_field], c0 = first[column_field];
    const Index c1 = c0 + size[column_field];
    CsrPattern part;
    for (Index row = r0; row < r0 + size[row_field]; ++row) {
      bool diagonal = false;
      for (Index s = pattern.outer[row]; s < pattern.outer[row + 1]; ++s) {
        const Index column = pattern.inner[s];
        if (column < c0 || column >= c1) continue;
        // The pressure block keeps every diagonal entry (zero where C has none, as with
        // d = 0), so that it is never an empty matrix: fieldsplit's Schur complement
        // reads it.
        if (b == 3 && !diagonal && column >= row) {
          diagonal = true;
          if (column > row) part.inner.push_back(row - c0);
        }
        part.inner.push_back(column - c0);
      }
      if (b == 3 && !diagonal) part.inner.push_back(row - c0);
      part.outer.push_back(static_cast<Index>(part.inner.size()));
    }
    const auto m = static_cast<PetscInt>(size[row_field]);
    const auto k = static_cast<PetscInt>(size[column_field]);
    if (MatCreate(PETSC_COMM_SELF, &blocks_[b]) != 0 || MatSetSizes(blocks_[b], m, k, m, k) != 0 ||
        (b == 0 && block_size > 1 && MatSetBlockSize(blocks_[b], block_size) != 0) ||
        MatSetType(blocks_[b], MATSEQAIJ) != 0 ||
        MatSeqAIJSetPreallocationCSR(blocks_[b], part.outer.data(), part.inner.data(), nullptr) !=
            0)
      return false;
    maps_[b] = ValueMap(input, lower_only, frames, layout, part.outer, part.inner, n_velocity,
                        MatrixBlock{r0, c0});
    values_[b] = part.inner.size();
  }
  IS fields[2] = {nullptr, nullptr};
  ISCreateStride(PETSC_COMM_SELF, static_cast<PetscInt>(n_first), 0, 1, &fields[0]);
  ISCreateStride(PETSC_COMM_SELF, static_cast<PetscInt>(n - n_first),
                 static_cast<PetscInt>(n_first), 1, &fields[1]);
  const PetscErrorCode made =
      MatCreateNest(PETSC_COMM_SELF, 2, fields, 2, fields, blocks_.data(), &nest_);
  ISDestroy(&fields[0]);
  ISDestroy(&fields[1]);
  return made == 0;
}

void SaddlePointNest::fill(const assembly::SparseMatrix& input) {
  for (int b = 0; b < 4; ++b) {
    PetscScalar* values = nullptr;
    MatSeqAIJGetArray(blocks_[b], &values);
    maps_[b].fill(input, std::span<Real>(values, values_[b]));
    MatSeqAIJRestoreArray(blocks_[b], &values);
  }
  // The nest's own state: the outer preconditioner sets up anew when it has risen.
  MatAssemblyBegin(nest_, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(nest_, MAT_FINAL_ASSEMBLY);
}

} // namespace formflow::solvers::petsc
