// SPDX-License-Identifier: MIT
// The checks between case keys that CaseBuilder runs once every key is set
// (io/case_builder.hpp), and the defaults that depend on other keys.
#include "formflow/core/error.hpp"
#include "formflow/io/case_builder.hpp"
#include "formflow/io/case_validation_3d.hpp"
#include "formflow/io/case_validation_mesh_source.hpp"
#include "formflow/io/case_validation_profile.hpp"
#include "formflow/io/case_validation_simplex.hpp"
#include "formflow/io/mesh_memory.hpp"
#include "formflow/io/problem_shape.hpp"
#include "formflow/io/stage_set.hpp"
#include "formflow/mesh/fitting_sizes.hpp"
#include "formflow/physics/friction.hpp"
#include "formflow/physics/manufactured_thermal.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/petsc_case_options.hpp"
#include "formflow/solvers/petsc_option_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace formflow::io {

namespace {

/// Suggests the nearest sizes that fit every length: "1.25 (= 10/8) or 2.5 (= 10/4)".
std::string fitting_sizes_hint(const mesh::ChannelGeometry& geometry, Real size) {
  const mesh::NearestFittingSizes nearest =
      mesh::nearest_fitting_sizes(mesh::lengths_to_fit(geometry), size);
  auto text = [](const mesh::FittingSize& choice) {
    return fmt::format("{} (= {}/{})", format_key_value(choice.size()), choice.length,
                       choice.cells);
  };
  if (nearest.smaller && nearest.larger)
    return "sizes that fit every length: " + text(*nearest.smaller) + " or " +
           text(*nearest.larger);
  if (nearest.smaller || nearest.larger)
    return "a size that fits every length: " +
           text(nearest.smaller ? *nearest.smaller : *nearest.larger);
  return "no size near this one fits every length: make the lengths multiples of one size";
}

/// Whether the discontinuous pressure kept as a saddle point, solved by the secant loop
/// (the 3D iterative path, issue 20), takes solver.acceleration = "anderson" when the key
/// is not set. On since session 13 (the lead's decision; docs/benchmarks.md "Anderson
/// acceleration": at h = 1/12 26 -> 17 fine steps, 427 -> 290 Krylov iterations, at h =
/// 0.125 29 -> 18–19 steps, the load within the stop's reach of δ). A case that sets the
/// key keeps its value and the resolved case (summary.json) records the choice.
constexpr bool anderson_by_default_on_saddle_point_secant = true;

} // namespace

/// Keys whose default depends on another key's value: mesh.cell and what it sets
/// (io/case_validation_simplex.hpp); solver.acceleration on the
/// saddle point's secant loop (anderson_by_default_on_saddle_point_secant); integration.volumetric
/// is the element's reduced rule unless set (the complete rule locks Q1,
/// paper Remark 5.1); an explicit complete rule with Q1 gets a warning.
void CaseBuilder::resolve_dependent_defaults() {
  const auto is_set = [this](const std::string& name) { return origin(name).order > 0; };
  resolve_cad_defaults(case_, is_set);
  resolve_profile_defaults(case_, is_set);
  if (!case_.profile_file.empty()) {
    const Origin where = origin("geometry.profile_file");
    read_profile_file(case_, where.file, where.line);
  }
  resolve_cell_defaults(case_, [this](const std::string& name) { return origin(name).order > 0; });
  // Laws of an absolute temperature read the case's temperatures in its unit.
  case_.material.parameters_of<physics::SellarsTegart>().absolute_offset =
      physics::absolute_offset(case_.thermal.unit);
  if (auto note = face_points_note(case_)) case_.warnings.push_back(std::move(*note));
  if (anderson_by_default_on_saddle_point_secant && origin("solver.acceleration").order == 0 &&
      case_.solver.method == solvers::NonlinearMethod::Secant &&
      case_.formulation.type == assembly::FormulationType::Mixed &&
      fem::is_discontinuous(case_.formulation.pressure) &&
      case_.formulation.discontinuous == assembly::DiscontinuousPressure::SaddlePoint)
    case_.solver.acceleration = solvers::NonlinearAcceleration::Anderson;
  const bool q1 = case_.element == fem::ElementKind::Q1;
  if (origin("integration.volumetric").order == 0) {
    case_.volumetric_points = q1 ? 1 : 2;
    return;
  }
  const Origin where = origin("integration.volumetric");
  if (q1 && case_.volumetric_points >= 2 &&
      case_.formulation.type == assembly::FormulationType::Penalty)
    case_.warnings.push_back(fmt::format(
        "{}{}: integration.volumetric = {} with mesh.element = \"Q1\" imposes the "
        "incompressibility at {} points per cell: the penalty solution locks (the load grows "
        "like 1/d); integration.volumetric = 1 is the reduced rule that does not",
        where.file, where.line > 0 ? fmt::format(":{}", where.line) : "", case_.volumetric_points,
        case_.volumetric_points * case_.volumetric_points));
}

