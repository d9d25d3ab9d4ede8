// SPDX-License-Identifier: MIT
// Fuzz target: any bytes as the start of a mesh file, through the MSH header check
// that decides whether Gmsh may read it (the bytes never reach Gmsh here).
#include "formflow/mesh/msh_header.hpp"
#include "fuzz/fuzz_support.hpp"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes = formflow::fuzz::as_text(data, size);
  std::string problem;
  const auto header = formflow::mesh::parse_msh_header(bytes, problem);
  // Exactly one of a header and a reason; an accepted file starts as Gmsh writes it.
  if (header.has_value() == !problem.empty()) std::abort();
  if (header && bytes.rfind("$MeshFormat\n", 0) != 0 && bytes.rfind("$MeshFormat\r\n", 0) != 0)
    std::abort();
  return 0;
}
