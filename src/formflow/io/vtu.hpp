// SPDX-License-Identifier: MIT
// fields.vtu: the mesh and the result fields as a VTK XML UnstructuredGrid.
#pragma once

#include "formflow/mesh/mesh.hpp"
#include "formflow/post/results.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <array>
#include <span>
#include <string>

namespace formflow::io {

/// VTK cell type of a 2D cell of `order`: 9 (VTK_QUAD) for Q1, 28
/// (VTK_BIQUADRATIC_QUAD) for Q2.
int vtk_cell_type(int order);

/// For each VTK node position k, the lexicographic local node index that goes
/// there (size 4 for Q1, 9 for Q2). See vtu.cpp for the drawing.
std::span<const int> vtk_node_order(int order);

/// The whole fields.vtu document (ASCII). Points have z = 0.
/// Point data: velocity (3 components, z = 0), equivalent_strain_rate,
/// hydrostatic_stress (σ_H, tension positive), hydrostatic_pressure (−σ_H),
/// contact_pressure, friction_stress. Cell data: equivalent_strain_rate,
/// hydrostatic_stress, hydrostatic_pressure (cell means) and cell_id.
/// Field data (one value for the whole grid, shown by ParaView's
/// Information panel and read by any VTK reader): Int32 `converged`, 1 or 0;
/// a run that stopped for another `stop_reason` also carries an XML comment
/// `NOT CONVERGED (<stop_reason>)` at the top of the file.
/// Throws InternalError if a field has the wrong size or a non-finite value.
std::string fields_vtu(const mesh::Mesh<2>& mesh, const post::Fields& fields,
                       solvers::StopReason stop_reason = solvers::StopReason::Converged);

} // namespace formflow::io