void CaseBuilder::check_cross_keys() const {
  check_order("geometry.exit_half_height", "geometry.entry_half_height");
  check_order("material.rate1", "material.rate2");
  check_die();
  check_cells();
  check_solid();
  if (case_.mesh.source == mesh::MeshSource::Structured) check_mesh_fits();
  check_mesh_source();
  check_flow_law();
  check_formulation();
  check_linear_solver();
  check_acceleration();
  check_verification();
  check_thermal();
  check_adapt();
  check_mesh_memory();
}

/// Requires value(small) < value(large); blames whichever of the two was set last.
void CaseBuilder::check_order(const std::string& small, const std::string& large) const {
  const Real small_value = real_value(small), large_value = real_value(large);
  if (small_value < large_value) return;
  const bool blame_small = origin(small).order > origin(large).order;
  const std::string& blamed = blame_small ? small : large;
  const std::string& other = blame_small ? large : small;
  const Origin where = origin(blamed);
  throw InputError(where.file, where.line, blamed,
                   fmt::format("value {} is not {} {} = {}", format_key_value(real_value(blamed)),
                               blame_small ? "less than" : "greater than", other,
                               format_key_value(real_value(other))),
                   fmt::format("{} must be {} {}", blamed, blame_small ? "<" : ">", other));
}

/// Condition (2.11) of the whole law; blames the material key set last.
void CaseBuilder::check_flow_law() const {
  const auto non_finite = non_finite_law(); // first: (2.11) cannot be judged on inf or NaN
  const auto violation =
      non_finite ? non_finite : physics::check_flow_law(case_.material.selected());
  if (!violation) return;
  std::string blamed = "material.law";
  for (const CaseKey& key : case_keys())
    if (key.section() == "material" && origin(std::string(key.name)).order > origin(blamed).order)
      blamed = key.name;
  const Origin where = origin(blamed);
  if (non_finite)
    throw InputError(where.file, where.line, blamed,
                     "the flow law cannot be evaluated: " + *non_finite,
                     "choose parameters whose σ_p is a finite stress between rate1/10 and "
                     "10 rate2 (e.g. a smaller |m1 T| or |m4/ε| of hensel_spittel)");
  throw InputError(where.file, where.line, blamed,
                   "the flow law violates condition (2.11): " + *violation,
                   "choose parameters with σ_p increasing and σ_p′ ≤ σ_p/ε̄̇ (rate exponent in "
                   "(0, 1])");
}

/// Where σ_p, σ_p/ε̄̇ or σ_p′ is not a finite, positive (or for σ_p′
/// non-negative) number over the rates the solver can meet: [rate1/10,
/// 10 rate2] and the first iterate's solver.initial_rate.
std::optional<std::string> CaseBuilder::non_finite_law() const {
  const physics::FlowLaw law = case_.material.selected();
  const Real low = law.rate1 / 10, high = law.rate2 * 10;
  std::vector<Real> rates = {case_.solver.initial_rate};
  for (int k = 0; k <= 8; ++k) rates.push_back(low * std::pow(high / low, k / 8.0));
  for (const Real rate : rates) {
    const Real stress = law.yield_stress(rate);
    const auto [viscosity, derivative] = law.secant_viscosity_and_derivative(rate);
    const bool normal = std::isnormal(stress) && stress > 0 && std::isnormal(viscosity) &&
                        viscosity > 0 && std::isfinite(derivative) && derivative >= 0;
    if (!normal)
      return fmt::format("σ_p({}) = {}, σ_p/ε̄̇ = {}, σ_p′ = {}: not finite and positive",
                         format_key_value(rate), format_key_value(stress),
                         format_key_value(viscosity), format_key_value(derivative));
  }
  return std::nullopt;
}

