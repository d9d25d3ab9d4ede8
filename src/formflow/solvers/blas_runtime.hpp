// SPDX-License-Identifier: MIT
// Which BLAS the process runs, as far as the library says.
#pragma once

#include <optional>
#include <string>

namespace formflow::solvers {

/// The BLAS behind CHOLMOD's supernodes and the dense kernels, read at run time: the
/// same binary may be served by OpenBLAS (Debian's default), reference BLAS or another
/// alternative, and OpenBLAS picks its kernels by the CPU it finds. OpenBLAS 0.3.21
/// (Debian 12) does not recognise newer Xeons (avx512_fp16) and falls back to its
/// generic "Prescott" kernels: factorisations then run slower than the CPU allows
/// (OPENBLAS_CORETYPE=SkylakeX or Haswell in the environment chooses the kernels;
/// docs/benchmarks.md "The BLAS kernels").
struct BlasRuntime {
  std::string library; ///< OpenBLAS's configuration string, or "not OpenBLAS"
  std::string core;    ///< OpenBLAS's kernel family ("Haswell", "Prescott"); empty if unknown
  std::optional<int> threads; ///< OpenBLAS's thread count
};

/// Asks the loaded BLAS (by symbol lookup: nothing is linked for it).
BlasRuntime blas_runtime();

} // namespace formflow::solvers
