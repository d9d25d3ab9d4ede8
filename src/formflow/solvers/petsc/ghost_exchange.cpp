// SPDX-License-Identifier: MIT
#include "formflow/solvers/petsc/ghost_exchange.hpp"

#include "formflow/core/error.hpp"
#include "formflow/solvers/petsc/petsc_session.hpp"

#include <petscvec.h>

#include <algorithm>
#include <vector>

namespace formflow::solvers::petsc {

namespace {

class PetscGhostExchange final : public assembly::GhostExchange {
public:
  PetscGhostExchange(Index n_owned, std::span<const Index> ghost_globals)
      : n_held_(n_owned + static_cast<Index>(ghost_globals.size())) {
    const std::vector<PetscInt> ghosts(ghost_globals.begin(), ghost_globals.end());
    const PetscErrorCode error =
        VecCreateGhost(PETSC_COMM_WORLD, static_cast<PetscInt>(n_owned), PETSC_DETERMINE,
                       static_cast<PetscInt>(ghosts.size()), ghosts.data(), &vector_);
    FF_ASSERT(error == 0, "PETSc makes a ghosted vector of a consistent numbering");
  }
  ~PetscGhostExchange() override {
    if (vector_) VecDestroy(&vector_);
  }
  PetscGhostExchange(const PetscGhostExchange&) = delete;
  PetscGhostExchange& operator=(const PetscGhostExchange&) = delete;

  void sum_shares(std::span<Real> held) override {
    FF_ASSERT(static_cast<Index>(held.size()) == n_held_, "the owned entries, then the ghosts");
    copy_local(held, /*into_vector=*/true);
    VecGhostUpdateBegin(vector_, ADD_VALUES, SCATTER_REVERSE);
    VecGhostUpdateEnd(vector_, ADD_VALUES, SCATTER_REVERSE);
    VecGhostUpdateBegin(vector_, INSERT_VALUES, SCATTER_FORWARD);
    VecGhostUpdateEnd(vector_, INSERT_VALUES, SCATTER_FORWARD);
    copy_local(held, /*into_vector=*/false);
  }

private:
  /// The local form is the owned entries followed by the ghosts: `held`'s order.
  void copy_local(std::span<Real> held, bool into_vector) {
    Vec local = nullptr;
    VecGhostGetLocalForm(vector_, &local);
    PetscScalar* values = nullptr;
    VecGetArray(local, &values);
    if (into_vector)
      std::copy(held.begin(), held.end(), values);
    else
      std::copy(values, values + held.size(), held.begin());
    VecRestoreArray(local, &values);
    VecGhostRestoreLocalForm(vector_, &local);
  }

  Index n_held_;
  Vec vector_ = nullptr;
};

} // namespace

std::unique_ptr<assembly::GhostExchange> make_ghost_exchange(Index n_owned,
                                                             std::span<const Index> ghost_globals) {
  ensure_initialized();
  return std::make_unique<PetscGhostExchange>(n_owned, ghost_globals);
}

} // namespace formflow::solvers::petsc