/// Pairs and exact constraints the solver can honour (docs/mixed.md).
void CaseBuilder::check_formulation() const {
  using assembly::FormulationType;
  using fem::PressureSpace;
  const bool mixed = case_.formulation.type == FormulationType::Mixed;
  const PressureSpace pressure = case_.formulation.pressure;
  if (case_.penalty.d == 0 && !mixed)
    blame({"penalty.d", "formulation.type"},
          "d = 0 (exact incompressibility) needs a pressure space: the penalty formulation "
          "would lock (complete rule) or leave σ_H undefined",
          "set formulation.type = \"mixed\" (e.g. with formulation.pressure = \"P1disc\"), "
          "or use penalty.d > 0");
  if (case_.formulation.discontinuous == assembly::DiscontinuousPressure::SaddlePoint &&
      (!mixed || !fem::is_discontinuous(pressure)))
    blame(
        {"formulation.discontinuous_pressure", mixed ? "formulation.pressure" : "formulation.type"},
        mixed ? "the Q1 pressure is continuous: it is always solved as a saddle point, so "
                "\"saddle_point\" here would be set in vain"
              : "the penalty formulation has no pressure space to keep as a saddle point",
        mixed ? "remove formulation.discontinuous_pressure, or use formulation.pressure = "
                "\"P1disc\" or \"P0\""
              : "set formulation.type = \"mixed\" (with formulation.pressure = \"P1disc\" "
                "or \"P0\"), or remove formulation.discontinuous_pressure");
  // The combinations no loop serves, from the capability table the run plan reads.
  const solvers::ProblemShape shape = problem_shape(case_);
  const auto loop = solvers::choose_loop(shape);
  if (const auto* refused = std::get_if<solvers::Refusal>(&loop))
    blame(std::vector<std::string>(refused->keys.begin(), refused->keys.end()), refused->message,
          refused->hint);
  if (!mixed) return;
  if (case_.element == fem::ElementKind::Q1 && pressure != PressureSpace::P0)
    blame({"formulation.pressure", "mesh.element"},
          pressure == PressureSpace::Q1
              ? std::string("Q1 velocity with the Q1 pressure is not inf-sup stable (spurious "
                            "pressure modes, docs/mixed.md)")
              : fmt::format("Q1 velocity with the {} pressure locks (more pressure than velocity "
                            "freedom per cell)",
                            fem::pressure_space_name(pressure)),
          "with mesh.element = \"Q1\" use formulation.pressure = \"P0\"; or mesh.element = \"Q2\"");
  if (case_.element == fem::ElementKind::Q1 && case_.penalty.d == 0)
    blame({"penalty.d", "mesh.element"},
          "Q1–P0 is not inf-sup stable (Remark 4.3: checkerboard pressure, β_h → 0), so the "
          "exact constraint d = 0 is refused",
          "use penalty.d > 0 with Q1–P0, or mesh.element = \"Q2\" with \"P1disc\"");
}

/// solver.linear = "petsc" needs a PETSc build; solver.petsc_options needs petsc,
/// PETSc's option syntax and only the solver options a case file may carry
/// (solvers/petsc_case_options.hpp: no viewer, monitor or file; whether PETSc reads
/// them is checked at the first factorisation, where PETSc has read them).
void CaseBuilder::check_linear_solver() const {
  if (!solvers::is_built(case_.solver.linear))
    blame({"solver.linear"}, "this formflow was built without PETSc (FORMFLOW_WITH_PETSC=OFF)",
          "rebuild with -DFORMFLOW_WITH_PETSC=ON (./run and ./test do), or use \"cholmod\" or "
          "\"umfpack\"");
  const std::string& options = case_.solver.petsc_options;
  if (options.empty()) return;
  if (case_.solver.linear != solvers::LinearSolverKind::Petsc)
    blame({"solver.petsc_options", "solver.linear"},
          "PETSc options are read only by solver.linear = \"petsc\"",
          "set solver.linear = \"petsc\", or remove solver.petsc_options");
  if (const auto problem = solvers::petsc_option_syntax_error(options))
    blame({"solver.petsc_options"}, *problem,
          "e.g. \"-ksp_type cg -pc_type gamg -ksp_rtol 1e-10\"");
  if (const auto refusal = solvers::case_petsc_options_refusal(options))
    blame({"solver.petsc_options"}, *refusal, std::string(solvers::case_petsc_options_allowed()));
}

