// SPDX-License-Identifier: MIT
// fields.pvtu (a distributed run's fields, io/pvtu.hpp) read back by VTK's parallel
// reader: one grid with every cell once, the fields of the whole-mesh fields.vtu at
// each cell_id, the arrays the pieces have.
#include "formflow/io/pvtu.hpp"
#include "formflow/io/vtu.hpp"
#include "support/run_cli.hpp"
#include "support/synthetic_run.hpp"
#include "support/vtk_reader.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <set>
#include <string>

namespace formflow::testing {
namespace {

TEST(Pvtu, PiecesMakeTheWholeGridWithItsFields) {
  io::Case case_;
  mesh::Mesh<2> mesh;
  post::Results results;
  make_synthetic_run(2, 1.0, case_, mesh, results);
  ScratchDirectory scratch("formflow-pvtu");
  for (const int parts : {1, 3}) {
    const auto files = io::fields_pvtu(mesh, results.fields, solvers::StopReason::Converged, parts);
    ASSERT_EQ(static_cast<int>(files.size()), parts + 1);
    EXPECT_EQ(files.front().first, "fields.pvtu");
    for (const auto& [name, text] : files) std::ofstream(scratch / name, std::ios::binary) << text;
    const nlohmann::json whole = read_file_with_vtk(scratch / "fields.pvtu");
    ASSERT_TRUE(whole.contains("n_cells"));
    EXPECT_EQ(whole["n_cells"], mesh.n_cells());
    // Every cell once, by its id in the whole mesh, with its own cell means.
    const auto& ids = whole["cell_data"]["cell_id"]["values"];
    const auto& rates = whole["cell_data"]["equivalent_strain_rate"]["values"];
    std::set<long> seen;
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const auto cell = static_cast<Index>(ids[k].get<double>());
      EXPECT_TRUE(seen.insert(cell).second) << "cell " << cell << " twice";
      EXPECT_EQ(rates[k].get<double>(), results.fields.cell_equivalent_strain_rate[cell]);
    }
    EXPECT_EQ(static_cast<Index>(seen.size()), mesh.n_cells());
    // The pvtu declares exactly the arrays of a piece (the same names, point and cell).
    const nlohmann::json piece = read_file_with_vtk(scratch / io::piece_name(0));
    for (const char* kind : {"point_data", "cell_data"}) {
      std::set<std::string> in_whole, in_piece;
      for (const auto& [name, array] : whole[kind].items()) in_whole.insert(name);
      for (const auto& [name, array] : piece[kind].items()) in_piece.insert(name);
      EXPECT_EQ(in_whole, in_piece) << kind;
    }
    // A cut's nodes are in both pieces beside it: at least the whole mesh's nodes.
    EXPECT_GE(whole["n_points"].get<Index>(), mesh.n_nodes());
    if (parts == 1) {
      EXPECT_EQ(whole["n_points"].get<Index>(), mesh.n_nodes());
    }
  }
}

} // namespace
} // namespace formflow::testing
