// SPDX-License-Identifier: MIT
// The case-key table (names, types, defaults, ranges, units, docs) and its lookups.
#include "formflow/io/case_keys.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <type_traits>
#include <utility>

namespace formflow::io {

namespace {

using physics::ProcessType;
using physics::RamCondition;
using physics::ViscousStrain;

/// Fluent description of one key, read like a row of the table; converts to its CaseKey.
struct KeySpec {
  CaseKey key;

  KeySpec(std::string_view name, KeyType type, KeyValue default_value) {
    key.name = name;
    key.type = type;
    key.default_value = std::move(default_value);
    key.unit = "—";
  }
  KeySpec& above(Real value) { return lower({value, false}); }
  KeySpec& at_least(Real value) { return lower({value, true}); }
  KeySpec& below(Real value) { return upper({value, false}); }
  KeySpec& at_most(Real value) { return upper({value, true}); }
  KeySpec& unit(std::string_view text) { return assign(key.unit, text); }
  KeySpec& constraint(std::string_view text) { return assign(key.constraint, text); }
  KeySpec& doc(std::string_view text) { return assign(key.doc, text); }
  operator CaseKey() const { return key; }  // NOLINT: implicit, so a table is a braced list

 private:
  KeySpec& lower(Bound bound) { return key.lower = bound, *this; }
  KeySpec& upper(Bound bound) { return key.upper = bound, *this; }
  KeySpec& assign(std::string_view& field, std::string_view text) { return field = text, *this; }
};

// `access` is a generic lambda returning a reference to the field, so the same
// accessor serves `set` (Case&) and `get` (const Case&).
template <class Access>
KeySpec real_key(std::string_view name, Real default_value, Access access) {
  KeySpec spec(name, KeyType::Real, default_value);
  spec.key.set = [access](Case& case_, const KeyValue& value) {
    access(case_) = std::get<Real>(value);
  };
  spec.key.get = [access](const Case& case_) -> KeyValue { return access(case_); };
  return spec;
}

template <class Access>
KeySpec integer_key(std::string_view name, std::int64_t default_value, Access access) {
  KeySpec spec(name, KeyType::Integer, default_value);
  spec.key.set = [access](Case& case_, const KeyValue& value) {
    access(case_) = static_cast<int>(std::get<std::int64_t>(value));
  };
  spec.key.get = [access](const Case& case_) -> KeyValue { return std::int64_t{access(case_)}; };
  return spec;
}

/// The type of the Case field that `access` refers to.
template <class Access>
using field_type = std::remove_cvref_t<decltype(std::declval<Access>()(std::declval<Case&>()))>;

template <class Access>
KeySpec enum_key(std::string_view name, std::string_view default_value,
                 std::vector<std::pair<std::string_view, field_type<Access>>> mapping,
                 Access access) {
  KeySpec spec(name, KeyType::Enum, std::string(default_value));
  for (const auto& [text, enumerator] : mapping) spec.key.choices.push_back(text);
  spec.key.set = [access, mapping](Case& case_, const KeyValue& value) {
    for (const auto& [text, enumerator] : mapping)
      if (text == std::get<std::string>(value)) access(case_) = enumerator;
  };
  spec.key.get = [access, mapping](const Case& case_) -> KeyValue {
    for (const auto& [text, enumerator] : mapping)
      if (enumerator == access(case_)) return std::string(text);
    return std::string("?");
  };
  return spec;
}

bool contains(const std::vector<std::string>& list, std::string_view entry) {
  return std::find(list.begin(), list.end(), entry) != list.end();
}

KeySpec friction_parts_key() {
  KeySpec spec("friction.on", KeyType::StringList, std::vector<std::string>{"container", "die"});
  spec.key.choices = {"container", "die"};
  spec.key.set = [](Case& case_, const KeyValue& value) {
    const auto& parts = std::get<std::vector<std::string>>(value);
    case_.friction.on_container = contains(parts, "container");
    case_.friction.on_die = contains(parts, "die");
  };
  spec.key.get = [](const Case& case_) -> KeyValue {
    std::vector<std::string> parts;
    if (case_.friction.on_container) parts.emplace_back("container");
    if (case_.friction.on_die) parts.emplace_back("die");
    return parts;
  };
  return spec.doc("parts of the contact boundary Γ3 with friction: the container wall y = H_in "
                  "and/or the die (its face and its land); [] = frictionless everywhere");
}

KeySpec die_shape_key() {
  using mesh::DieShape;
  return enum_key("geometry.die", "square",
                  {{"square", DieShape::Square},
                   {"wedge", DieShape::Wedge},
                   {"arc", DieShape::Arc},
                   {"polyline", DieShape::Polyline}},
                  [](auto& c) -> auto& { return c.geometry.die; })
      .doc("die shape: square (a step at x = L_c, the benchmark), wedge (geometry.die_angle), "
           "arc (geometry.die_radius) or polyline (geometry.die_profile)");
}

KeySpec die_profile_key() {
  KeySpec spec("geometry.die_profile", KeyType::PointList, KeyPoints{});
  spec.key.set = [](Case& case_, const KeyValue& value) {
    case_.geometry.die_profile = std::get<KeyPoints>(value);
  };
  spec.key.get = [](const Case& case_) -> KeyValue { return case_.geometry.die_profile; };
  return spec.unit("length")
      .constraint("polyline die: starts at [0, H_in], ends at y = H_out, x increasing, y "
                  "non-increasing")
      .doc("polyline die face as [x, y] points, x measured from the die entry x = L_c");
}

KeySpec mesh_file_key() {
  KeySpec spec("mesh.file", KeyType::Text, std::string());
  spec.key.set = [](Case& case_, const KeyValue& value) {
    case_.mesh_file = std::get<std::string>(value);
  };
  spec.key.get = [](const Case& case_) -> KeyValue { return case_.mesh_file; };
  return spec.constraint("required when mesh.source = \"file\"; only then")
      .doc("the Gmsh mesh (.msh 4.1 or 2.2, ASCII or binary) of quad-4 (Q1) or quad-9 (Q2) "
           "cells; a relative path is taken from the case file's directory");
}

KeySpec mesh_boundaries_key() {
  KeySpec spec("mesh.boundaries", KeyType::NameMap, NameMap{});
  for (int k = 0; k < mesh::n_boundary_labels; ++k)
    spec.key.choices.push_back(mesh::label_name(static_cast<mesh::BoundaryLabel>(k)));
  spec.key.set = [](Case& case_, const KeyValue& value) {
    case_.mesh_boundaries = std::get<NameMap>(value);
  };
  spec.key.get = [](const Case& case_) -> KeyValue { return case_.mesh_boundaries; };
  return spec.constraint("only with mesh.source = \"file\"")
      .doc("physical curve name in mesh.file → boundary part, as a table `[mesh.boundaries]` "
           "with lines `ram = \"rear\"`; several names may share a part; every boundary "
           "facet needs one; {} = the physical names are the part names");
}

std::vector<CaseKey> process_and_geometry_keys() {
  return {
      enum_key("process.type", "extrusion",
               {{"extrusion", ProcessType::Extrusion}, {"drawing", ProcessType::Drawing}},
               [](auto& c) -> auto& { return c.process.type; })
          .doc("extrusion: the ram pushes the rear end Γ1 with the process speed; "
               "drawing: the front end Γ5 is pulled"),
      real_key("process.speed", 1.0, [](auto& c) -> auto& { return c.process.speed; })
          .above(0)
          .unit("length/time")
          .doc("prescribed normal speed u⁰ on Γ1 (extrusion) or Γ5 (drawing)"),
      enum_key("process.ram", "sliding",
               {{"sliding", RamCondition::Sliding}, {"sticking", RamCondition::Sticking}},
               [](auto& c) -> auto& { return c.process.ram; })
          .doc("ram condition on Γ1 for extrusion: sliding = σ_T = 0, u_y free (the paper's); "
               "sticking = u_y = 0 as well"),
      real_key("geometry.container_length", 10.0,
               [](auto& c) -> auto& { return c.geometry.container_length; })
          .above(0)
          .constraint("a multiple of mesh.size")
          .unit("length")
          .doc("L_c: the container part is x ∈ [0, L_c]"),
      real_key("geometry.entry_half_height", 10.0,
               [](auto& c) -> auto& { return c.geometry.entry_half_height; })
          .above(0)
          .constraint("> geometry.exit_half_height; a multiple of mesh.size")
          .unit("length")
          .doc("H_in: half thickness of the billet in the container"),
      real_key("geometry.exit_half_height", 5.0,
               [](auto& c) -> auto& { return c.geometry.exit_half_height; })
          .above(0)
          .constraint("< geometry.entry_half_height; a multiple of mesh.size")
          .unit("length")
          .doc("H_out: half thickness of the product after the die"),
      real_key("geometry.exit_length", 10.0,
               [](auto& c) -> auto& { return c.geometry.exit_length; })
          .above(0)
          .constraint("a multiple of mesh.size")
          .unit("length")
          .doc("L_e: the exit part is x ∈ [L_c, L_c + L_e]"),
      die_shape_key(),
      real_key("geometry.die_angle", 15.0, [](auto& c) -> auto& { return c.geometry.die_angle; })
          .above(0)
          .below(90)
          .unit("degrees")
          .doc("wedge (conical) die semi-angle α; the face runs from (L_c, H_in) to "
               "(L_c + (H_in − H_out)/tan α, H_out)"),
      real_key("geometry.die_radius", 10.0, [](auto& c) -> auto& { return c.geometry.die_radius; })
          .above(0)
          .constraint("≥ geometry.entry_half_height − geometry.exit_half_height")
          .unit("length")
          .doc("arc die: radius of the circular face, tangent to the exit direction at the die "
               "exit"),
      die_profile_key(),
      real_key("geometry.land_length", 0.0, [](auto& c) -> auto& { return c.geometry.land_length; })
          .at_least(0)
          .constraint("a multiple of mesh.size; < geometry.exit_length for the square die")
          .unit("length")
          .doc("die land: a straight contact part y = H_out after the die face (Γ3; it counts "
               "as \"die\" for friction.on)"),
      enum_key("geometry.symmetry", "plane",
               {{"plane", physics::Symmetry::Plane},
                {"axisymmetric", physics::Symmetry::Axisymmetric}},
               [](auto& c) -> auto& { return c.symmetry; })
          .doc("plane strain, or axial symmetry about y = 0 (y = r; rod and wire): pressures "
               "are forces over πR²"),
  };
}

std::vector<CaseKey> discretisation_keys() {
  return {
      enum_key("mesh.element", "Q2", {{"Q1", fem::ElementKind::Q1}, {"Q2", fem::ElementKind::Q2}},
               [](auto& c) -> auto& { return c.element; })
          .doc("velocity element: Q1 (4-node bilinear) or Q2 (9-node biquadratic)"),
      real_key("mesh.size", 1.0, [](auto& c) -> auto& { return c.mesh_size; })
          .above(0)
          .constraint("divides every geometry length when mesh.source = \"structured\"; the "
                      "mesh's estimated memory fits in this machine's (docs/benchmarks.md)")
          .unit("length")
          .doc("side of the uniform square cells (mesh I: 10/6, mesh II: 1); the target "
               "element size for mesh.source = \"gmsh\"; unused for \"file\""),
      enum_key("mesh.source", "structured",
               {{"structured", mesh::MeshSource::Structured},
                {"gmsh", mesh::MeshSource::Gmsh},
                {"file", mesh::MeshSource::File}},
               [](auto& c) -> auto& { return c.mesh_source; })
          .doc("structured: uniform square cells; gmsh: the same geometry meshed by Gmsh with "
               "recombined quadrilaterals of size mesh.size; file: the mesh in mesh.file"),
      mesh_file_key(),
      mesh_boundaries_key(),
      integer_key("integration.volumetric", 2,
                  [](auto& c) -> auto& { return c.volumetric_points; })
          .at_least(1)
          .at_most(3)
          .unit("points")
          .doc("Gauss points per direction of the volumetric penalty term (complete: 2 for "
               "Q1, 3 for Q2; reduced: 1, or 2 for Q2); the viscous term always uses the "
               "complete rule"),
      enum_key("formulation.viscous_strain", "full",
               {{"full", ViscousStrain::Full}, {"deviatoric", ViscousStrain::Deviatoric}},
               [](auto& c) -> auto& { return c.viscous_strain; })
          .doc("strain rate in the viscous a-form: the full ε̇ (paper eq. 3.3) or its deviator "
               "ė (the same as d → 0)"),
      enum_key("formulation.type", "penalty",
               {{"penalty", assembly::FormulationType::Penalty},
                {"mixed", assembly::FormulationType::Mixed}},
               [](auto& c) -> auto& { return c.formulation.type; })
          .doc("penalty: problem (3.9), σ_H = ε̇_V/d at the volumetric points; mixed: problem "
               "(3.7), σ_H in formulation.pressure, condensed cell by cell (docs/mixed.md)"),
      enum_key("formulation.pressure", "P1disc",
               {{"P0", fem::PressureSpace::P0},
                {"P1disc", fem::PressureSpace::P1disc},
                {"Q1", fem::PressureSpace::Q1}},
               [](auto& c) -> auto& { return c.formulation.pressure; })
          .constraint("mixed with Q1 velocity: P0 only; Q1 (Taylor–Hood) needs Q2 velocity and "
                      "regularized friction")
          .doc("pressure space of the mixed formulation: P0 (cell constant), P1disc (cell linear, "
               "discontinuous), both condensed cell by cell, or Q1 (continuous bilinear on the "
               "vertices, Taylor–Hood: global saddle-point solve with UMFPACK)"),
      real_key("formulation.augmentation", 1e3,
               [](auto& c) -> auto& { return c.formulation.augmentation; })
          .above(0)
          .at_most(1e8)
          .doc("ρ of the augmented-Lagrangian term for d = 0: r = ρ × the cell's mean secant "
               "viscosity; larger = fewer Uzawa steps, worse conditioning"),
      real_key("formulation.contact_augmentation", 1e6,
               [](auto& c) -> auto& { return c.formulation.contact_augmentation; })
          .above(0)
          .at_most(1e12)
          .unit("stress·time/length")
          .doc("r_N of the augmented-Lagrangian contact term for dN = 0 (plays the role of 1/d_N)"),
      real_key("formulation.uzawa_tolerance", 1e-8,
               [](auto& c) -> auto& { return c.formulation.uzawa_tolerance; })
          .above(0)
          .below(1)
          .doc("Uzawa steps (d = 0 or dN = 0) end when the multipliers change by less than "
               "this, relative, or stop changing at a round-off floor below its square root"),
      integer_key("formulation.uzawa_max_steps", 50,
                  [](auto& c) -> auto& { return c.formulation.uzawa_max_steps; })
          .at_least(1)
          .at_most(10000)
          .doc("Uzawa steps per secant iteration at most (each is one solve with the same "
               "factorisation)"),
  };
}

std::vector<CaseKey> material_keys() {
  using physics::FlowLawKind;
  return {
      enum_key("material.law", "piecewise_power",
               {{"piecewise_power", FlowLawKind::PiecewisePower},
                {"norton_hoff", FlowLawKind::NortonHoff},
                {"hensel_spittel", FlowLawKind::HenselSpittel},
                {"perfectly_plastic", FlowLawKind::PerfectlyPlastic}},
               [](auto& c) -> auto& { return c.material.kind; })
          .constraint("the law must satisfy condition (2.11) (checked at load time)")
          .doc("σ_p on [rate1, rate2], linear through the origin outside: piecewise_power "
               "A ε̄̇^α (paper eq. 5.4); norton_hoff √3 K (√3 ε̄̇)^m; hensel_spittel "
               "A e^(m1 T) ε^m2 e^(m4/ε) ε̄̇^(m3 + m8 T); perfectly_plastic σ0"),
      real_key("material.A", 1.7320508075688772, [](auto& c) -> auto& { return c.material.A; })
          .above(0)
          .unit("stress·time^α")
          .doc("A of σ_p = A ε̄̇^α (paper eq. 5.4); √3 gives the shear yield k ≈ 1"),
      real_key("material.alpha", 1e-3, [](auto& c) -> auto& { return c.material.alpha; })
          .above(0)
          .at_most(1)
          .doc("strain-rate sensitivity α"),
      real_key("material.rate1", 1e-3, [](auto& c) -> auto& { return c.material.rate1; })
          .above(0)
          .constraint("< material.rate2")
          .unit("1/time")
          .doc("ε̄̇₁: below it σ_p is continued linearly through the origin"),
      real_key("material.rate2", 1e3, [](auto& c) -> auto& { return c.material.rate2; })
          .above(0)
          .constraint("> material.rate1")
          .unit("1/time")
          .doc("ε̄̇₂: above it σ_p is continued linearly through the origin"),
      real_key("material.K", 1.0, [](auto& c) -> auto& { return c.material.K; })
          .above(0)
          .unit("stress·time^m")
          .doc("norton_hoff: consistency K of s = 2K(√3 ε̄̇)^(m−1) ė"),
      real_key("material.m", 0.1, [](auto& c) -> auto& { return c.material.m; })
          .above(0)
          .at_most(1)
          .doc("norton_hoff: strain-rate sensitivity m (1 = linear viscous)"),
      real_key("material.sigma0", 1.7320508075688772,
               [](auto& c) -> auto& { return c.material.sigma0; })
          .above(0)
          .unit("stress")
          .doc("perfectly_plastic: the rate-independent yield stress σ0"),
      real_key("material.hs_A", 1.7320508075688772, [](auto& c) -> auto& { return c.material.hs_A; })
          .above(0)
          .unit("stress·time^(m3+m8 T)")
          .doc("hensel_spittel: A"),
      real_key("material.hs_m1", 0.0, [](auto& c) -> auto& { return c.material.hs_m1; })
          .unit("1/temperature")
          .doc("hensel_spittel: temperature factor e^(m1 T)"),
      real_key("material.hs_m2", 0.0, [](auto& c) -> auto& { return c.material.hs_m2; })
          .doc("hensel_spittel: strain-hardening exponent of ε^m2"),
      real_key("material.hs_m3", 0.1, [](auto& c) -> auto& { return c.material.hs_m3; })
          .constraint("0 < m3 + m8 T ≤ 1")
          .doc("hensel_spittel: strain-rate exponent m3 of ε̄̇^(m3 + m8 T)"),
      real_key("material.hs_m4", 0.0, [](auto& c) -> auto& { return c.material.hs_m4; })
          .doc("hensel_spittel: softening term e^(m4/ε)"),
      real_key("material.hs_m8", 0.0, [](auto& c) -> auto& { return c.material.hs_m8; })
          .unit("1/temperature")
          .constraint("0 < m3 + m8 T ≤ 1")
          .doc("hensel_spittel: temperature dependence m8 T of the strain-rate exponent"),
      real_key("material.temperature", 0.0,
               [](auto& c) -> auto& { return c.material.temperature; })
          .unit("temperature")
          .doc("hensel_spittel: the (uniform, constant) temperature T of the isothermal form"),
      real_key("material.strain", 1.0, [](auto& c) -> auto& { return c.material.strain; })
          .above(0)
          .doc("hensel_spittel: the reference equivalent strain ε at which the law is taken "
               "(the steady model carries no strain history)"),
  };
}

std::vector<CaseKey> contact_keys() {
  return {
      enum_key("contact.normals", "faces",
               {{"faces", assembly::ContactNormals::Faces}, {"nodes", assembly::ContactNormals::Nodes}},
               [](auto& c) -> auto& { return c.contact.normals; })
          .doc("normal of the Γ3 penalty and friction: faces = each face's own normal at its "
               "Gauss points (the paper); nodes = one length-weighted mean normal per node, "
               "penalty and friction lumped on the nodes (docs/validation.md, contact normals)"),
      real_key("contact.corner_angle", 60.0, [](auto& c) -> auto& { return c.contact.corner_angle; })
          .above(0)
          .below(180)
          .unit("degree")
          .doc("contact.normals = \"nodes\" only: where Γ3 faces meet at a larger turn of the "
               "normal, the node keeps both face normals and cannot move (a dead-metal corner)"),
      real_key("friction.mu", 0.0, [](auto& c) -> auto& { return c.friction.mu; })
          .at_least(0)
          .doc("Coulomb coefficient μ_f of the nonlocal friction law τ_f = μ_f σ̄_N"),
      real_key("friction.radius", 0.0, [](auto& c) -> auto& { return c.friction.radius; })
          .at_least(0)
          .unit("length")
          .doc("mollifier radius h of the mean contact pressure σ̄_N; 0 = local pressure"),
      friction_parts_key(),
      enum_key("friction.regularization", "regularized",
               {{"regularized", physics::FrictionRegularization::Regularized},
                {"none", physics::FrictionRegularization::None}},
               [](auto& c) -> auto& { return c.friction.regularization; })
          .doc("regularized: the paper's |u_T| → √(|u_T|² + d_T²) with penalty.dT (eq. 3.14); "
               "none: exact Coulomb law by an augmented Lagrangian on the friction traction "
               "(docs/friction.md)"),
      real_key("friction.augmentation", 1.0,
               [](auto& c) -> auto& { return c.friction.augmentation; })
          .above(0)
          .at_most(1e6)
          .unit("1/penalty.dN")
          .doc("exact friction with solver.method = \"secant\" (or a mixed formulation): "
               "augmentation r = value/d_N of λ_T = proj(λ_T + r u_T); "
               "any value converges, larger takes fewer multiplier updates"),
      real_key("friction.newton_augmentation", 100.0,
               [](auto& c) -> auto& { return c.friction.newton_augmentation; })
          .above(0)
          .at_most(1e6)
          .unit("1/penalty.dN")
          .doc("exact friction solved by Newton (solver.method = \"newton\"; penalty, or mixed "
               "with a condensed pressure): r = value/d_N; Newton's tangent carries the stick "
               "penalty, and a stiffer one settles the multipliers in fewer updates "
               "(docs/friction.md)"),
      real_key("penalty.d", 1e-3, [](auto& c) -> auto& { return c.penalty.d; })
          .at_least(0)
          .constraint("0 (exact incompressibility) only with formulation.type = \"mixed\"")
          .unit("1/(stress·time)")
          .doc("incompressibility penalty: σ_H = ε̇_V/d (paper eq. 3.8); 0 = exact constraint "
               "(Uzawa steps)"),
      real_key("penalty.dN", 1e-6, [](auto& c) -> auto& { return c.penalty.d_n; })
          .at_least(0)
          .unit("length/(stress·time)")
          .doc("contact penalty d_N: σ_N = −u_N/d_N on Γ3 (paper eq. 3.8); 0 = exact u_N = 0 "
               "(Uzawa steps)"),
      real_key("penalty.dT", 1e-6, [](auto& c) -> auto& { return c.friction.d_t; })
          .above(0)
          .unit("length/time")
          .doc("friction regularisation d_T: |u_T| → √(|u_T|² + d_T²) (paper eq. 3.14)"),
  };
}

std::vector<CaseKey> solver_keys() {
  return {
      real_key("solver.tolerance", 1e-4, [](auto& c) -> auto& { return c.solver.tolerance; })
          .above(0)
          .below(1)
          .doc("δ: the secant iteration stops when ‖uⁿ⁺¹ − uⁿ‖/‖uⁿ⁺¹‖ < δ"),
      integer_key("solver.max_iterations", 500,
                  [](auto& c) -> auto& { return c.solver.max_iterations; })
          .at_least(1)
          .at_most(1e9)
          .doc("iteration limit; reaching it is a result (not converged, exit 3), not an error"),
      real_key("solver.initial_rate", 1.0, [](auto& c) -> auto& { return c.solver.initial_rate; })
          .above(0)
          .unit("1/time")
          .doc("ε̄̇ whose secant viscosity σ_p(ε̄̇)/ε̄̇ gives the constant-viscosity first "
               "iterate"),
      enum_key("solver.method", "newton",
               {{"newton", solvers::NonlinearMethod::Newton},
                {"secant", solvers::NonlinearMethod::Secant}},
               [](auto& c) -> auto& { return c.solver.method; })
          .doc("newton: Newton–Raphson with the consistent tangent and a line search; "
               "secant: the paper's secant-modulus (Kachanov) iteration (eq. 5.2–5.3)"),
      real_key("solver.newton_start", 0.5, [](auto& c) -> auto& { return c.solver.newton_start; })
          .above(0)
          .doc("newton only: secant steps are taken while the relative change exceeds this "
               "(safeguard far from the solution)"),
      integer_key("solver.coarse_levels", 2,
                  [](auto& c) -> auto& { return c.solver.coarse_levels; })
          .at_least(0)
          .at_most(6)
          .doc("newton only: first solve on this many coarser meshes (mesh.size times 2^L, ..., 2), "
               "each started from the previous one, and start from the last; 0: from the "
               "constant-viscosity solution; levels the geometry does not admit (or a mesh from a "
               "file) are skipped, and summary.json coarse_mesh_sizes lists those used"),
  };
}

std::vector<CaseKey> verification_keys() {
  using physics::ManufacturedSolution;
  return {
      enum_key("verification.solution", "none",
               {{"none", ManufacturedSolution::None},
                {"smooth", ManufacturedSolution::Smooth},
                {"extension", ManufacturedSolution::Extension}},
               [](auto& c) -> auto& { return c.manufactured; })
          .constraint("not none: mesh.size divides 1")
          .doc("manufactured solution on the unit square with all-Dirichlet boundary and a body "
               "force (process and geometry, also geometry.symmetry, are then ignored): smooth = "
               "extension + vortex, "
               "extension = u = (x, −y) (patch test); none = the forming case"),
      enum_key("verification.distortion", "none",
               {{"none", mesh::Distortion::None},
                {"smooth", mesh::Distortion::Smooth},
                {"random", mesh::Distortion::Random}},
               [](auto& c) -> auto& { return c.distortion.kind; })
          .doc("interior nodes of the verification box mesh: uniform squares, a fixed smooth map, "
               "or random offsets (non-affine cells)"),
      real_key("verification.amplitude", 0.1,
               [](auto& c) -> auto& { return c.distortion.amplitude; })
          .at_least(0)
          .below(0.25)
          .constraint("≤ 0.1 with distortion = \"smooth\" (the map stays one-to-one)")
          .doc("distortion size: smooth = displacement amplitude / box side; random = "
               "largest offset / cell side"),
      integer_key("verification.seed", 1, [](auto& c) -> auto& { return c.distortion.seed; })
          .at_least(0)
          .at_most(2147483647)
          .doc("seed of the random distortion (each mesh of a ladder draws its own offsets)"),
  };
}

/// The sections' keys in case_sections() order (the reference and JSON follow it).
std::vector<CaseKey> make_table() {
  std::vector<CaseKey> table;
  for (auto part : {process_and_geometry_keys(), discretisation_keys(), material_keys(),
                    contact_keys(), solver_keys(), verification_keys()})
    for (CaseKey& key : part) table.push_back(std::move(key));
  return table;
}

char lower_case(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

/// Levenshtein distance, ignoring letter case (so `penalty.dn` is next to `penalty.dN`).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution =
          diagonal + (lower_case(a[i - 1]) == lower_case(b[j - 1]) ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

std::optional<KeyProblem> check_number(const CaseKey& key, Real value, const std::string& text) {
  const bool below_lower = key.lower.value && (key.lower.inclusive ? value < *key.lower.value
                                                                   : value <= *key.lower.value);
  const bool above_upper = key.upper.value && (key.upper.inclusive ? value > *key.upper.value
                                                                   : value >= *key.upper.value);
  if (!std::isfinite(value))
    return KeyProblem{"value " + text + " is not finite", "must be " + valid_values_text(key)};
  if (below_lower || above_upper)
    return KeyProblem{"value " + text + " is out of range", "must be " + valid_values_text(key)};
  return std::nullopt;
}

std::string quoted_choices(const CaseKey& key) {
  std::string text;
  for (std::string_view choice : key.choices)
    text += (text.empty() ? "\"" : ", \"") + std::string(choice) + "\"";
  return text;
}

std::optional<KeyProblem> check_list(const CaseKey& key, const std::vector<std::string>& list) {
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (std::find(key.choices.begin(), key.choices.end(), list[i]) == key.choices.end())
      return KeyProblem{"invalid entry \"" + list[i] + "\"",
                        "valid entries: " + quoted_choices(key)};
    if (std::find(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(i), list[i]) !=
        list.begin() + static_cast<std::ptrdiff_t>(i))
      return KeyProblem{"duplicate entry \"" + list[i] + "\"",
                        "list each of " + quoted_choices(key) + " at most once"};
  }
  return std::nullopt;
}

}  // namespace

const std::vector<CaseSection>& case_sections() {
  static const std::vector<CaseSection> sections = {
      {"process", "What drives the flow (SPEC §1)."},
      {"geometry", "The half model of the die channel (SPEC §4); lengths are dimensionless."},
      {"mesh", "Where the cells come from (a uniform grid, Gmsh, or a .msh file) and their "
               "element kind."},
      {"integration", "Quadrature of the volumetric penalty term (selective integration, SPEC §3)."},
      {"formulation", "Which form of the a-term is assembled, and penalty or mixed (pressure) form of the constraints (SPEC §2, docs/mixed.md)."},
      {"material", "Flow law σ_p(ε̄̇) on [rate1, rate2], linear through the origin outside "
                   "(paper eq. 5.4 by default; material.law picks another)."},
      {"contact", "How the contact boundary Γ3 is discretised: the normal of the penalty and "
                  "of the friction law."},
      {"friction", "Nonlocal Coulomb friction on Γ3: regularised (paper eq. 3.14–3.15) or "
                   "exact."},
      {"penalty", "Penalty and regularisation parameters (paper eq. 3.8, 3.14)."},
      {"solver", "The nonlinear iteration: Newton, or the paper's secant-modulus (Kachanov) "
                 "iteration (eq. 5.2–5.3)."},
      {"verification", "Manufactured solutions for the convergence studies (docs/verification.md)."},
  };
  return sections;
}

const std::vector<CaseKey>& case_keys() {
  static const std::vector<CaseKey> table = make_table();
  return table;
}

const CaseKey* find_case_key(std::string_view name) {
  const auto& table = case_keys();
  const auto found = std::find_if(table.begin(), table.end(),
                                  [name](const CaseKey& key) { return key.name == name; });
  return found == table.end() ? nullptr : &*found;
}

bool is_case_section(std::string_view name) {
  const auto& sections = case_sections();
  return std::any_of(sections.begin(), sections.end(),
                     [name](const CaseSection& section) { return section.name == name; });
}

std::string_view closest_case_key(std::string_view name) {
  const std::string_view section = name.substr(0, name.find('.'));
  const std::string_view leaf =
      name.find('.') == std::string_view::npos ? name : name.substr(name.rfind('.') + 1);
  std::string_view best;
  std::size_t best_score = std::string_view::npos;
  for (const CaseKey& key : case_keys()) {
    // A right leaf in the wrong section (or no section) costs 2: `speed` → `process.speed`.
    const std::size_t leaf_score =
        edit_distance(leaf, key.leaf()) + (section == key.section() ? 0 : 2);
    const std::size_t score = std::min(edit_distance(name, key.name), leaf_score);
    if (score < best_score) {
      best_score = score;
      best = key.name;
    }
  }
  return best;
}

std::string_view closest_case_section(std::string_view name) {
  std::string_view best;
  std::size_t best_score = std::string_view::npos;
  for (const CaseSection& section : case_sections()) {
    const std::size_t score = edit_distance(name, section.name);
    if (score < best_score) {
      best_score = score;
      best = section.name;
    }
  }
  return best;
}

std::optional<KeyProblem> check_key_value(const CaseKey& key, const KeyValue& value) {
  switch (key.type) {
    case KeyType::Real: {
      const Real number = std::get<Real>(value);
      return check_number(key, number, format_key_value(value));
    }
    case KeyType::Integer: {
      const auto number = static_cast<Real>(std::get<std::int64_t>(value));
      return check_number(key, number, format_key_value(value));
    }
    case KeyType::Enum: {
      const std::string& text = std::get<std::string>(value);
      if (std::find(key.choices.begin(), key.choices.end(), text) == key.choices.end())
        return KeyProblem{"invalid value \"" + text + "\"", "valid values: " + quoted_choices(key)};
      return std::nullopt;
    }
    case KeyType::StringList: return check_list(key, std::get<std::vector<std::string>>(value));
    case KeyType::PointList:
      for (const auto& point : std::get<KeyPoints>(value))
        if (!std::isfinite(point[0]) || !std::isfinite(point[1]))
          return KeyProblem{"a point is not finite", "give finite [x, y] pairs"};
      return std::nullopt;
    case KeyType::Text: return std::nullopt;
    case KeyType::NameMap:
      for (const auto& [entry, text] : std::get<NameMap>(value))
        if (std::find(key.choices.begin(), key.choices.end(), text) == key.choices.end())
          return KeyProblem{"invalid value \"" + text + "\" for \"" + entry + "\"",
                            "valid values: " + quoted_choices(key)};
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace formflow::io
