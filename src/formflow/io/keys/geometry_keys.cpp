// SPDX-License-Identifier: MIT
// Case keys of the [geometry] section (The die channel): rows of the table in io/case_keys.cpp.
#include "formflow/io/keys/key_spec.hpp"

namespace formflow::io::keys {

namespace {

KeySpec die_shape_key() {
  using mesh::DieShape;
  return enum_key(
             "geometry.die", "square",
             {{"square", DieShape::Square},
              {"wedge", DieShape::Wedge},
              {"arc", DieShape::Arc},
              {"polyline", DieShape::Polyline}},
             [](auto& c) -> auto& { return c.mesh.geometry.die; })
      .doc("die shape: square (a step at x = L_c, the benchmark), wedge (geometry.die_angle), "
           "arc (geometry.die_radius) or polyline (geometry.die_profile)");
}

/// A die face is a handful of straight pieces; 1000 points follow any curve
/// to well below the mesh size, and keep parsing and meshing fast.
constexpr std::size_t max_die_profile_points = 1000;

KeySpec die_profile_key() {
  KeySpec spec("geometry.die_profile", KeyType::PointList, KeyPoints{});
  spec.key.set = [](Case& case_, const KeyValue& value) {
    case_.mesh.geometry.die_profile = std::get<KeyPoints>(value);
  };
  spec.key.get = [](const Case& case_) -> KeyValue { return case_.mesh.geometry.die_profile; };
  return spec.unit("length")
      .at_most_entries(max_die_profile_points)
      .why("coordinates within 1e6 like every length; a face needs few points, and toml11 "
           "parses long lists slowly")
      .constraint("polyline die: starts at [0, H_in], ends at y = H_out, x increasing, y "
                  "non-increasing, |x|, |y| ≤ 1e6")
      .doc("polyline die face as [x, y] points, x measured from the die entry x = L_c");
}

KeySpec section_key() {
  using mesh::ChannelSection;
  return enum_key(
             "geometry.section", "slab",
             {{"slab", ChannelSection::Slab},
              {"rectangle", ChannelSection::Rectangle},
              {"round", ChannelSection::Round},
              {"profile", ChannelSection::Profile}},
             [](auto& c) -> auto& { return c.mesh.solid.section; })
      .constraint("only with geometry.dimension = 3")
      .doc("solid channel (quarter model, symmetry planes y = 0 and z = 0): slab (the plane "
           "channel extruded over geometry.thickness, u_z = 0 on both z faces: plane strain in "
           "3D), rectangle (half widths in z), round (a round billet, radius = the half heights; "
           "with geometry.die = \"square\" the product is the rectangle exit_half_height × "
           "exit_half_width), or profile (a round billet of geometry.billet_radius through a "
           "flat die whose opening is the outline geometry.profile, with its bearing and the "
           "free extrudate; built by Gmsh in tetrahedra; docs/profiles.md)");
}

/// An outline of a few thousand points follows any profile to well below a cell; a
/// longer one belongs in geometry.profile_file.
constexpr std::size_t max_profile_points = 2000;

KeySpec profile_key() {
  KeySpec spec("geometry.profile", KeyType::PointList, KeyPoints{});
  spec.key.set = [](Case& case_, const KeyValue& value) {
    case_.mesh.solid.profile.outline = std::get<KeyPoints>(value);
  };
  spec.key.get = [](const Case& case_) -> KeyValue { return case_.mesh.solid.profile.outline; };
  return spec.unit("length")
      .at_most_entries(max_profile_points)
      .why("an outline needs few points; toml11 parses long lists slowly (use "
           "geometry.profile_file)")
      .constraint("geometry.section = \"profile\": a closed polygon (not repeating its first "
                  "point) that does not cross or touch itself, inside geometry.billet_radius; "
                  "symmetric about the planes of geometry.profile_symmetry")
      .doc("the product's cross-section as [y, z] points, either way round; edge k runs from "
           "point k to point k + 1 (the last edge back to point 0)");
}

KeySpec profile_file_key() {
  KeySpec spec("geometry.profile_file", KeyType::Text, std::string());
  spec.key.set = [](Case& case_, const KeyValue& value) {
    case_.profile_file = std::get<std::string>(value);
  };
  spec.key.get = [](const Case& case_) -> KeyValue { return case_.profile_file; };
  return spec
      .constraint("geometry.section = \"profile\", instead of geometry.profile; at most 100 000 "
                  "points and 8 MB")
      .doc("a CSV of the outline, one `y, z` per line (a header line, blank lines and `#` "
           "comments allowed); a relative path is taken from the case file's directory");
}

KeySpec bearing_length_key() {
  KeySpec spec("geometry.bearing_length", KeyType::RealList, std::vector<Real>{1.0});
  spec.key.set = [](Case& case_, const KeyValue& value) {
    case_.mesh.solid.profile.bearing_length = std::get<std::vector<Real>>(value);
  };
  spec.key.get = [](const Case& case_) -> KeyValue {
    return case_.mesh.solid.profile.bearing_length;
  };
  return spec.within(1e-6, 1e6)
      .why(length_range)
      .at_most_entries(100000)
      .unit("length")
      .constraint("geometry.section = \"profile\": one value, or one per outline edge; each at "
                  "least a bearing cell (mesh.bearing_size)")
      .doc("the bearing: the die's wall along each outline edge, from the die face x = L_c to "
           "L_c + its length; the free extrudate follows");
}

} // namespace

std::vector<CaseKey> geometry_keys() {
  return {
      real_key(
          "geometry.container_length", 10.0,
          [](auto& c) -> auto& { return c.mesh.geometry.container_length; })
          .within(1e-6, 1e6)
          .why(length_range)
          .constraint("a multiple of mesh.size")
          .unit("length")
          .doc("L_c: the container part is x ∈ [0, L_c]"),
      real_key(
          "geometry.entry_half_height", 10.0,
          [](auto& c) -> auto& { return c.mesh.geometry.entry_half_height; })
          .within(1e-6, 1e6)
          .why(length_range)
          .constraint("> geometry.exit_half_height; a multiple of mesh.size")
          .unit("length")
          .doc("H_in: half thickness of the billet in the container"),
      real_key(
          "geometry.exit_half_height", 5.0,
          [](auto& c) -> auto& { return c.mesh.geometry.exit_half_height; })
          .within(1e-6, 1e6)
          .why(length_range)
          .constraint("< geometry.entry_half_height; a multiple of mesh.size")
          .unit("length")
          .doc("H_out: half thickness of the product after the die"),
      real_key(
          "geometry.exit_length", 10.0,
          [](auto& c) -> auto& { return c.mesh.geometry.exit_length; })
          .within(1e-6, 1e6)
          .why(length_range)
          .constraint("a multiple of mesh.size")
          .unit("length")
          .doc("L_e: the exit part is x ∈ [L_c, L_c + L_e]"),
      die_shape_key(),
      real_key(
          "geometry.die_angle", 15.0, [](auto& c) -> auto& { return c.mesh.geometry.die_angle; })
          .above(0)
          .below(90)
          .unit("degrees")
          .doc("wedge (conical) die semi-angle α; the face runs from (L_c, H_in) to "
               "(L_c + (H_in − H_out)/tan α, H_out)"),
      real_key(
          "geometry.die_radius", 10.0, [](auto& c) -> auto& { return c.mesh.geometry.die_radius; })
          .within(1e-6, 1e6)
          .why(length_range)
          .constraint("≥ geometry.entry_half_height − geometry.exit_half_height")
          .unit("length")
          .doc("arc die: radius of the circular face, tangent to the exit direction at the die "
               "exit"),
      die_profile_key(),
      real_key(
          "geometry.land_length", 0.0, [](auto& c) -> auto& { return c.mesh.geometry.land_length; })
          .zero_or_at_least(1e-6)
          .at_most(1e6)
          .why(length_range)
          .constraint("a multiple of mesh.size; < geometry.exit_length for the square die")
          .unit("length")
          .doc("die land: a straight contact part y = H_out after the die face (Γ3; it counts "
               "as \"die\" for friction.on)"),
      integer_key(
          "geometry.dimension", 2, [](auto& c) -> auto& { return c.mesh.dimension; })
          .within(2, 3)
          .constraint(
              "3: geometry.symmetry = \"plane\"; mesh.source = \"gmsh\" only for the slab and "
              "the square-die rectangle")
          .doc("2: the plane (or axisymmetric) channel in quadrilaterals; 3: the solid channel "
               "of geometry.section in hexahedra or tetrahedra (mesh.cell; docs/3d.md, "
               "docs/simplices.md), or the unit cube of "
               "verification.solution"),
      section_key(),
      real_key(
          "geometry.thickness", 1.0, [](auto& c) -> auto& { return c.mesh.solid.thickness; })
          .within(1e-6, 1e6)
          .why(length_range)
          .constraint("only with geometry.dimension = 3 and geometry.section = \"slab\"")
          .unit("length")
          .doc("slab: extent in z, meshed in round(thickness/mesh.size) layers (at least one); "
               "pressures are forces over the ram area, so they do not depend on it"),
      real_key(
          "geometry.entry_half_width", 10.0,
          [](auto& c) -> auto& { return c.mesh.solid.entry_half_width; })
          .within(1e-6, 1e6)
          .why(length_range)
          .constraint("≥ geometry.exit_half_width; a multiple of mesh.size; only with "
                      "geometry.dimension = 3 and geometry.section = \"rectangle\"")
          .unit("length")
          .doc("rectangle: half width (in z) of the billet in the container"),
      real_key(
          "geometry.exit_half_width", 5.0,
          [](auto& c) -> auto& { return c.mesh.solid.exit_half_width; })
          .within(1e-6, 1e6)
          .why(length_range)
          .constraint("≤ geometry.entry_half_width; a multiple of mesh.size with the square "
                      "die; only with geometry.dimension = 3 and geometry.section = \"rectangle\", "
                      "or \"round\" with the square die (then the exit's corner within "
                      "geometry.entry_half_height − mesh.size/2 of the axis)")
          .unit("length")
          .doc("rectangle, and round with the square die: half width (in z) of the product "
               "after the die"),
      profile_key(),
      profile_file_key(),
      enum_key(
          "geometry.profile_symmetry", "none",
          {{"none", mesh::ProfileSymmetry::None},
           {"y", mesh::ProfileSymmetry::Y},
           {"yz", mesh::ProfileSymmetry::YZ}},
          [](auto& c) -> auto& { return c.mesh.solid.profile.symmetry; })
          .constraint("geometry.section = \"profile\"; the outline symmetric about the planes")
          .doc("planes of symmetry of the profile: none (the whole die), y (the plane y = 0: "
               "the half y ≥ 0 is modelled) or yz (y = 0 and z = 0: the quarter y, z ≥ 0); the "
               "outline is given whole"),
      real_key(
          "geometry.billet_radius", 10.0,
          [](auto& c) -> auto& { return c.mesh.solid.profile.billet_radius; })
          .within(1e-6, 1e6)
          .why(length_range)
          .constraint("geometry.section = \"profile\"; every outline point inside it")
          .unit("length")
          .doc("profile: radius of the round billet (and container) x ∈ [0, L_c]; pressures are "
               "forces over its area"),
      bearing_length_key(),
      enum_key(
          "geometry.symmetry", "plane",
          {{"plane", physics::Symmetry::Plane}, {"axisymmetric", physics::Symmetry::Axisymmetric}},
          [](auto& c) -> auto& { return c.symmetry; })
          .doc("plane strain, or axial symmetry about y = 0 (y = r; rod and wire): pressures "
               "are forces over πR²"),
  };
}

} // namespace formflow::io::keys