/// Anderson acceleration mixes the secant loop's steps: Newton's loop has no such map
/// (its steps converge quadratically; the secant steps it starts with are few), and a
/// depth other than the default without acceleration would be read by nothing (the
/// default is accepted: a resolved case, every key written, must load again).
void CaseBuilder::check_acceleration() const {
  const bool anderson = case_.solver.acceleration == solvers::NonlinearAcceleration::Anderson;
  if (anderson && case_.solver.method == solvers::NonlinearMethod::Newton)
    blame({"solver.acceleration", "solver.method"},
          "Anderson acceleration mixes the steps of the secant iteration; Newton's steps are "
          "not a fixed-point map's",
          "set solver.method = \"secant\", or solver.acceleration = \"none\"");
  if (!anderson && case_.solver.acceleration_depth != Case{}.solver.acceleration_depth)
    blame({"solver.acceleration_depth", "solver.acceleration"},
          "solver.acceleration_depth is read only by solver.acceleration = \"anderson\"",
          "set solver.acceleration = \"anderson\", or remove solver.acceleration_depth");
}

/// Cells, element and pressure that go together (io/case_validation_simplex.hpp).
void CaseBuilder::check_cells() const {
  const auto refusal =
      cell_case_problem(case_, [this](const std::string& name) { return origin(name).order > 0; });
  if (refusal) blame(refusal->keys, refusal->message, refusal->hint);
}

/// What geometry.dimension = 3 cannot run yet, and solid-channel keys set in vain
/// (io/case_validation_3d.hpp).
void CaseBuilder::check_solid() const {
  const auto is_set = [this](const std::string& name) { return origin(name).order > 0; };
  if (const auto refusal = solid_case_problem(case_, is_set))
    blame(refusal->keys, refusal->message, refusal->hint);
  if (const auto refusal = profile_case_problem(case_, is_set))
    blame(refusal->keys, refusal->message, refusal->hint);
}

/// What each mesh source needs and reads (io/case_validation_mesh_source.hpp).
void CaseBuilder::check_mesh_source() const {
  if (const auto refusal = mesh_source_problem(case_))
    blame(refusal->keys, refusal->message, refusal->hint);
}

/// A manufactured solution lives on the unit square; the smooth map must stay one-to-one.
void CaseBuilder::check_verification() const {
  if (case_.manufactured == physics::ManufacturedSolution::None) return;
  if (mesh::cells_along(1.0, case_.mesh.size) <= 0)
    die_error("mesh.size",
              fmt::format("value {} does not divide the unit square of verification.solution",
                          format_key_value(case_.mesh.size)),
              "use 1/n, e.g. 0.25 or 0.125", {"verification.solution"});
  if (case_.mesh.distortion.kind == mesh::Distortion::Smooth &&
      case_.mesh.distortion.amplitude > 0.1) {
    const Origin where = origin("verification.amplitude");
    throw InputError(where.file, where.line, "verification.amplitude",
                     fmt::format("value {} folds the smooth distortion map",
                                 format_key_value(case_.mesh.distortion.amplitude)),
                     "must be ≤ 0.1 with verification.distortion = \"smooth\"");
  }
}

