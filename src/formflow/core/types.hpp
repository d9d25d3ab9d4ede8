// SPDX-License-Identifier: MIT
// Scalar, index and small fixed-size vector types shared by every layer.
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace formflow {

using Real = double;
/// Global indices (nodes, cells, dofs). Signed to match Eigen's StorageIndex.
using Index = int;

template <int dim> using Point = Eigen::Matrix<Real, dim, 1>;
template <int dim> using Tensor2 = Eigen::Matrix<Real, dim, dim>;
/// Strain-rate and stress tensors are always 3×3: plane strain keeps zz = 0,
/// axisymmetry fills θθ, 3D fills everything.
using Tensor3 = Eigen::Matrix<Real, 3, 3>;

using VectorX = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
using MatrixX = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
/// A row over one cell's local dofs: at most 27 nodes × 3 components (Q2 hexahedron),
/// so kernels keep it on the stack instead of allocating per cell or point.
using CellVector = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, 81, 1>;

} // namespace formflow
