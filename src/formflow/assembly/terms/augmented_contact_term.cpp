// SPDX-License-Identifier: MIT
// Exact contact (d_N = 0): at each Γ3 point the term r_N u_N v_N and the load −λ_k v_N;
// the Uzawa step λ_k ← λ_k + r_N u_N(x_k) (ConstraintMultipliers::update), −σ_N = λ.
#include "formflow/assembly/terms/terms.hpp"
#include "formflow/core/error.hpp"

namespace formflow::assembly {

namespace {

template <int dim> class AugmentedContactTerm final : public FaceTerm<dim> {
public:
  explicit AugmentedContactTerm(ConstraintMultipliers<dim>& multipliers)
      : multipliers_(multipliers) {}
  std::string_view name() const override { return "augmented contact"; }

  void add_secant(const FaceState<dim>& face, MatrixX& matrix, VectorX& load) const override {
    const fem::FacetValues<dim>& values = face.values;
    const int n = static_cast<int>(values.shape(0).size());
    const Real r = multipliers_.formulation().contact_augmentation;
    CellVector normal_row(n * dim);
    for (int q = 0; q < values.n_points(); ++q) {
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < dim; ++i)
          normal_row[a * dim + i] = values.shape(q)[a] * values.normal(q)[i];
      const Index k = face.first_point() + q;
      multipliers_.record_contact_weight(k, values.JxW(q));
      matrix.noalias() += (r * values.JxW(q)) * normal_row * normal_row.transpose(); // r_N u_N v_N
      load.noalias() -= (multipliers_.contact_multiplier(k) * values.JxW(q)) * normal_row; // −λ v_N
    }
  }
  void add_force(const FaceState<dim>&, CellVector&) const override {
    FF_ASSERT(false, "Newton does not linearise the Uzawa multipliers (solvers/capabilities)");
  }
  /// −σ_N u_N dΓ = (λ + r_N u_N) u_N dΓ, → 0 as the constraint is met.
  void add_power(const FaceState<dim>& face, PowerTerms& power) const override {
    for (const ContactPoint<dim>& point : face.points)
      power.contact_penalty += point.contact_pressure * point.normal_velocity * point.weight;
  }
  bool has_loads() const override { return true; }
  bool newton_ready() const override { return false; }

private:
  ConstraintMultipliers<dim>& multipliers_;
};

} // namespace

template <int dim>
std::unique_ptr<FaceTerm<dim>> make_augmented_contact_term(ConstraintMultipliers<dim>& contact) {
  return std::make_unique<AugmentedContactTerm<dim>>(contact);
}

template std::unique_ptr<FaceTerm<2>> make_augmented_contact_term<2>(ConstraintMultipliers<2>&);
template std::unique_ptr<FaceTerm<3>> make_augmented_contact_term<3>(ConstraintMultipliers<3>&);

} // namespace formflow::assembly