/// Hot forming (docs/thermal.md): the temperature range the flow law will meet, and
/// what a coupled run does not do yet.
void CaseBuilder::check_thermal() const {
  const physics::Thermal& thermal = case_.thermal;
  if (!thermal.enabled) return;
  // The coupled manufactured solution (physics/manufactured_thermal.hpp): plane only, T
  // from billet_temperature to 1.5 × coupled_temperature_rise above it, all inside the
  // range the law is checked on (else the clamp would change the exact problem).
  if (case_.manufactured != physics::ManufacturedSolution::None && case_.mesh.dimension == 3)
    die_error("thermal.enabled",
              "the coupled manufactured solution (verification.solution with thermal) is "
              "plane only",
              "set mesh.dimension = 2 or thermal.enabled = false", {"verification.solution"});
  if (case_.manufactured != physics::ManufacturedSolution::None &&
      thermal.max_temperature <
          thermal.billet_temperature + 1.5 * physics::coupled_temperature_rise)
    die_error("thermal.max_temperature",
              fmt::format("value {} is below the coupled manufactured solution's highest T, "
                          "billet_temperature + {}",
                          format_key_value(thermal.max_temperature),
                          1.5 * physics::coupled_temperature_rise),
              "raise thermal.max_temperature", {"verification.solution"});
  const bool convective = thermal.free_surface_transfer > 0;
  const Real low = std::min({thermal.billet_temperature, thermal.tool_temperature,
                             convective ? thermal.ambient_temperature : INFINITY});
  const Real high = std::max({thermal.billet_temperature, thermal.tool_temperature,
                              convective ? thermal.ambient_temperature : -INFINITY});
  if (!(thermal.max_temperature > high))
    die_error(
        "thermal.max_temperature",
        fmt::format("value {} is not above the highest prescribed temperature {}",
                    format_key_value(thermal.max_temperature), format_key_value(high)),
        "must be > thermal.billet_temperature and thermal.tool_temperature (and "
        "thermal.ambient_temperature when thermal.free_surface_transfer > 0)",
        {"thermal.billet_temperature", "thermal.tool_temperature", "thermal.ambient_temperature"});
  const Real offset = physics::absolute_offset(thermal.unit);
  if (low + offset <= 0)
    die_error(
        "thermal.temperature_unit",
        fmt::format("the lowest prescribed temperature {} is not above absolute zero",
                    format_key_value(low)),
        "temperatures are in °C with \"celsius\" (T + 273.15 > 0), in K with \"kelvin\"",
        {"thermal.billet_temperature", "thermal.tool_temperature", "thermal.ambient_temperature"});
  const physics::FlowLaw law = case_.material.selected();
  if (!law.is_temperature_dependent()) return;
  if (const auto violation = physics::check_flow_law_over(law, low, thermal.max_temperature))
    die_error("thermal.max_temperature",
              "the flow law violates condition (2.11) on the run's temperature range [" +
                  format_key_value(low) + ", " + format_key_value(thermal.max_temperature) +
                  "]: " + *violation,
              "choose parameters with σ_p increasing and σ_p′ ≤ σ_p/ε̄̇ at every temperature "
              "(hensel_spittel: 0 < m3 + m8 T ≤ 1), or a lower thermal.max_temperature",
              {"material.law", "material.hs_m3", "material.hs_m8", "material.st_n",
               "thermal.billet_temperature", "thermal.tool_temperature"});
  // The stages hot forming does not compose with (solvers/stage_table.hpp).
  check_stages("thermal.enabled");
}

/// The first row of the outer loops' composition table (solvers/stage_table.hpp) that
/// refuses this case and belongs to the stage switched on by `stage_key`.
void CaseBuilder::check_stages(const std::string& stage_key) const {
  const auto refusal = solvers::refused_composition(stage_set(case_));
  if (refusal && refusal->stage_key == stage_key)
    die_error(refusal->key, refusal->message, refusal->hint, {refusal->stage_key});
}

/// Adaptivity (docs/error-estimation.md) remeshes the plane channel with Gmsh and
/// needs the load's error indicators: what it cannot serve is refused here.
void CaseBuilder::check_adapt() const {
  if (!case_.adapt.enabled()) return;
  const std::initializer_list<std::string> switch_key = {"adapt.target_error"};
  const std::string off = "set adapt.target_error = 0 (no adaptivity)";
#if !FORMFLOW_WITH_GMSH
  die_error("adapt.target_error",
            "needs Gmsh to remesh, and this formflow was built without it "
            "(FORMFLOW_WITH_GMSH=OFF)",
            off + ", or rebuild with libgmsh-dev installed");
#endif
  if (case_.mesh.dimension == 3)
    die_error("geometry.dimension",
              "adaptivity is not done for the solid channel yet (only plane and axisymmetric)",
              off + ", or geometry.dimension = 2", switch_key);
  if (case_.mesh.source == mesh::MeshSource::File)
    die_error("mesh.source", "a mesh from a file has no channel geometry for the cycles to remesh",
              off + ", or mesh.source = \"structured\" or \"gmsh\"", switch_key);
  // The stages adaptivity does not compose with: the table the run plan reads too.
  check_stages("adapt.target_error");
}

/// A mesh that cannot fit in this machine's memory is refused now, not by the allocator.
void CaseBuilder::check_mesh_memory() const {
  if (const auto problem = mesh_memory_problem(case_, machine_memory_bytes()))
    die_error("mesh.size", problem->message, problem->hint,
              {"mesh.element", "geometry.container_length", "geometry.entry_half_height",
               "geometry.exit_half_height", "geometry.exit_length", "geometry.land_length",
               "geometry.die", "geometry.die_angle", "geometry.die_radius", "geometry.die_profile",
               "verification.solution"});
}

