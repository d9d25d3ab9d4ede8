// SPDX-License-Identifier: MIT
// VTK XML UnstructuredGrid writer (ASCII) for Q1/Q2 meshes in 2D and 3D and their fields.
#include "formflow/io/vtu.hpp"

#include "formflow/core/error.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <iterator>
#include <string_view>
#include <utility>

namespace formflow::io {

namespace {

// Our cells are lexicographic (fem/lagrange.hpp); VTK wants the corners
// counter-clockwise, then the mid-edge nodes (bottom, right, top, left), then
// the centre:
//
//   lexicographic (ours)        VTK_QUAD (9)     VTK_BIQUADRATIC_QUAD (28)
//   Q1        Q2
//   2 --- 3   6 --- 7 --- 8      3 --- 2          3 --- 6 --- 2
//   |     |   |     |     |      |     |          |     |     |
//   |     |   3 --- 4 --- 5      |     |          7 --- 8 --- 5
//   0 --- 1   0 --- 1 --- 2      0 --- 1          0 --- 4 --- 1
//
// so VTK position k takes our local node order[k].
constexpr std::array<int, 4> vtk_from_q1 = {0, 1, 3, 2};
constexpr std::array<int, 9> vtk_from_q2 = {0, 2, 8, 6, 1, 5, 7, 3, 4};

// Hexahedra: our node (i, j, k) on the lattice of n_side per direction is
// i + n_side·(j + n_side·k) (x fastest). VTK_HEXAHEDRON wants the bottom face
// (z = 0) counter-clockwise seen from +z, then the top face the same way.
// VTK_TRIQUADRATIC_HEXAHEDRON then takes the edge midpoints: the bottom
// face's four edges (along 0-1, 1-2, 2-3, 3-0), the top face's, the four
// vertical edges (above 0, 1, 2, 3); then the face centres in the order
// x = 0, x = 1, y = 0, y = 1, z = 0, z = 1 (what vtkTriQuadraticHexahedron::
// GetParametricCoords returns, which differs from its class comment); then
// the body centre. Lattice positions (i, j, k) ∈ {0, 1, 2}³:
//
//   corners  (0,0,0) (2,0,0) (2,2,0) (0,2,0) (0,0,2) (2,0,2) (2,2,2) (0,2,2)
//   edges    (1,0,0) (2,1,0) (1,2,0) (0,1,0)   (1,0,2) (2,1,2) (1,2,2) (0,1,2)
//            (0,0,1) (2,0,1) (2,2,1) (0,2,1)
//   faces    (0,1,1) (2,1,1) (1,0,1) (1,2,1) (1,1,0) (1,1,2)     centre (1,1,1)
//
// tests/unit/io/test_vtu_hexahedra.cpp checks this against VTK's own coordinates.
constexpr std::array<int, 8> vtk_from_hex8 = {0, 1, 3, 2, 4, 5, 7, 6};
constexpr std::array<int, 27> vtk_from_hex27 = {0,  2,  8,  6,  18, 20, 26, 24, 1,
                                                5,  7,  3,  19, 23, 25, 21, 9,  11,
                                                17, 15, 12, 14, 10, 16, 4,  22, 13};

// Simplices: our local order is VTK's (vertices, then edge midpoints).
constexpr std::array<int, 10> vtk_from_simplex = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};

using Out = std::back_insert_iterator<std::string>;

void check_size(std::string_view name, Index actual, Index expected) {
  if (actual != expected)
    throw InternalError(
        fmt::format("fields.vtu: {} has {} values, expected {}", name, actual, expected));
}

void check_finite(std::string_view name, const VectorX& values) {
  for (Index i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw InternalError(fmt::format("fields.vtu: {}[{}] is not finite", name, i));
}

/// What goes before item `i` of a list written `per_line` items to a line.
const char* separator(Index i, Index per_line) {
  if (i % per_line != 0) return " ";
  return i == 0 ? "          " : "\n          ";
}

/// One Float64 data array; `sign` flips it (σ_H → −σ_H) without a copy.
void scalar_array(Out out, std::string_view name, const VectorX& values, Real sign = 1.0) {
  fmt::format_to(out, "        <DataArray type=\"Float64\" Name=\"{}\" format=\"ascii\">\n", name);
  for (Index i = 0; i < values.size(); ++i)
    fmt::format_to(out, "{}{}", separator(i, 6), sign * values[i] + 0.0);
  // `+ 0.0` turns −0 into 0, so a zero field never reads as "-0".
  fmt::format_to(out, "\n        </DataArray>\n");
}

/// One 3-component tuple from `dim` values (a plane vector gets z = 0);
/// `zero` is added to each value (0.0 turns −0 into 0 as in scalar_array, −0.0
/// keeps every value's sign as the coordinates always have been written).
template <int dim> void tuple3(Out out, const Real* values, Real zero) {
  if constexpr (dim == 2)
    fmt::format_to(out, "          {} {} 0\n", values[0] + zero, values[1] + zero);
  else
    fmt::format_to(out, "          {} {} {}\n", values[0] + zero, values[1] + zero,
                   values[2] + zero);
}

template <int dim> void points_section(Out out, const mesh::Mesh<dim>& mesh) {
  fmt::format_to(out, "      <Points>\n        <DataArray type=\"Float64\" "
                      "NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (Index n = 0; n < mesh.n_nodes(); ++n) {
    const Point<dim> x = mesh.nodes.col(n);
    tuple3<dim>(out, x.data(), -0.0);
  }
  fmt::format_to(out, "        </DataArray>\n      </Points>\n");
}

template <int dim> void cells_section(Out out, const mesh::Mesh<dim>& mesh) {
  const std::span<const int> order = vtk_node_order(mesh.cell_type(), dim);
  const int per_cell = static_cast<int>(order.size());
  fmt::format_to(out, "      <Cells>\n        <DataArray type=\"Int64\" Name=\"connectivity\" "
                      "format=\"ascii\">\n");
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    fmt::format_to(out, "         ");
    for (const int local : order) fmt::format_to(out, " {}", mesh.cells(local, c));
    fmt::format_to(out, "\n");
  }
  fmt::format_to(out, "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" "
                      "format=\"ascii\">\n");
  for (Index c = 0; c < mesh.n_cells(); ++c)
    fmt::format_to(out, "{}{}", separator(c, 10), static_cast<long long>(c + 1) * per_cell);
  fmt::format_to(out, "\n        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" "
                      "format=\"ascii\">\n");
  const int type = vtk_cell_type(mesh.cell_type(), dim);
  for (Index c = 0; c < mesh.n_cells(); ++c) fmt::format_to(out, "{}{}", separator(c, 20), type);
  fmt::format_to(out, "\n        </DataArray>\n      </Cells>\n");
}

template <int dim>
void point_data_section(Out out, const mesh::Mesh<dim>& mesh, const post::Fields& fields) {
  fmt::format_to(out, "      <PointData Scalars=\"equivalent_strain_rate\" Vectors=\"velocity\">\n"
                      "        <DataArray type=\"Float64\" Name=\"velocity\" "
                      "NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (Index n = 0; n < mesh.n_nodes(); ++n)
    tuple3<dim>(out, fields.velocity.data() + dim * n, 0.0);
  fmt::format_to(out, "        </DataArray>\n");
  scalar_array(out, "equivalent_strain_rate", fields.equivalent_strain_rate);
  scalar_array(out, "hydrostatic_stress", fields.hydrostatic_stress);
  scalar_array(out, "hydrostatic_pressure", fields.hydrostatic_stress, -1.0);
  scalar_array(out, "contact_pressure", fields.contact_pressure);
  scalar_array(out, "friction_stress", fields.friction_stress);
  if (fields.temperature.size() > 0) scalar_array(out, "temperature", fields.temperature);
  fmt::format_to(out, "      </PointData>\n");
}

template <int dim>
void cell_data_section(Out out, const mesh::Mesh<dim>& mesh, const post::Fields& fields,
                       std::span<const Index> cell_ids) {
  fmt::format_to(out, "      <CellData Scalars=\"equivalent_strain_rate\">\n");
  scalar_array(out, "equivalent_strain_rate", fields.cell_equivalent_strain_rate);
  scalar_array(out, "hydrostatic_stress", fields.cell_hydrostatic_stress);
  scalar_array(out, "hydrostatic_pressure", fields.cell_hydrostatic_stress, -1.0);
  // The load's error indicator (signed share of p_{h/2} − p_h), when it was estimated.
  if (fields.cell_load_error.size() == mesh.n_cells())
    scalar_array(out, "load_error_indicator", fields.cell_load_error);
  fmt::format_to(out, "        <DataArray type=\"Int64\" Name=\"cell_id\" format=\"ascii\">\n");
  for (Index c = 0; c < mesh.n_cells(); ++c)
    fmt::format_to(out, "{}{}", separator(c, 10), cell_ids.empty() ? c : cell_ids[c]);
  fmt::format_to(out, "\n        </DataArray>\n      </CellData>\n");
}

template <int dim> void check_fields(const mesh::Mesh<dim>& mesh, const post::Fields& fields) {
  const Index n_nodes = mesh.n_nodes(), n_cells = mesh.n_cells();
  check_size("velocity", static_cast<Index>(fields.velocity.size()), dim * n_nodes);
  const std::array<std::pair<std::string_view, const VectorX*>, 4> nodal = {
      {{"equivalent_strain_rate", &fields.equivalent_strain_rate},
       {"hydrostatic_stress", &fields.hydrostatic_stress},
       {"contact_pressure", &fields.contact_pressure},
       {"friction_stress", &fields.friction_stress}}};
  for (const auto& [name, values] : nodal)
    check_size(name, static_cast<Index>(values->size()), n_nodes);
  check_size("cell equivalent_strain_rate",
             static_cast<Index>(fields.cell_equivalent_strain_rate.size()), n_cells);
  check_size("cell hydrostatic_stress", static_cast<Index>(fields.cell_hydrostatic_stress.size()),
             n_cells);
  check_finite("velocity", fields.velocity);
  for (const auto& [name, values] : nodal) check_finite(name, *values);
  check_finite("cell equivalent_strain_rate", fields.cell_equivalent_strain_rate);
  check_finite("cell hydrostatic_stress", fields.cell_hydrostatic_stress);
  if (fields.temperature.size() > 0) {
    check_size("temperature", static_cast<Index>(fields.temperature.size()), n_nodes);
    check_finite("temperature", fields.temperature);
  }
  check_finite("cell load_error_indicator", fields.cell_load_error);
  for (Index n = 0; n < mesh.n_nodes(); ++n)
    if (!mesh.nodes.col(n).allFinite())
      throw InternalError(fmt::format("fields.vtu: node {} has a non-finite coordinate", n));
}

} // namespace

int vtk_cell_type(int order, int dim) {
  if (dim == 2 && order == 1) return 9;
  if (dim == 2 && order == 2) return 28;
  if (dim == 3 && order == 1) return 12;
  if (dim == 3 && order == 2) return 29;
  throw InternalError(
      fmt::format("fields.vtu: no VTK cell type for order {} in {} dimensions", order, dim));
}

std::span<const int> vtk_node_order(int order, int dim) {
  if (dim == 2 && order == 1) return vtk_from_q1;
  if (dim == 2 && order == 2) return vtk_from_q2;
  if (dim == 3 && order == 1) return vtk_from_hex8;
  if (dim == 3 && order == 2) return vtk_from_hex27;
  throw InternalError(
      fmt::format("fields.vtu: no VTK node order for order {} in {} dimensions", order, dim));
}

int vtk_cell_type(const mesh::CellType& type, int dim) {
  if (!type.is_simplex()) return vtk_cell_type(type.order, dim);
  if (dim == 2) return type.order == 1 ? 5 : 22;
  return type.order == 1 ? 10 : 24;
}

std::span<const int> vtk_node_order(const mesh::CellType& type, int dim) {
  if (!type.is_simplex()) return vtk_node_order(type.order, dim);
  const int vertices = dim + 1;
  const int nodes = type.order == 1 ? vertices : vertices * (vertices + 1) / 2;
  return std::span<const int>(vtk_from_simplex).first(static_cast<std::size_t>(nodes));
}

template <int dim>
std::string fields_vtu(const mesh::Mesh<dim>& mesh, const post::Fields& fields,
                       solvers::StopReason stop_reason, std::span<const Index> cell_ids) {
  if (!cell_ids.empty() && static_cast<Index>(cell_ids.size()) != mesh.n_cells())
    throw InternalError("fields.vtu: one cell_id per cell");
  if (!mesh.is_simplex() &&
      mesh.nodes_per_cell() != static_cast<int>(vtk_node_order(mesh.order, dim).size()))
    throw InternalError(fmt::format("fields.vtu: cells do not have (order + 1)^{} nodes", dim));
  check_fields(mesh, fields);
  std::string text;
  Out out(text);
  const bool converged = stop_reason == solvers::StopReason::Converged;
  fmt::format_to(out, "<?xml version=\"1.0\"?>\n");
  // Stop reasons are fixed lower-case words: nothing to escape inside the comment.
  if (!converged)
    fmt::format_to(out,
                   "<!-- NOT CONVERGED ({}): these fields are the last iterate, not a "
                   "solution -->\n",
                   solvers::stop_reason_name(stop_reason));
  fmt::format_to(out,
                 "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
                 "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
                 "  <UnstructuredGrid>\n"
                 "    <FieldData>\n"
                 "      <DataArray type=\"Int32\" Name=\"converged\" NumberOfTuples=\"1\" "
                 "format=\"ascii\">{}</DataArray>\n"
                 "    </FieldData>\n"
                 "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
                 converged ? 1 : 0, mesh.n_nodes(), mesh.n_cells());
  points_section(out, mesh);
  cells_section(out, mesh);
  point_data_section(out, mesh, fields);
  cell_data_section(out, mesh, fields, cell_ids);
  fmt::format_to(out, "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
  return text;
}

template std::string fields_vtu<2>(const mesh::Mesh<2>&, const post::Fields&, solvers::StopReason,
                                   std::span<const Index>);
template std::string fields_vtu<3>(const mesh::Mesh<3>&, const post::Fields&, solvers::StopReason,
                                   std::span<const Index>);

} // namespace formflow::io
