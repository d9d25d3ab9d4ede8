// SPDX-License-Identifier: MIT
// Cell shape, element and pressure: the pairs that are stable, and what simplices run.
#include "formflow/io/case_validation_simplex.hpp"

#include "formflow/fem/element_choice.hpp"
#include "formflow/io/case_keys.hpp"

#include <fmt/format.h>

namespace formflow::io {

namespace {

using assembly::FormulationType;
using fem::ElementKind;
using fem::PressureSpace;

std::string quoted(std::string_view text) {
  return fmt::format("\"{}\"", text);
}

/// Cell shape against geometry.dimension and the element's family.
std::optional<KeyRefusal> shape_problem(const Case& case_) {
  const mesh::CellKind cell = case_.mesh.cell;
  const int dim = case_.mesh.dimension;
  if (mesh::dimension_of(cell) != dim) {
    const mesh::CellShape shape = mesh::shape_of(cell);
    return KeyRefusal{{"mesh.cell", "geometry.dimension"},
                      fmt::format("{} cells are {}-dimensional, and geometry.dimension = {}",
                                  mesh::cell_shape_name(shape, mesh::dimension_of(cell)),
                                  mesh::dimension_of(cell), dim),
                      fmt::format("with geometry.dimension = {} set mesh.cell = {} or {}", dim,
                                  quoted(mesh::cell_shape_name(mesh::CellShape::Cube, dim)),
                                  quoted(mesh::cell_shape_name(mesh::CellShape::Simplex, dim)))};
  }
  const bool simplex = mesh::shape_of(cell) == mesh::CellShape::Simplex;
  if (simplex != fem::is_simplex_element(case_.element))
    return KeyRefusal{
        {"mesh.element", "mesh.cell"},
        fmt::format("{} is an element of {}, and mesh.cell = {}", fem::element_name(case_.element),
                    simplex ? "quadrilaterals and hexahedra" : "triangles and tetrahedra",
                    quoted(mesh::cell_shape_name(mesh::shape_of(cell), dim))),
        simplex ? "on triangles and tetrahedra use mesh.element = \"P2\" or \"P1b\""
                : "on quadrilaterals and hexahedra use mesh.element = \"Q2\" or \"Q1\""};
  return std::nullopt;
}

/// The pressure paired with a simplex element, and the formulation it needs.
std::optional<KeyRefusal> simplex_pair_problem(const Case& case_) {
  const PressureSpace pressure = case_.formulation.pressure;
  if (case_.formulation.type == FormulationType::Penalty)
    return KeyRefusal{{"formulation.type", "mesh.cell"},
                      "the volumetric penalty term has no reduced rule on simplices that does "
                      "not lock; their penalty method is the mixed formulation with "
                      "penalty.d > 0 (σ_H = Π div u / d, condensed cell by cell)",
                      "set formulation.type = \"mixed\" (the default on simplices), with "
                      "penalty.d as before"};
  if (pressure == PressureSpace::Q1)
    return KeyRefusal{{"formulation.pressure", "mesh.cell"},
                      "Q1 is the continuous pressure of quadrilaterals and hexahedra",
                      "on triangles and tetrahedra use formulation.pressure = \"P1\" (continuous), "
                      "\"P1disc\" or \"P0\""};
  if (case_.element == ElementKind::P1b && pressure != PressureSpace::P1)
    return KeyRefusal{{"formulation.pressure", "mesh.element"},
                      fmt::format("P1b is the MINI element, stable with the continuous P1 "
                                  "pressure only; with {} its one bubble per cell cannot carry "
                                  "the cell's {} constraints",
                                  fem::pressure_space_name(pressure),
                                  pressure == PressureSpace::P0 ? "pressure" : "linear pressure"),
                      "with mesh.element = \"P1b\" use formulation.pressure = \"P1\" (the "
                      "default), or mesh.element = \"P2\""};
  return std::nullopt;
}

/// What the simplex path does not run yet, refused by the key that asks for it.
std::optional<KeyRefusal> simplex_scope_problem(const Case& case_) {
  if (case_.adapt.enabled())
    return KeyRefusal{{"adapt.target_error", "mesh.cell"},
                      "adaptive refinement remeshes with quadrilaterals only",
                      "set adapt.target_error = 0 (no adaptivity), or mesh.cell = "
                      "\"quadrilateral\""};
  return std::nullopt;
}

} // namespace

void resolve_cell_defaults(Case& case_, const std::function<bool(const std::string&)>& is_set) {
  // (A profile's tetrahedra are resolved before: io/case_validation_profile.hpp.)
  if (!is_set("mesh.cell") && case_.mesh.dimension == 3 &&
      case_.mesh.cell == mesh::CellKind::Quadrilateral)
    case_.mesh.cell = mesh::CellKind::Hexahedron;
  if (mesh::shape_of(case_.mesh.cell) != mesh::CellShape::Simplex) return;
  if (!is_set("mesh.element")) case_.element = ElementKind::P2;
  if (!is_set("formulation.type")) case_.formulation.type = FormulationType::Mixed;
  if (!is_set("formulation.pressure") && case_.element == ElementKind::P1b)
    case_.formulation.pressure = PressureSpace::P1;
}

std::optional<KeyRefusal> cell_case_problem(const Case& case_,
                                            const std::function<bool(const std::string&)>& is_set) {
  if (auto problem = shape_problem(case_)) return problem;
  // The manufactured solve is the CHOLMOD secant loop: a mixed pressure must be condensed
  // with d > 0 there (no saddle point, no Uzawa steps).
  const bool mixed = case_.formulation.type == FormulationType::Mixed;
  if (mixed && case_.manufactured != physics::ManufacturedSolution::None &&
      (!fem::is_discontinuous(case_.formulation.pressure) || case_.penalty.d == 0 ||
       case_.formulation.discontinuous == assembly::DiscontinuousPressure::SaddlePoint))
    return KeyRefusal{{"verification.solution", "formulation.pressure", "penalty.d"},
                      "the manufactured solutions are solved with the pressure condensed per "
                      "cell: a discontinuous pressure (P1disc, P0) with penalty.d > 0",
                      "use formulation.pressure = \"P1disc\" with penalty.d > 0, or "
                      "verification.solution = \"none\""};
  const bool simplex = mesh::shape_of(case_.mesh.cell) == mesh::CellShape::Simplex;
  if (!simplex) {
    if (case_.formulation.type == FormulationType::Mixed &&
        case_.formulation.pressure == PressureSpace::P1)
      return KeyRefusal{{"formulation.pressure", "mesh.cell"},
                        "P1 is the continuous pressure of triangles and tetrahedra",
                        "on quadrilaterals and hexahedra use formulation.pressure = \"Q1\" "
                        "(continuous), \"P1disc\" or \"P0\""};
    return std::nullopt;
  }
  if (auto problem = simplex_pair_problem(case_)) return problem;
  // The volumetric rule belongs to the penalty term that simplices do not use.
  const CaseKey* volumetric = find_case_key("integration.volumetric");
  if (is_set("integration.volumetric") && volumetric->get(case_) != volumetric->default_value)
    return KeyRefusal{{"integration.volumetric", "mesh.cell"},
                      "the volumetric rule is the penalty term's, which simplices do not use",
                      "leave integration.volumetric out on triangles and tetrahedra"};
  return simplex_scope_problem(case_);
}

mesh::CellType case_cell_type(const Case& case_) {
  const bool mixed = case_.formulation.type == FormulationType::Mixed;
  return fem::velocity_cell_type(case_.element, case_.formulation.pressure, mixed);
}

} // namespace formflow::io