/// The die face must join the entry and exit heights monotonically.
void CaseBuilder::check_die() const {
  const mesh::ChannelGeometry& geometry = case_.mesh.geometry;
  const Real drop = geometry.entry_half_height - geometry.exit_half_height;
  if (geometry.die == mesh::DieShape::Square && geometry.land_length > 0 &&
      !(geometry.land_length < geometry.exit_length))
    die_error("geometry.land_length",
              fmt::format("value {} does not leave a free exit: geometry.exit_length = {}",
                          format_key_value(geometry.land_length),
                          format_key_value(geometry.exit_length)),
              "the square die's land is part of the exit: make it shorter than exit_length",
              {"geometry.exit_length", "geometry.die"});
  if (geometry.die == mesh::DieShape::Arc && geometry.die_radius < drop)
    die_error("geometry.die_radius",
              fmt::format("value {} cannot reach from the exit half height {} to the entry "
                          "half height {}",
                          format_key_value(geometry.die_radius),
                          format_key_value(geometry.exit_half_height),
                          format_key_value(geometry.entry_half_height)),
              fmt::format("die_radius must be ≥ entry_half_height − exit_half_height = {}",
                          format_key_value(drop)),
              {"geometry.die", "geometry.entry_half_height", "geometry.exit_half_height"});
  if (geometry.die != mesh::DieShape::Polyline) return;
  const std::string name = "geometry.die_profile";
  const auto& points = geometry.die_profile;
  const std::string shape = "[[0, H_in], ..., [x_n, H_out]] with x increasing, y non-increasing";
  const std::initializer_list<std::string> profile_related = {
      "geometry.die", "geometry.entry_half_height", "geometry.exit_half_height"};
  if (points.size() < 2)
    die_error(name, "a polyline die needs at least two points", shape, profile_related);
  for (std::size_t k = 0; k < points.size(); ++k)
    if (std::abs(points[k][0]) > 1e6 || std::abs(points[k][1]) > 1e6)
      die_error(name,
                fmt::format("point {} ([{}, {}]) is farther than 1e6 from the die entry", k + 1,
                            points[k][0], points[k][1]),
                "coordinates are lengths: |x|, |y| ≤ 1e6, like every length");
  if (points.front()[0] != 0 || points.front()[1] != geometry.entry_half_height)
    die_error(name,
              fmt::format("the first point [{}, {}] is not the die entry [0, {}]",
                          points.front()[0], points.front()[1], geometry.entry_half_height),
              "start the profile at x = 0 (the die entry) and y = geometry.entry_half_height",
              profile_related);
  if (points.back()[1] != geometry.exit_half_height)
    die_error(name,
              fmt::format("the last point ends at y = {}, not at the exit half height {}",
                          points.back()[1], geometry.exit_half_height),
              "end the profile at y = geometry.exit_half_height", profile_related);
  for (std::size_t k = 1; k < points.size(); ++k) {
    if (!(points[k][0] > points[k - 1][0]))
      die_error(name,
                fmt::format("x is not increasing at point {} ([{}, {}])", k + 1, points[k][0],
                            points[k][1]),
                shape);
    if (points[k][1] > points[k - 1][1])
      die_error(name,
                fmt::format("y increases at point {} ([{}, {}]): the die must not "
                            "widen",
                            k + 1, points[k][0], points[k][1]),
                shape);
  }
}

void CaseBuilder::check_mesh_fits() const {
  const std::string size_name = "mesh.size";
  const Real size = case_.mesh.size;
  // The square die is two blocks of square cells; the mapped dies need only
  // the lengths the user sets to fit (the die face gets ⌈length/size⌉ columns).
  std::vector<std::string> names = {"geometry.container_length", "geometry.entry_half_height",
                                    "geometry.exit_length"};
  if (case_.mesh.geometry.die == mesh::DieShape::Square)
    names.push_back("geometry.exit_half_height");
  if (case_.mesh.geometry.land_length > 0) names.push_back("geometry.land_length");
  for (const std::string& length_name : names) {
    const Real length = real_value(length_name);
    if (mesh::cells_along(length, size) > 0) continue;
    const std::string hint = fitting_sizes_hint(case_.mesh.geometry, size);
    if (origin(length_name).order > origin(size_name).order) {
      const Origin where = origin(length_name);
      throw InputError(where.file, where.line, length_name,
                       fmt::format("value {} is not a multiple of mesh.size = {}: {:.6g} cells",
                                   format_key_value(length), format_key_value(size), length / size),
                       "use a multiple of mesh.size; or change mesh.size: " + hint);
    }
    const Origin where = origin(size_name);
    throw InputError(where.file, where.line, size_name,
                     fmt::format("value {} does not fit {} = {}: {:.6g} cells",
                                 format_key_value(size), length_name, format_key_value(length),
                                 length / size),
                     hint);
  }
}

} // namespace formflow::io
