// SPDX-License-Identifier: MIT
// A profile through a flat die (geometry.section = "profile"): the product's outline, its
// symmetry, the round billet and the bearing, and the plane geometry they need.
#pragma once

#include "formflow/core/types.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace formflow::mesh {

/// Which planes of symmetry the model uses: the outline is given whole and the model
/// keeps y ≥ 0 (`Y`: the plane y = 0), or y ≥ 0 and z ≥ 0 (`YZ`: half and quarter models).
enum class ProfileSymmetry { None, Y, YZ };

/// The product's cross-section in the (y, z) plane of the die, x the extrusion direction.
/// The billet x ∈ [0, L_c] (radius `billet_radius`) is pushed against a flat die at
/// x = L_c with the outline as its opening; the opening's wall, the bearing, runs from
/// x = L_c over bearing(e) along each outline edge e; the free extrudate then runs to
/// x = L_c + max bearing + L_e (ChannelGeometry's container_length and exit_length).
struct ProfileDie {
  std::vector<std::array<Real, 2>> outline; ///< closed polygon (y, z); last ≠ first
  ProfileSymmetry symmetry = ProfileSymmetry::None;
  Real billet_radius = 10.0;
  /// One length for every edge, or one per outline edge (edge e from point e to e + 1).
  std::vector<Real> bearing_length = {1.0};

  /// The bearing length of outline edge `edge`.
  Real bearing(std::size_t edge) const {
    return bearing_length.size() == 1 ? bearing_length.front() : bearing_length.at(edge);
  }
  Real longest_bearing() const;
  Real shortest_bearing() const;
};

/// What is wrong with the outline of `die` as a flat die's opening, or nothing: fewer than
/// three points, two consecutive points together, edges that cross or touch, a point not
/// inside the billet, an outline that is not symmetric about the planes its symmetry
/// names, or no area on the model's side of them. The text says where (point or edge
/// numbers from 0, coordinates).
std::optional<std::string> profile_outline_problem(const ProfileDie& die);

/// The distance from (y, z) to outline edge `edge` (a segment).
Real distance_to_edge(const ProfileDie& die, std::size_t edge, const std::array<Real, 2>& point);

/// The outline edge nearest to (y, z) (the first of equally near ones).
std::size_t nearest_edge(const ProfileDie& die, const std::array<Real, 2>& point);

/// The images of (y, z) under the die's symmetry: itself, and its mirrors in y = 0 and
/// z = 0 as the symmetry has them (1, 2 or 4 points). A point of the model stands for
/// all of them in the whole section.
std::vector<std::array<Real, 2>> symmetry_images(const ProfileDie& die,
                                                 const std::array<Real, 2>& point);

/// The outline's area (positive: the outline may be given either way round).
Real outline_area(const ProfileDie& die);

/// The solid's volume in the model (the symmetry's part of it): billet, bearing and
/// extrudate, for the memory estimate before Gmsh meshes it.
Real profile_model_volume(const ProfileDie& die, Real container_length, Real exit_length);

/// The points of a profile CSV (geometry.profile_file), or what is wrong and where.
struct ProfileFileRead {
  std::vector<std::array<Real, 2>> points;
  std::string problem; ///< empty when read
  int line = 0;        ///< the line of `problem`
};
/// Reads `text` as lines `y, z` (blank lines and `#` comments skipped, one header line of
/// text allowed first); at most `max_points` points.
ProfileFileRead read_profile_csv(const std::string& text, std::size_t max_points);

} // namespace formflow::mesh
