// SPDX-License-Identifier: MIT
// fields.vtu: the mesh and the result fields as a VTK XML UnstructuredGrid.
#pragma once

#include "formflow/mesh/mesh.hpp"
#include "formflow/post/results.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include "formflow/mesh/cell_type.hpp"
#include <array>

#include <span>
#include <string>

namespace formflow::io {

/// VTK cell type of a cell of `order` in `dim` dimensions: 9 (VTK_QUAD) for
/// Q1, 28 (VTK_BIQUADRATIC_QUAD) for Q2; in 3D 12 (VTK_HEXAHEDRON) for Q1, 29
/// (VTK_TRIQUADRATIC_HEXAHEDRON) for the 27-node Q2.
int vtk_cell_type(int order, int dim = 2);

/// For each VTK node position k, the lexicographic local node index that goes
/// there (size 4, 9, 8 or 27). See vtu.cpp for the drawing.
std::span<const int> vtk_node_order(int order, int dim = 2);

/// The same for any cell type. Simplices: 5 (VTK_TRIANGLE), 22 (VTK_QUADRATIC_TRIANGLE),
/// 10 (VTK_TETRA), 24 (VTK_QUADRATIC_TETRA); their local nodes are already in VTK's
/// order (fem/simplex_lagrange.hpp), and bubble nodes, which VTK has no cell for, are
/// left out of the cells (they stay points of the grid, with their values).
int vtk_cell_type(const mesh::CellType& type, int dim);
std::span<const int> vtk_node_order(const mesh::CellType& type, int dim);

/// The whole fields.vtu document (ASCII) of a plane (dim 2, points and
/// velocities get z = 0) or solid (dim 3) mesh.
/// Point data: velocity (3 components), equivalent_strain_rate,
/// hydrostatic_stress (σ_H, tension positive), hydrostatic_pressure (−σ_H),
/// contact_pressure, friction_stress. Cell data: equivalent_strain_rate,
/// hydrostatic_stress, hydrostatic_pressure (cell means) and cell_id.
/// Field data (one value for the whole grid, shown by ParaView's
/// Information panel and read by any VTK reader): Int32 `converged`, 1 or 0;
/// a run that stopped for another `stop_reason` also carries an XML comment
/// `NOT CONVERGED (<stop_reason>)` at the top of the file.
/// Throws InternalError if a field has the wrong size or a non-finite value.
/// `cell_ids`: the cell_id written for each cell (a piece of fields.pvtu, io/pvtu.hpp,
/// gives its cells' ids in the whole mesh); empty: 0, 1, 2, ...
template <int dim>
std::string fields_vtu(const mesh::Mesh<dim>& mesh, const post::Fields& fields,
                       solvers::StopReason stop_reason = solvers::StopReason::Converged,
                       std::span<const Index> cell_ids = {});

} // namespace formflow::io
