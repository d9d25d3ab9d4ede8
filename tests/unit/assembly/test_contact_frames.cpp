// SPDX-License-Identifier: MIT
// The Γ3 nodes' normal–tangent frames (assembly/contact_frames.hpp): orthonormal, and
// with nodal normals the contact penalty seen in them is one diagonal entry per node.
#include "formflow/assembly/contact_frames.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"
#include "support/newton_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

namespace formflow::testing {
namespace {

/// The 30° wedge channel (Q2, h = 0.5): its die face's normal is no coordinate axis.
mesh::Mesh<2> wedge_channel() {
  mesh::ChannelGeometry geometry{2.0, 2.0, 1.0, 2.0};
  geometry.die = mesh::DieShape::Wedge;
  geometry.die_angle = 30.0;
  return mesh::make_die_channel_mesh(geometry, 0.5, 2);
}

/// The secant matrix at `u` (free dofs, both triangles) of a frictionless problem with
/// nodal normals and the contact penalty 1/d_N; u is the fixture's (the same random
/// velocity for every d_N).
MatrixX secant_matrix(const mesh::Mesh<2>& mesh, Real d_n,
                      std::vector<assembly::LocalFrame>* frames = nullptr) {
  assembly::ProblemSettings settings;
  settings.law = sensitive_law();
  settings.contact.normals = assembly::ContactNormals::Nodes;
  settings.penalty.d_n = d_n;
  const SmallExtrusionIn<2> extrusion(settings, mesh);
  assembly::LinearSystem system = extrusion.problem->plan().make_system();
  extrusion.problem->assemble(&extrusion.u, system);
  if (frames) *frames = assembly::contact_frames(extrusion.problem->discretisation());
  const MatrixX lower = MatrixX(system.matrix);
  return lower + lower.transpose() - MatrixX(lower.diagonal().asDiagonal());
}

TEST(ContactFrames, NodalNormalPenaltyIsOneDiagonalEntryPerNodeInTheFrames) {
  const mesh::Mesh<2> mesh = wedge_channel();
  std::vector<assembly::LocalFrame> frames;
  const MatrixX stiff = secant_matrix(mesh, 1e-6, &frames);
  ASSERT_FALSE(frames.empty());
  // Every frame orthonormal. Gram–Schmidt of k unit vectors leaves each column's
  // direction and norm wrong by at most 2kε, and each of the k² entries of QᵀQ is a
  // k-term dot product (kε more): |QᵀQ − I|_F ≤ k · 4kε = 4k²ε, doubled as a margin.
  constexpr Real epsilon = std::numeric_limits<Real>::epsilon();
  Index k_max = 0;
  for (const assembly::LocalFrame& frame : frames) {
    const auto k = static_cast<Index>(frame.rows.size());
    k_max = std::max(k_max, k);
    EXPECT_LT((frame.basis.transpose() * frame.basis - MatrixX::Identity(k, k)).norm(),
              8.0 * k * k * epsilon);
  }
  // The same velocity, another penalty: the difference is (10⁶ − 1) P, P the lumped
  // penalty's matrix (node-diagonal blocks w n nᵀ), every other term unchanged
  // (frictionless; the viscosity reads u only).
  const MatrixX penalty = stiff - secant_matrix(mesh, 1.0);
  const MatrixX q = MatrixX(assembly::frame_matrix(frames, penalty.rows()));
  const MatrixX in_frames = q.transpose() * penalty * q;
  const auto off_diagonal = [](const MatrixX& m) {
    return (m - MatrixX(m.diagonal().asDiagonal())).cwiseAbs().maxCoeff();
  };
  // Cartesian: the inclined normals couple the two components of a node at the size
  // of the penalty. In the frames: only round-off. Each difference entry errs by at
  // most 2ε max|stiff| (two roundings of entries ≤ max|stiff|), and an entry of QᵀPQ
  // sums dim² = 4 products of them with |q| ≤ 1: 8ε max|stiff|, doubled for the
  // products' own rounding.
  const Real round_off = 16 * epsilon * stiff.cwiseAbs().maxCoeff();
  EXPECT_GT(off_diagonal(penalty), 0.1 * penalty.cwiseAbs().maxCoeff());
  EXPECT_LE(off_diagonal(in_frames), round_off);
  // Vectors: to_frames and from_frames are inverse, and agree with Q. Each entry of Qᵀx
  // is a k-term dot product, by both routes: they differ by at most 2kε |x| (the dense
  // product's other terms are exact zeros). The round trip adds that twice and the
  // frames' departure from orthonormality (8k²ε, above).
  const VectorX x = random_vector(penalty.rows(), 3);
  VectorX y = x;
  assembly::to_frames(frames, y);
  const Real k = static_cast<Real>(k_max);
  EXPECT_LT((y - MatrixX(q).transpose() * x).norm(), 2.0 * k * epsilon * x.norm());
  assembly::from_frames(frames, y);
  EXPECT_LT((y - x).norm(), (4.0 * k + 8.0 * k * k) * epsilon * x.norm());
}

} // namespace
} // namespace formflow::testing
