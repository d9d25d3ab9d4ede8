// SPDX-License-Identifier: MIT
// Fuzz target: any bytes as a whole mesh file, through the header check and the data
// check of its sections (counts, tags, coordinates, repeated nodes; 2D and 3D, both
// versions, ASCII and binary) that stand before Gmsh's reader (never run here).
#include "formflow/mesh/msh_data.hpp"
#include "formflow/mesh/msh_header.hpp"
#include "fuzz/fuzz_support.hpp"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes = formflow::fuzz::as_text(data, size);
  std::string problem;
  const auto header = formflow::mesh::parse_msh_header(bytes, problem);
  if (!header) return 0;
  const auto refusal = formflow::mesh::msh_data_problem(bytes, *header, "m.msh");
  // A refusal names the file and where: "m.msh:LINE: " or "m.msh: byte N: ".
  if (refusal && refusal->rfind("m.msh:", 0) != 0) std::abort();
  // The check reads, never writes: the same bytes get the same answer.
  if (formflow::mesh::msh_data_problem(bytes, *header, "m.msh") != refusal) std::abort();
  return 0;
}
