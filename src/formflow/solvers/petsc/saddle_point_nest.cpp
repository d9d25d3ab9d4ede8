// SPDX-License-Identifier: MIT
// The saddle point as a MATNEST of four AIJ blocks, the velocity's filled through a ValueMap.
#include "formflow/solvers/petsc/saddle_point_nest.hpp"

#include "formflow/core/error.hpp"
#include "formflow/solvers/petsc/framed_coupling.hpp"

#include <Eigen/SparseCore>

#include <span>
#include <type_traits>
#include <vector>

namespace formflow::solvers::petsc {

SaddlePointNest::~SaddlePointNest() {
  if (nest_) MatDestroy(&nest_);
  for (Mat& block : blocks_)
    if (block) MatDestroy(&block);
}

namespace {

using RowMatrix = Eigen::SparseMatrix<Real, Eigen::RowMajor, Index>;

CsrPattern pattern_of(const RowMatrix& rows) {
  CsrPattern pattern;
  pattern.outer.assign(rows.outerIndexPtr(), rows.outerIndexPtr() + rows.rows() + 1);
  pattern.inner.assign(rows.innerIndexPtr(), rows.innerIndexPtr() + rows.nonZeros());
  return pattern;
}

} // namespace

bool SaddlePointNest::build_from_blocks(const assembly::SparseMatrix& velocity_lower,
                                        const assembly::SparseMatrix& coupling,
                                        const assembly::SparseMatrix& pressure_block,
                                        const assembly::SparseMatrix& frames,
                                        const NodeBlockLayout& layout, PetscInt block_size) {
  const Index n_v = velocity_lower.rows(), n_p = pressure_block.rows();
  FF_ASSERT(coupling.rows() == n_p && coupling.cols() == n_v, "B is n_p × n_v");
  const CsrPattern a = solved_pattern(velocity_lower, true, frames, layout);
  const auto n_first = static_cast<Index>(a.outer.size()) - 1;
  if (!make_block(0, n_first, n_first, a, nullptr, block_size)) return false;
  velocity_map_ = ValueMap(velocity_lower, true, frames, layout, a.outer, a.inner, n_v);
  // Bᵀ in the solved unknowns, P Qᵀ Bᵀ (n_first × n_p), and B Q Pᵀ, its transpose.
  std::vector<Eigen::Triplet<Real, Index>> entries = framed_coupling(coupling, frames, layout);
  RowMatrix upper(n_first, n_p);
  upper.setFromTriplets(entries.begin(), entries.end());
  upper.makeCompressed();
  RowMatrix lower = upper.transpose();
  lower.makeCompressed();
  // C with every diagonal entry (zero where C has none, as with d = 0): fieldsplit's
  // Schur complement reads the block, which must not be an empty matrix.
  entries.clear();
  for (Index column = 0; column < pressure_block.outerSize(); ++column)
    for (assembly::SparseMatrix::InnerIterator it(pressure_block, column); it; ++it)
      entries.emplace_back(it.row(), column, it.value());
  for (Index i = 0; i < n_p; ++i) entries.emplace_back(i, i, 0.0);
  RowMatrix c(n_p, n_p);
  c.setFromTriplets(entries.begin(), entries.end());
  c.makeCompressed();
  if (!make_block(1, n_first, n_p, pattern_of(upper), upper.valuePtr(), 1) ||
      !make_block(2, n_p, n_first, pattern_of(lower), lower.valuePtr(), 1) ||
      !make_block(3, n_p, n_p, pattern_of(c), c.valuePtr(), 1))
    return false;
  return nest(n_first, n_first + n_p);
}

bool SaddlePointNest::make_block(int b, Index rows, Index columns, const CsrPattern& pattern,
                                 const Real* values, PetscInt block_size) {
  const auto m = static_cast<PetscInt>(rows), k = static_cast<PetscInt>(columns);
  if (b == 0) velocity_values_ = pattern.inner.size();
  return MatCreate(PETSC_COMM_SELF, &blocks_[b]) == 0 && MatSetSizes(blocks_[b], m, k, m, k) == 0 &&
         (block_size <= 1 || MatSetBlockSize(blocks_[b], block_size) == 0) &&
         MatSetType(blocks_[b], MATSEQAIJ) == 0 &&
         MatSeqAIJSetPreallocationCSR(blocks_[b], pattern.outer.data(), pattern.inner.data(),
                                      values) == 0;
}

bool SaddlePointNest::nest(Index n_first, Index n) {
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

void SaddlePointNest::fill(const assembly::SparseMatrix& velocity_lower) {
  PetscScalar* values = nullptr;
  MatSeqAIJGetArray(blocks_[0], &values);
  velocity_map_.fill(velocity_lower, std::span<Real>(values, velocity_values_));
  MatSeqAIJRestoreArray(blocks_[0], &values);
  // The nest's own state: the outer preconditioner sets up anew when it has risen.
  MatAssemblyBegin(nest_, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(nest_, MAT_FINAL_ASSEMBLY);
}

} // namespace formflow::solvers::petsc
