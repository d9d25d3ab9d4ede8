// SPDX-License-Identifier: MIT
#include "formflow/solvers/petsc/framed_coupling.hpp"

namespace formflow::solvers::petsc {

std::vector<Eigen::Triplet<Real, Index>> framed_coupling(const assembly::SparseMatrix& coupling,
                                                         const assembly::SparseMatrix& frames,
                                                         const NodeBlockLayout& layout) {
  // B is a small part of the saddle point's nonzeros, made once: through Eigen.
  assembly::SparseMatrix framed = coupling.transpose();
  if (frames.size() != 0) framed = assembly::SparseMatrix(frames.transpose() * framed);
  std::vector<Eigen::Triplet<Real, Index>> entries;
  entries.reserve(static_cast<std::size_t>(framed.nonZeros()));
  for (Index column = 0; column < framed.outerSize(); ++column)
    for (assembly::SparseMatrix::InnerIterator it(framed, column); it; ++it)
      entries.emplace_back(layout.empty() ? it.row() : layout.position(it.row()), column,
                           it.value());
  return entries;
}

} // namespace formflow::solvers::petsc
