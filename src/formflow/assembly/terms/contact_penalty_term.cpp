// SPDX-License-Identifier: MIT
// (3) The normal contact penalty ∫_Γ3 (1/d_N) u_N v_N dΓ (eq. 3.8): σ_N = −u_N/d_N.
#include "formflow/assembly/kernels/kernels.hpp"
#include "formflow/assembly/kernels/residual_kernels.hpp"
#include "formflow/assembly/terms/terms.hpp"

namespace formflow::assembly {

namespace {

template <int dim> class ContactPenaltyTerm final : public FaceTerm<dim> {
public:
  explicit ContactPenaltyTerm(Real d_n) : d_n_(d_n) {}
  std::string_view name() const override { return "contact penalty"; }

  void add_secant(const FaceState<dim>& face, MatrixX& matrix, VectorX&) const override {
    add_contact_penalty<dim>(face.values, d_n_, matrix);
  }
  void add_force(const FaceState<dim>& face, CellVector& force) const override {
    add_contact_force<dim>(face.values, d_n_, face.velocities, force);
  }
  /// −σ_N u_N dΓ at the face's points: u_N²/d_N.
  void add_power(const FaceState<dim>& face, PowerTerms& power) const override {
    for (const ContactPoint<dim>& point : face.points)
      power.contact_penalty += point.contact_pressure * point.normal_velocity * point.weight;
  }

private:
  Real d_n_;
};

} // namespace

template <int dim> std::unique_ptr<FaceTerm<dim>> make_contact_penalty_term(Real d_n) {
  return std::make_unique<ContactPenaltyTerm<dim>>(d_n);
}

template std::unique_ptr<FaceTerm<2>> make_contact_penalty_term<2>(Real);
template std::unique_ptr<FaceTerm<3>> make_contact_penalty_term<3>(Real);

} // namespace formflow::assembly
