// SPDX-License-Identifier: MIT
// (4) Friction on Γ3, threshold × enforcement (SPEC §3, eq. 5.3): the traction λ_T of
// each ContactPoint, κ u_T + s λ̂_T, written for the secant system as the weight κ on
// u_T and the load −s λ̂_T (exact friction only), both frozen at the current iterate:
//  * regularised: κ = τ_f/√(|u_T|² + d_T²), no load;
//  * exact (Alart–Curnier): λ_T = proj(λ̂ + r u_T) = s (λ̂ + r u_T), κ = s r.
// Newton adds the derivative at fixed τ_f (primal–dual, kernels/tangent_kernels.hpp)
// and, for a pressure-dependent threshold, dτ_f = (∂τ_f/∂σ̄_N) dσ̄_N through the
// coupling: it links each point to the normal velocities of its neighbours within the
// mollifier radius h, outside the cell pattern. (Lagging τ_f instead gave a linear
// tail: mesh II, μ = 0.2, 9 iterations to δ = 1e-4 instead of 8.)
#include "formflow/assembly/kernels/kernels.hpp"
#include "formflow/assembly/kernels/tangent_kernels.hpp"
#include "formflow/assembly/terms/terms.hpp"
#include "formflow/core/error.hpp"

namespace formflow::assembly {

namespace {

template <int dim> class FrictionTerm final : public FaceTerm<dim> {
public:
  FrictionTerm(const physics::Friction& friction, Real augmentation)
      : d_t_(friction.d_t), augmentation_(augmentation),
        exact_(friction.regularization == physics::FrictionRegularization::None) {}
  std::string_view name() const override { return "friction"; }

  void add_secant(const FaceState<dim>& face, MatrixX& matrix, VectorX& load) const override {
    if (face.points.empty()) return; // the constant-viscosity start: τ_f(0) = 0
    const int n_q = face.values.n_points();
    FF_ASSERT(n_q <= max_face_points, "a face rule larger than the friction term's buffers");
    std::array<Real, max_face_points> weight{};
    for (int q = 0; q < n_q; ++q) weight[q] = face.points[q].friction_weight;
    add_friction_term<dim>(face.values, std::span<const Real>(weight.data(), n_q), matrix);
    if (!exact_) return;
    // The lagged part moves to the right-hand side: F −= ∫_Γ3 s λ̂_T·v dΓ. On prescribed
    // dofs (the ram corner of the container wall) it is part of the reaction.
    for (int q = 0; q < n_q; ++q) add_traction(face, q, -face.points[q].friction_load, load);
  }

  void add_force(const FaceState<dim>& face, CellVector& force) const override {
    if (face.points.empty()) return;
    // The points were evaluated at this pass's velocity: their u_T is the face's.
    for (int q = 0; q < face.values.n_points(); ++q) {
      const ContactPoint<dim>& point = face.points[q];
      add_traction(face, q, point.friction_weight * point.tangential_velocity + point.friction_load,
                   force);
    }
  }

  void add_tangent(const FaceState<dim>& face, MatrixX& matrix) const override {
    const int n_q = face.values.n_points();
    FF_ASSERT(n_q <= max_face_points, "a face rule larger than the friction term's buffers");
    std::array<Point<dim>, max_face_points> slip, dual_slip;
    std::array<Real, max_face_points> coefficient{};
    const bool primal = face.slip_duals.empty();
    for (int q = 0; q < n_q; ++q) {
      const ContactPoint<dim>& point = face.points[q];
      if (exact_) {
        // Semismooth derivative of proj(t), t = λ̂ + r u_T, at fixed τ_f: r P at stick
        // (the secant term s r P already), s r (P − t̂ t̂ᵀ) at slip: add −s r t̂ t̂ᵀ.
        // Primal–dual as for the regularised law: with the dual λ ≈ t/|t| (the traction
        // over τ_f, |λ| ≤ 1) the slip part is −s r/|t| ½(λ t̂ᵀ + t̂ λᵀ): exact for λ = t̂,
        // PSD with the secant term s r P for any capped λ.
        const Real trial_norm = point.friction_traction.norm();
        const bool slipping = !point.sticking && point.friction_weight > 0 && trial_norm > 0;
        slip[q] = slipping ? Point<dim>(point.friction_traction) : Point<dim>::Zero();
        dual_slip[q] = primal || !slipping ? slip[q] : Point<dim>(trial_norm * face.slip_duals[q]);
        coefficient[q] = slipping ? point.friction_weight / (trial_norm * trial_norm) : 0.0;
      } else {
        const Real slip_speed = point.tangential_velocity.norm();
        const Real s2 = slip_speed * slip_speed + d_t_ * d_t_;
        slip[q] = point.tangential_velocity;
        dual_slip[q] = primal ? slip[q] : Point<dim>(std::sqrt(s2) * face.slip_duals[q]);
        coefficient[q] = point.friction_threshold / (s2 * std::sqrt(s2)); // τ_f/s³
      }
    }
    add_friction_tangent<dim>(face.values, std::span<const Point<dim>>(slip.data(), n_q),
                              std::span<const Point<dim>>(dual_slip.data(), n_q),
                              std::span<const Real>(coefficient.data(), n_q), matrix);
  }

  /// λ_T·u_T dΓ (regularised: τ_f |u_T|²/√(|u_T|² + d_T²)).
  void add_power(const FaceState<dim>& face, PowerTerms& power) const override {
    for (const ContactPoint<dim>& point : face.points)
      power.friction += point.friction_traction.dot(point.tangential_velocity) * point.weight;
  }

  void begin_newton(NewtonPass<dim>& pass) const override {
    std::vector<ContactPoint<dim>>& state = pass.contact;
    UnsymmetricTangent<dim>* coupling = pass.coupling;
    if (coupling) coupling->threshold_slip.assign(state.size(), Point<dim>::Zero());
    for (std::size_t k = 0; k < state.size(); ++k) {
      ContactPoint<dim>& point = state[k];
      const Real threshold = pass.thresholds[k];
      // dτ_f = (∂τ_f/∂σ̄_N) dσ̄_N where the point's own τ_f(u) > 0 (read before the frozen
      // threshold replaces it): μ_f for Coulomb, 0 for Tresca, whose k(ε̄̇) is lagged (its
      // slope σ_p′/√3 is α σ_p/ε̄̇ small for the rate-insensitive laws and zero below
      // rate1, where the container's rigid billet slides).
      const bool own_threshold_positive = point.friction_threshold > 0;
      const Real slope = point.threshold_pressure_slope;
      if (exact_) {
        if (!own_threshold_positive && threshold <= 0) continue; // friction off here
        point.friction_threshold = threshold;
        const bool given = !pass.friction_multipliers.empty();
        exact_friction_point(given ? pass.friction_multipliers[k] : Point<dim>::Zero(),
                             augmentation_, point);
        // The projection's τ_f derivative keeps dτ_f's direction t̂ = t/|t| at slip
        // points, zero at stick points and where σ̄_N(u) ≤ 0.
        const bool slipping = threshold > 0 && !point.sticking;
        if (!coupling || !slipping || !own_threshold_positive || slope == 0) continue;
        coupling->threshold_slip[k] = slope * point.friction_traction.normalized();
        coupling->has_friction = true;
        continue;
      }
      if (coupling && own_threshold_positive && slope != 0) {
        const Real s = std::sqrt(point.tangential_velocity.squaredNorm() + d_t_ * d_t_);
        coupling->threshold_slip[k] = slope / s * point.tangential_velocity;
        coupling->has_friction = true;
      }
      point.friction_threshold = threshold;
      point.friction_weight =
          physics::friction_weight(threshold, point.tangential_velocity.norm(), d_t_);
    }
  }

  bool has_loads() const override { return exact_; }

private:
  /// Q2 faces in 3D have 3×3 Gauss points (nodal rule: 9 face nodes); a P2+ tetrahedron's
  /// face rule of degree 6 has 4×4 (fem/reference_element.cpp face_rule).
  static constexpr int max_face_points = 16;

  /// Adds ∫ t·φ_a e_i dΓ at face point q to a node-major local vector.
  template <class Vector>
  static void add_traction(const FaceState<dim>& face, int q, const Point<dim>& traction,
                           Vector& local) {
    if (traction.isZero(0.0)) return;
    const auto& phi = face.values.shape(q);
    for (int a = 0; a < static_cast<int>(phi.size()); ++a)
      local.template segment<dim>(a * dim) += (phi[a] * face.values.JxW(q)) * traction;
  }

  Real d_t_, augmentation_;
  bool exact_;
};

} // namespace

template <int dim>
std::unique_ptr<FaceTerm<dim>> make_friction_term(const physics::Friction& friction,
                                                  Real augmentation) {
  return std::make_unique<FrictionTerm<dim>>(friction, augmentation);
}

template std::unique_ptr<FaceTerm<2>> make_friction_term<2>(const physics::Friction&, Real);
template std::unique_ptr<FaceTerm<3>> make_friction_term<3>(const physics::Friction&, Real);

} // namespace formflow::assembly
