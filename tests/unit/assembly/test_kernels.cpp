// SPDX-License-Identifier: MIT
// Element kernels on single distorted Q1/Q2 cells: symmetry, definiteness, rigid
// modes, energies of linear fields, rank of reduced integration, face terms.
#include "formflow/assembly/kernels/kernels.hpp"

#include "formflow/fem/lagrange.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>
#include <ostream>
#include <vector>

namespace formflow::testing {
namespace {

using physics::ViscousStrain;
using Nodes2 = fem::CellValues<2>::Gradients;
using Nodes3 = fem::CellValues<3>::Gradients;

/// Non-affine quadrilateral, lexicographic corners (counter-clockwise 0, 1, 3, 2).
Nodes2 distorted_q1() {
  Nodes2 nodes(2, 4);
  nodes << 0.0, 2.0, 0.3, 2.4, //
      0.0, 0.2, 1.5, 1.9;
  return nodes;
}

double distorted_area() {
  const Nodes2 p = distorted_q1();
  const std::array<int, 4> ccw = {0, 1, 3, 2};
  double twice = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Point<2> a = p.col(ccw[k]), b = p.col(ccw[(k + 1) % 4]);
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

/// Q2 with the same (straight-edged) outline and a displaced centre node:
/// non-bilinear map, same area, same straight faces.
Nodes2 distorted_q2() {
  const Nodes2 q1 = distorted_q1();
  Nodes2 nodes(2, 9);
  for (int a = 0; a < 9; ++a) {
    const Point<2> xi = fem::reference_node<2>(2, a);
    const double s = 0.5 * (1 + xi.x()), t = 0.5 * (1 + xi.y());
    nodes.col(a) = (1 - s) * (1 - t) * q1.col(0) + s * (1 - t) * q1.col(1) +
                   (1 - s) * t * q1.col(2) + s * t * q1.col(3);
  }
  nodes.col(4) += Point<2>(0.12, -0.07);
  return nodes;
}

Nodes2 distorted(int order) {
  return order == 1 ? distorted_q1() : distorted_q2();
}

/// Nodal vector (node-major, component fastest) of u(x) = G x + c.
template <int dim>
VectorX nodal_field(const typename fem::CellValues<dim>::Gradients& nodes, const Tensor2<dim>& g,
                    const Point<dim>& c = Point<dim>::Zero()) {
  VectorX u(nodes.cols() * dim);
  for (int a = 0; a < nodes.cols(); ++a) u.segment<dim>(a * dim) = g * nodes.col(a) + c;
  return u;
}

/// Symmetric eigenvalues, ascending.
VectorX eigenvalues(const MatrixX& matrix) {
  return Eigen::SelfAdjointEigenSolver<MatrixX>(matrix, Eigen::EigenvaluesOnly).eigenvalues();
}

/// Number of eigenvalues below `relative`·λ_max.
int n_small_eigenvalues(const MatrixX& matrix, double relative) {
  const VectorX lambda = eigenvalues(matrix);
  int count = 0;
  for (Index k = 0; k < lambda.size(); ++k)
    count += std::abs(lambda[k]) < relative * lambda.maxCoeff();
  return count;
}

/// Per-point viscosities that vary, so that no test relies on a constant ν.
std::vector<Real> varying_viscosity(int n) {
  std::vector<Real> viscosity;
  for (int q = 0; q < n; ++q) viscosity.push_back(1.0 + 0.37 * q);
  return viscosity;
}

MatrixX viscous_matrix(const fem::CellValues<2>& values, const std::vector<Real>& viscosity,
                       ViscousStrain strain) {
  MatrixX local = MatrixX::Zero(values.n_nodes() * 2, values.n_nodes() * 2);
  assembly::add_viscous_term<2>(values, viscosity, strain, local);
  return local;
}

// A local matrix of ≤ 18 rows built from ≤ 9 points of O(1) terms: entries
// carry ~1e-15 relative error. "Zero" below means ≤ 1e-12 relative to the
// natural scale ‖K‖·‖u‖ — round-off, four orders below any true signal.
constexpr double kernel_roundoff = 1e-12;

struct KernelCase {
  int order;
  ViscousStrain strain;
};

void PrintTo(const KernelCase& c, std::ostream* os) {
  *os << "Q" << c.order << (c.strain == ViscousStrain::Full ? " full" : " deviatoric");
}

class ViscousKernel : public ::testing::TestWithParam<KernelCase> {
protected:
  int order() const { return GetParam().order; }
  ViscousStrain strain() const { return GetParam().strain; }
  fem::CellValues<2> values() const {
    fem::CellValues<2> v(order(), fem::gauss_rule<2>(order() + 1));
    EXPECT_TRUE(v.reinit(distorted(order())));
    return v;
  }
};

TEST_P(ViscousKernel, IsSymmetricAndPositiveSemiDefinite) {
  const fem::CellValues<2> v = values();
  const MatrixX k = viscous_matrix(v, varying_viscosity(v.n_points()), strain());
  EXPECT_TRUE(approx((k - k.transpose()).norm(), 0.0, 0.0, kernel_roundoff * k.norm()));
  EXPECT_GE(eigenvalues(k).minCoeff(), -kernel_roundoff * k.norm());
}

TEST_P(ViscousKernel, RigidBodyModesAreExactlyTheNullSpace) {
  const fem::CellValues<2> v = values();
  const MatrixX k = viscous_matrix(v, varying_viscosity(v.n_points()), strain());
  Tensor2<2> rotation;
  rotation << 0, -1, 1, 0; // u = (−y, x)
  const std::array<VectorX, 3> modes = {
      nodal_field<2>(distorted(order()), Tensor2<2>::Zero(), Point<2>(1.0, 0.0)),
      nodal_field<2>(distorted(order()), Tensor2<2>::Zero(), Point<2>(0.0, 1.0)),
      nodal_field<2>(distorted(order()), rotation)};
  for (const VectorX& mode : modes)
    EXPECT_TRUE(approx((k * mode).norm(), 0.0, 0.0, kernel_roundoff * k.norm() * mode.norm()));
  // Full integration (2×2 for Q1, 3×3 for Q2) leaves no spurious zero-energy
  // modes: exactly three, in plane strain for ė as well as ε̇ (ė = 0 with
  // ε̇_zz = 0 forces ε̇ = 0). 1e-10 of λ_max separates them from the rest.
  EXPECT_EQ(n_small_eigenvalues(k, 1e-10), 3);
}

TEST_P(ViscousKernel, EnergyOfALinearFieldByHand) {
  // u = G x, G = [[0.3, 0.7], [−0.2, 0.5]]: ε̇ = [[0.3, 0.25], [0.25, 0.5]],
  // ε̇:ε̇ = 0.09 + 2·0.0625 + 0.25 = 0.465; ε̇_V = 0.8 and, with ε̇_zz = 0,
  // ė:ė = ε̇:ε̇ − ε̇_V²/3 = 0.465 − 0.64/3. Energy uᵀKu = ⅔ ν (·) |Ω|.
  const double nu = 2.5;
  Tensor2<2> g;
  g << 0.3, 0.7, -0.2, 0.5;
  const double contraction = strain() == ViscousStrain::Full ? 0.465 : 0.465 - 0.64 / 3.0;
  const fem::CellValues<2> v = values();
  const MatrixX k = viscous_matrix(v, std::vector<Real>(v.n_points(), nu), strain());
  const VectorX u = nodal_field<2>(distorted(order()), g, Point<2>(0.4, -0.9));
  // The gradient of the interpolated linear field is exact, and the full rule
  // integrates det J exactly: round-off only.
  EXPECT_TRUE(
      approx(u.dot(k * u), 2.0 / 3.0 * nu * contraction * distorted_area(), kernel_roundoff));
}

TEST_P(ViscousKernel, MatchesTheVoigtBMatrixForm) {
  // Independent construction: ε̇ in Voigt form (ε̇_xx, ε̇_yy, 2ε̇_xy) = B u and
  // ε̇:ε̇ = ε̇_xx² + ε̇_yy² + ½(2ε̇_xy)², so K = Σ_q ⅔ν_q Bᵀ D B JxW with
  // D = diag(1, 1, ½), minus ⅓ m mᵀ (m = (1, 1, 0)) for the deviator.
  const fem::CellValues<2> v = values();
  const std::vector<Real> viscosity = varying_viscosity(v.n_points());
  const MatrixX k = viscous_matrix(v, viscosity, strain());
  const int n = v.n_nodes();
  Eigen::Matrix3d d = Eigen::Vector3d(1.0, 1.0, 0.5).asDiagonal();
  if (strain() == ViscousStrain::Deviatoric)
    d -= Eigen::Vector3d(1, 1, 0) * Eigen::Vector3d(1, 1, 0).transpose() / 3.0;
  MatrixX reference = MatrixX::Zero(2 * n, 2 * n);
  for (int q = 0; q < v.n_points(); ++q) {
    MatrixX b = MatrixX::Zero(3, 2 * n);
    for (int a = 0; a < n; ++a) {
      const double dx = v.gradients(q)(0, a), dy = v.gradients(q)(1, a);
      b(0, 2 * a) = dx;
      b(1, 2 * a + 1) = dy;
      b(2, 2 * a) = dy;
      b(2, 2 * a + 1) = dx;
    }
    reference += 2.0 / 3.0 * viscosity[q] * v.JxW(q) * b.transpose() * d * b;
  }
  EXPECT_TRUE(approx((k - reference).norm(), 0.0, 0.0, kernel_roundoff * reference.norm()));
}

INSTANTIATE_TEST_SUITE_P(
    Kernels, ViscousKernel,
    ::testing::Values(KernelCase{1, ViscousStrain::Full}, KernelCase{1, ViscousStrain::Deviatoric},
                      KernelCase{2, ViscousStrain::Full}, KernelCase{2, ViscousStrain::Deviatoric}),
    [](const auto& info) {
      return std::string(info.param.order == 1 ? "Q1" : "Q2") +
             (info.param.strain == ViscousStrain::Full ? "Full" : "Deviatoric");
    });

TEST(ViscousKernel3D, SixRigidModesOnADistortedHexahedron) {
  // Unit square base, top z = 1 + 0.5x + 0.3xy.
  Nodes3 nodes(3, 8);
  nodes << 0, 1, 0, 1, 0, 1, 0, 1, //
      0, 0, 1, 1, 0, 0, 1, 1,      //
      0, 0, 0, 0, 1, 1.5, 1, 1.8;
  fem::CellValues<3> v(1, fem::gauss_rule<3>(2));
  ASSERT_TRUE(v.reinit(nodes));
  MatrixX k = MatrixX::Zero(24, 24);
  assembly::add_viscous_term<3>(v, std::vector<Real>(v.n_points(), 1.0), ViscousStrain::Full, k);
  EXPECT_EQ(n_small_eigenvalues(k, 1e-10), 6); // 3 translations + 3 rotations
  Tensor2<3> spin;
  spin << 0, -0.3, 0.5, 0.3, 0, -0.2, -0.5, 0.2, 0;
  const VectorX u = nodal_field<3>(nodes, spin, Point<3>(0.1, 0.2, 0.3));
  EXPECT_TRUE(approx((k * u).norm(), 0.0, 0.0, kernel_roundoff * k.norm() * u.norm()));
  // Energy of u = diag(1, −½, −½) x: ε̇:ε̇ = 1.5, volume 1.325 (hand).
  Tensor2<3> stretch = Tensor2<3>::Zero();
  stretch.diagonal() << 1, -0.5, -0.5;
  const VectorX w = nodal_field<3>(nodes, stretch);
  EXPECT_TRUE(approx(w.dot(k * w), 2.0 / 3.0 * 1.5 * 1.325, kernel_roundoff));
}

// ---- volumetric penalty -------------------------------------------------------

MatrixX volumetric_matrix(int order, int n_points, double d) {
  fem::CellValues<2> v(order, fem::gauss_rule<2>(n_points));
  EXPECT_TRUE(v.reinit(distorted(order)));
  MatrixX local = MatrixX::Zero(v.n_nodes() * 2, v.n_nodes() * 2);
  assembly::add_volumetric_penalty<2>(v, d, local);
  return local;
}

TEST(VolumetricPenalty, DivergenceFreeLinearFieldHasNoPenalty) {
  Tensor2<2> g;
  g << 0.4, 0.7, -0.3, -0.4; // tr G = 0
  for (int order : {1, 2})
    for (int n = 1; n <= order + 1; ++n) {
      const MatrixX k = volumetric_matrix(order, n, 1e-3);
      const VectorX u = nodal_field<2>(distorted(order), g, Point<2>(1.0, 2.0));
      EXPECT_TRUE(approx((k * u).norm(), 0.0, 0.0, kernel_roundoff * k.norm() * u.norm()))
          << order << "/" << n;
    }
}

TEST(VolumetricPenalty, UniformDilatationGivesDivergenceSquaredOverD) {
  // u = x: ε̇_V = 2, energy (1/d)·4·|Ω| when the rule integrates det J exactly
  // (any rule for Q1, whose det J is affine per variable; ≥ 2×2 for this Q2).
  const double d = 1e-3;
  const std::vector<std::array<int, 2>> cases = {{1, 1}, {1, 2}, {2, 2}, {2, 3}};
  for (const auto& [order, n] : cases) {
    const MatrixX k = volumetric_matrix(order, n, d);
    const VectorX u = nodal_field<2>(distorted(order), Tensor2<2>::Identity());
    EXPECT_TRUE(approx(u.dot(k * u), 4.0 / d * distorted_area(), kernel_roundoff))
        << order << "/" << n;
    EXPECT_GE(eigenvalues(k).minCoeff(), -kernel_roundoff * k.norm());
  }
}

TEST(VolumetricPenalty, ReducedOnePointRuleOnQ1HasRankOne) {
  // One point: K = (w det J / d) g gᵀ with g the divergence row — rank 1
  // ({Q1, P0} behaviour, SPEC Remark 5.1).
  EXPECT_EQ(8 - n_small_eigenvalues(volumetric_matrix(1, 1, 1e-3), 1e-10), 1);
  // 2×2 on Q2: one constraint per point, four points.
  EXPECT_EQ(18 - n_small_eigenvalues(volumetric_matrix(2, 2, 1e-3), 1e-10), 4);
}

// ---- face terms -----------------------------------------------------------------

struct Face {
  int local_face;
  Point<2> normal; // outward unit normal of the straight face (hand)
  double length;
};

/// The four faces of the distorted outline, from its corners (counter-clockwise 0→1→3→2).
std::array<Face, 4> faces() {
  const Nodes2 c = distorted_q1();
  auto face = [&](int local_face, int from, int to) {
    const Point<2> e = c.col(to) - c.col(from);
    return Face{local_face, Point<2>(e.y(), -e.x()) / e.norm(), e.norm()};
  };
  return {face(2, 0, 1), face(1, 1, 3), face(3, 3, 2), face(0, 2, 0)};
}

TEST(ContactPenalty, NormalVelocityIsPenalisedWithOneOverDn) {
  const double d_n = 1e-6;
  for (int order : {1, 2}) {
    fem::FacetValues<2> values(order, fem::gauss_rule<1>(order + 1));
    for (const Face& face : faces()) {
      values.reinit(distorted(order), face.local_face);
      MatrixX k = MatrixX::Zero(2 * (order + 1) * (order + 1), 2 * (order + 1) * (order + 1));
      assembly::add_contact_penalty<2>(values, d_n, k);
      const Point<2> tangent(-face.normal.y(), face.normal.x());
      const VectorX normal_field =
          nodal_field<2>(distorted(order), Tensor2<2>::Zero(), face.normal);
      const VectorX tangent_field = nodal_field<2>(distorted(order), Tensor2<2>::Zero(), tangent);
      // u = n: u_N = 1 along the face → (1/d_N)·L; u = t: u_N = 0.
      EXPECT_TRUE(approx(normal_field.dot(k * normal_field), face.length / d_n, kernel_roundoff))
          << face.local_face;
      EXPECT_TRUE(approx(tangent_field.dot(k * tangent_field), 0.0, 0.0,
                         kernel_roundoff * face.length / d_n));
      EXPECT_TRUE(approx((k - k.transpose()).norm(), 0.0, 0.0, kernel_roundoff * k.norm()));
    }
  }
}

TEST(ContactPenalty, OnlyTheFaceNodesAreCoupled) {
  // Q2 face 3 (top) holds nodes 6, 7, 8: every other row must stay zero.
  fem::FacetValues<2> values(2, fem::gauss_rule<1>(3));
  values.reinit(distorted_q2(), 3);
  MatrixX k = MatrixX::Zero(18, 18);
  assembly::add_contact_penalty<2>(values, 1.0, k);
  for (int a = 0; a < 6; ++a)
    EXPECT_TRUE(approx(k.middleRows(2 * a, 2).norm(), 0.0, 0.0, 1e-15)) << a;
  EXPECT_GT(k.bottomRows(6).norm(), 0.1);
}

TEST(FrictionTerm, TangentialSlipIsWeightedAndNormalMotionIsFree) {
  const double kappa = 3.5;
  for (int order : {1, 2}) {
    fem::FacetValues<2> values(order, fem::gauss_rule<1>(order + 1));
    for (const Face& face : faces()) {
      values.reinit(distorted(order), face.local_face);
      const int n_local = 2 * (order + 1) * (order + 1);
      MatrixX k = MatrixX::Zero(n_local, n_local);
      assembly::add_friction_term<2>(values, std::vector<Real>(values.n_points(), kappa), k);
      const Point<2> tangent(-face.normal.y(), face.normal.x());
      const VectorX normal_field =
          nodal_field<2>(distorted(order), Tensor2<2>::Zero(), face.normal);
      // u = 0.6 n + 2 t: only the tangential part counts, |u_T|² = 4.
      const VectorX mixed_field = nodal_field<2>(distorted(order), Tensor2<2>::Zero(),
                                                 Point<2>(0.6 * face.normal + 2.0 * tangent));
      EXPECT_TRUE(approx(normal_field.dot(k * normal_field), 0.0, 0.0,
                         kernel_roundoff * kappa * face.length));
      EXPECT_TRUE(
          approx(mixed_field.dot(k * mixed_field), 4.0 * kappa * face.length, kernel_roundoff))
          << face.local_face;
      EXPECT_GE(eigenvalues(k).minCoeff(), -kernel_roundoff * k.norm());
    }
  }
}

TEST(FrictionTerm, PointWeightsFollowTheirQuadraturePoints) {
  // κ(x) = 1 + 2 s, s the distance from corner 0 along the bottom face:
  // ∫ κ dΓ = L + L² for u = t with |t| = 1 (the 2-point rule is exact for it).
  fem::FacetValues<2> values(1, fem::gauss_rule<1>(2));
  values.reinit(distorted_q1(), 2);
  const Face bottom = faces()[0];
  std::vector<Real> weight;
  for (int q = 0; q < values.n_points(); ++q)
    weight.push_back(1.0 + 2.0 * (values.point(q) - distorted_q1().col(0)).norm());
  MatrixX k = MatrixX::Zero(8, 8);
  assembly::add_friction_term<2>(values, weight, k);
  const Point<2> tangent(-bottom.normal.y(), bottom.normal.x());
  const VectorX u = nodal_field<2>(distorted_q1(), Tensor2<2>::Zero(), tangent);
  EXPECT_TRUE(approx(u.dot(k * u), bottom.length + bottom.length * bottom.length, kernel_roundoff));
  // Zero weights everywhere add nothing.
  MatrixX unchanged = MatrixX::Zero(8, 8);
  assembly::add_friction_term<2>(values, std::vector<Real>(2, 0.0), unchanged);
  EXPECT_EQ(unchanged.norm(), 0.0);
}

TEST(Kernels, AddToTheExistingLocalMatrix) {
  // FormingProblem sums all terms into one local matrix: each kernel must add, not assign.
  fem::CellValues<2> v(1, fem::gauss_rule<2>(2));
  ASSERT_TRUE(v.reinit(distorted_q1()));
  fem::FacetValues<2> f(1, fem::gauss_rule<1>(2));
  f.reinit(distorted_q1(), 1);
  const MatrixX start = MatrixX::Identity(8, 8) * 7.0;

  MatrixX alone = MatrixX::Zero(8, 8), summed = start;
  const std::vector<Real> nu(4, 1.3), kappa(2, 0.9);
  assembly::add_viscous_term<2>(v, nu, ViscousStrain::Full, alone);
  assembly::add_volumetric_penalty<2>(v, 0.5, alone);
  assembly::add_contact_penalty<2>(f, 0.25, alone);
  assembly::add_friction_term<2>(f, kappa, alone);
  assembly::add_viscous_term<2>(v, nu, ViscousStrain::Full, summed);
  assembly::add_volumetric_penalty<2>(v, 0.5, summed);
  assembly::add_contact_penalty<2>(f, 0.25, summed);
  assembly::add_friction_term<2>(f, kappa, summed);
  EXPECT_TRUE(approx((summed - start - alone).norm(), 0.0, 0.0, kernel_roundoff * alone.norm()));
}

} // namespace
} // namespace formflow::testing
