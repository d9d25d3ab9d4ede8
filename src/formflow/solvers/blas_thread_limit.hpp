// SPDX-License-Identifier: MIT
// A cap on OpenBLAS's threads around work that its threads do not speed up.
#pragma once

namespace formflow::solvers {

/// While alive, OpenBLAS (if it is the process's BLAS) runs on at most `threads`
/// threads; 0 leaves it as it is. Nothing changes either when the user chose the count
/// (OPENBLAS_NUM_THREADS, GOTO_NUM_THREADS or OMP_NUM_THREADS in the environment, which
/// OpenBLAS reads at start): an explicit choice is kept.
///
/// Why: the supernodes of a 2D factor are small, and OpenBLAS's second thread costs
/// more than it computes there (docs/benchmarks.md "OpenBLAS's threads per factor").
/// Woken for every supernode, the idle thread then spins: the adaptive sticking ram
/// spent 10 s of system time that way and took 14.1 s wall against 13.0 s on one thread.
/// The count is OpenBLAS's global setting; the library calls BLAS from one thread.
class BlasThreadLimit {
public:
  explicit BlasThreadLimit(int threads);
  ~BlasThreadLimit();
  BlasThreadLimit(const BlasThreadLimit&) = delete;
  BlasThreadLimit& operator=(const BlasThreadLimit&) = delete;

private:
  int restore_ = 0; ///< the count to set back; 0: nothing was changed
};

} // namespace formflow::solvers
