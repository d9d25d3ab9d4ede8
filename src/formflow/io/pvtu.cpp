// SPDX-License-Identifier: MIT
#include "formflow/io/pvtu.hpp"

#include "formflow/core/error.hpp"
#include "formflow/io/vtu.hpp"
#include "formflow/mesh/cell_partition.hpp"

#include <fmt/format.h>

#include <iterator>

namespace formflow::io {

namespace {

/// `values` (per node, `width` entries each) at the nodes `nodes`.
VectorX at_nodes(const VectorX& values, const std::vector<Index>& nodes, int width) {
  if (values.size() == 0) return values;
  VectorX result(static_cast<Index>(nodes.size()) * width);
  for (std::size_t k = 0; k < nodes.size(); ++k)
    result.segment(static_cast<Index>(k) * width, width) = values.segment(nodes[k] * width, width);
  return result;
}

VectorX at_cells(const VectorX& values, const std::vector<Index>& cells) {
  if (values.size() == 0) return values;
  VectorX result(static_cast<Index>(cells.size()));
  for (std::size_t k = 0; k < cells.size(); ++k) result[static_cast<Index>(k)] = values[cells[k]];
  return result;
}

} // namespace

std::string piece_name(int part) {
  return fmt::format("fields_{}.vtu", part);
}

template <int dim>
std::vector<std::pair<std::string, std::string>>
fields_pvtu(const mesh::Mesh<dim>& mesh, const post::Fields& fields,
            solvers::StopReason stop_reason, int parts, std::span<const int> cell_ranks) {
  const std::vector<int> part = cell_ranks.size() == static_cast<std::size_t>(mesh.n_cells())
                                    ? std::vector<int>(cell_ranks.begin(), cell_ranks.end())
                                    : mesh::slab_partition(mesh, parts);
  std::vector<std::pair<std::string, std::string>> files(1);
  for (int r = 0; r < parts; ++r) {
    std::vector<Index> cells;
    for (Index cell = 0; cell < mesh.n_cells(); ++cell)
      if (part[cell] == r) cells.push_back(cell);
    // The piece's nodes: those of its cells, in the whole mesh's order.
    std::vector<Index> local(static_cast<std::size_t>(mesh.n_nodes()), -1), nodes;
    for (const Index cell : cells)
      for (Index a = 0; a < mesh.cells.rows(); ++a) local[mesh.cells(a, cell)] = 0;
    for (Index node = 0; node < mesh.n_nodes(); ++node)
      if (local[node] == 0) {
        local[node] = static_cast<Index>(nodes.size());
        nodes.push_back(node);
      }
    mesh::Mesh<dim> piece;
    piece.order = mesh.order;
    piece.shape = mesh.shape;
    piece.bubbles = mesh.bubbles;
    piece.nodes.resize(dim, static_cast<Index>(nodes.size()));
    for (std::size_t k = 0; k < nodes.size(); ++k)
      piece.nodes.col(static_cast<Index>(k)) = mesh.nodes.col(nodes[k]);
    piece.cells.resize(mesh.cells.rows(), static_cast<Index>(cells.size()));
    for (std::size_t k = 0; k < cells.size(); ++k)
      for (Index a = 0; a < mesh.cells.rows(); ++a)
        piece.cells(a, static_cast<Index>(k)) = local[mesh.cells(a, cells[k])];
    post::Fields restricted;
    restricted.velocity = at_nodes(fields.velocity, nodes, dim);
    restricted.equivalent_strain_rate = at_nodes(fields.equivalent_strain_rate, nodes, 1);
    restricted.hydrostatic_stress = at_nodes(fields.hydrostatic_stress, nodes, 1);
    restricted.contact_pressure = at_nodes(fields.contact_pressure, nodes, 1);
    restricted.friction_stress = at_nodes(fields.friction_stress, nodes, 1);
    restricted.temperature = at_nodes(fields.temperature, nodes, 1);
    restricted.cell_equivalent_strain_rate = at_cells(fields.cell_equivalent_strain_rate, cells);
    restricted.cell_hydrostatic_stress = at_cells(fields.cell_hydrostatic_stress, cells);
    if (fields.cell_load_error.size() == mesh.n_cells())
      restricted.cell_load_error = at_cells(fields.cell_load_error, cells);
    files.emplace_back(piece_name(r), fields_vtu(piece, restricted, stop_reason, cells));
  }

  // The parallel file: the arrays fields_vtu writes (io/vtu.cpp), then the pieces.
  std::string text;
  auto out = std::back_inserter(text);
  fmt::format_to(out, "<?xml version=\"1.0\"?>\n");
  if (stop_reason != solvers::StopReason::Converged)
    fmt::format_to(out,
                   "<!-- NOT CONVERGED ({}): these fields are the last iterate, not a "
                   "solution -->\n",
                   solvers::stop_reason_name(stop_reason));
  const auto scalar = [&](const char* name, const char* type = "Float64") {
    fmt::format_to(out, "      <PDataArray type=\"{}\" Name=\"{}\"/>\n", type, name);
  };
  fmt::format_to(out, "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" "
                      "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
                      "  <PUnstructuredGrid GhostLevel=\"0\">\n"
                      "    <PPointData Scalars=\"equivalent_strain_rate\" Vectors=\"velocity\">\n"
                      "      <PDataArray type=\"Float64\" Name=\"velocity\" "
                      "NumberOfComponents=\"3\"/>\n");
  for (const char* name : {"equivalent_strain_rate", "hydrostatic_stress", "hydrostatic_pressure",
                           "contact_pressure", "friction_stress"})
    scalar(name);
  if (fields.temperature.size() > 0) scalar("temperature");
  fmt::format_to(out, "    </PPointData>\n"
                      "    <PCellData Scalars=\"equivalent_strain_rate\">\n");
  for (const char* name : {"equivalent_strain_rate", "hydrostatic_stress", "hydrostatic_pressure"})
    scalar(name);
  if (fields.cell_load_error.size() == mesh.n_cells()) scalar("load_error_indicator");
  scalar("cell_id", "Int64");
  fmt::format_to(out, "    </PCellData>\n"
                      "    <PPoints>\n"
                      "      <PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n"
                      "    </PPoints>\n");
  for (int r = 0; r < parts; ++r)
    fmt::format_to(out, "    <Piece Source=\"{}\"/>\n", piece_name(r));
  fmt::format_to(out, "  </PUnstructuredGrid>\n</VTKFile>\n");
  files.front() = {"fields.pvtu", std::move(text)};
  return files;
}

template std::vector<std::pair<std::string, std::string>> fields_pvtu<2>(const mesh::Mesh<2>&,
                                                                         const post::Fields&,
                                                                         solvers::StopReason, int,
                                                                         std::span<const int>);
template std::vector<std::pair<std::string, std::string>> fields_pvtu<3>(const mesh::Mesh<3>&,
                                                                         const post::Fields&,
                                                                         solvers::StopReason, int,
                                                                         std::span<const int>);

} // namespace formflow::io
