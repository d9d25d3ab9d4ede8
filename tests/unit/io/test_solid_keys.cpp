// SPDX-License-Identifier: MIT
// The solid-channel keys (geometry.dimension, .section, .thickness, .*_half_width): their
// defaults, the slab mesh they make, and the refusal of what 3D cannot run yet.
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"
#include "formflow/io/case_json.hpp"
#include "formflow/io/mesh_input.hpp"
#include "formflow/io/mesh_memory.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>
#include <variant>

namespace formflow::io {
namespace {

bool solid_hint_has_text(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// The InputError of loading `text`, checked to name `key` on `line`.
InputError error_in(const std::string& text, const std::string& key, int line) {
  try {
    load_case_text(text, "solid.toml", {});
  } catch (const InputError& error) {
    EXPECT_EQ(error.key, key) << error.what();
    EXPECT_EQ(error.line, line) << error.what();
    EXPECT_EQ(error.file, "solid.toml") << error.what();
    return error;
  }
  ADD_FAILURE() << "no InputError for\n" << text;
  return InputError("", -1, "", "");
}

TEST(SolidKeys, DefaultsArePlaneAndTheSlab) {
  const Case case_ = load_case("", {});
  EXPECT_EQ(case_.mesh.dimension, 2);
  EXPECT_EQ(case_.mesh.solid.section, mesh::ChannelSection::Slab);
  EXPECT_EQ(case_.mesh.solid.thickness, 1.0);
  EXPECT_EQ(case_.mesh.solid.entry_half_width, 10.0);
  EXPECT_EQ(case_.mesh.solid.exit_half_width, 5.0);
}

TEST(SolidKeys, DimensionThreeMakesTheSlabOfThePlaneChannelInLayers) {
  const Case case_ = load_case_text(
      "[geometry]\ndimension = 3\nthickness = 5\n[mesh]\nsize = 2.5\nelement = \"Q1\"\n",
      "solid.toml", {});
  const mesh::AnyMesh any = load_mesh(case_);
  ASSERT_EQ(mesh::dimension_of(any), 3);
  const mesh::Mesh<3>& slab = std::get<mesh::Mesh<3>>(any);
  const mesh::Mesh<2> plane = mesh::make_die_channel_mesh(case_.mesh.geometry, 2.5, 1);
  EXPECT_EQ(slab.n_cells(), 2 * plane.n_cells()); // 5/2.5 layers
  EXPECT_EQ(slab.n_nodes(), 3 * plane.n_nodes());
  EXPECT_EQ(slab.nodes.row(2).maxCoeff(), 5.0);
  // The memory estimate counts the layers and three components per node.
  const auto estimate = estimate_mesh_memory(case_, 2.5);
  ASSERT_TRUE(estimate.has_value());
  EXPECT_EQ(estimate->cells, slab.n_cells());
  EXPECT_EQ(estimate->dofs, 3.0 * slab.n_cells());
}

TEST(SolidKeys, ValuesRoundTripThroughTheCaseJson) {
  const Case case_ =
      load_case_text("[geometry]\ndimension = 3\nthickness = 2.5\n", "solid.toml", {});
  const nlohmann::json json = case_to_json(case_);
  EXPECT_EQ(json["geometry"]["dimension"], 3);
  EXPECT_EQ(json["geometry"]["section"], "slab");
  EXPECT_EQ(json["geometry"]["thickness"], 2.5);
  EXPECT_EQ(case_.mesh.solid.thickness, 2.5);
}

TEST(SolidKeys, SolidKeysInAPlaneCaseAreRefusedByNameUnlessAtTheirDefaults) {
  // A default value changes nothing (the reference's block of defaults must load).
  EXPECT_NO_THROW(
      load_case_text("[geometry]\nsection = \"slab\"\nthickness = 1\n", "solid.toml", {}));
  error_in("[geometry]\nsection = \"round\"\n", "geometry.section", 2);
  const InputError thickness = error_in("[geometry]\nthickness = 2\n", "geometry.thickness", 2);
  EXPECT_TRUE(solid_hint_has_text(thickness.message, "geometry.dimension = 3"))
      << thickness.message;
  error_in("[geometry]\nentry_half_width = 4\n", "geometry.entry_half_width", 2);
  // The slab reads the thickness, not the rectangle's half widths.
  error_in("[geometry]\ndimension = 3\nexit_half_width = 4\n", "geometry.exit_half_width", 3);
}

TEST(SolidKeys, WhatThreeDimensionsCannotRunYetIsRefusedNamingTheKeySetLast) {
  // A round billet through the (default) square die runs (mesh/round_square_die_mesh.hpp)
  // while the exit rectangle fits inside the circle with half a cell to spare.
  EXPECT_NO_THROW(
      load_case_text("[geometry]\ndimension = 3\nsection = \"round\"\n", "round.toml", {}));
  const InputError outside =
      error_in("[geometry]\ndimension = 3\nsection = \"round\"\nexit_half_width = 9\n",
               "geometry.exit_half_width", 4);
  EXPECT_TRUE(solid_hint_has_text(outside.message, "not inside the billet's radius 10"))
      << outside.message;
  error_in("[geometry]\ndimension = 3\nsection = \"round\"\nexit_half_width = 8\n"
           "exit_half_height = 6\n",
           "geometry.exit_half_height", 5); // radius 10 = R: no margin
  error_in("[geometry]\ndimension = 3\nsection = \"round\"\nexit_half_width = 4.25\n",
           "geometry.exit_half_width", 4); // not a multiple of mesh.size
  // The revolved dies make a round product: no half width to set.
  error_in("[geometry]\ndimension = 3\nsection = \"round\"\ndie = \"wedge\"\n"
           "exit_half_width = 4\n",
           "geometry.exit_half_width", 5);
  // The rectangle's half widths: no wider exit, cells of mesh.size across them (the
  // exit's only with the square die).
  error_in("[geometry]\ndimension = 3\nsection = \"rectangle\"\nexit_half_width = 11\n",
           "geometry.exit_half_width", 4);
  error_in("[geometry]\ndimension = 3\nsection = \"rectangle\"\nexit_half_width = 4.5\n",
           "geometry.exit_half_width", 4);
  error_in("[geometry]\ndimension = 3\nsection = \"rectangle\"\ndie = \"wedge\"\n"
           "entry_half_width = 9.5\n",
           "geometry.entry_half_width", 5);
  // Two keys make the combination: the one set last is blamed.
  error_in("[geometry]\nsymmetry = \"axisymmetric\"\ndimension = 3\n", "geometry.dimension", 3);
  error_in("[geometry]\ndimension = 3\nsymmetry = \"axisymmetric\"\n", "geometry.symmetry", 3);
  // Gmsh builds the slab and the square-die rectangle only (mesh/gmsh_solid_channel.hpp).
  const InputError gmsh = error_in("[geometry]\ndimension = 3\nsection = \"round\"\ndie = "
                                   "\"wedge\"\n[mesh]\nsource = \"gmsh\"\n",
                                   "mesh.source", 6);
  EXPECT_TRUE(solid_hint_has_text(gmsh.hint, "mesh.source = \"structured\"")) << gmsh.hint;
  error_in("[geometry]\ndimension = 3\nsection = \"rectangle\"\ndie = \"wedge\"\n"
           "entry_half_width = 5\nexit_half_width = 2\n[mesh]\nsource = \"gmsh\"\n",
           "mesh.source", 8);
  EXPECT_NO_THROW(
      load_case_text("[geometry]\ndimension = 3\n[mesh]\nsource = \"gmsh\"\n", "slab.toml", {}));
  // Gmsh needs no half width that mesh.size divides.
  EXPECT_NO_THROW(load_case_text("[geometry]\ndimension = 3\nsection = \"rectangle\"\n"
                                 "entry_half_width = 9.5\nexit_half_width = 4.5\n[mesh]\n"
                                 "source = \"gmsh\"\n",
                                 "bar.toml", {}));
  // A manufactured solution in 3D is the unit cube (physics/manufactured_3d.hpp): it loads.
  EXPECT_NO_THROW(load_case_text(
      "[geometry]\ndimension = 3\n[verification]\nsolution = \"smooth\"\n[mesh]\nsize = 0.25\n",
      "solid.toml", {}));
  const InputError four = error_in("[geometry]\ndimension = 4\n", "geometry.dimension", 2);
  EXPECT_TRUE(solid_hint_has_text(four.hint, "2 ≤ value ≤ 3")) << four.hint;
}

} // namespace
} // namespace formflow::io
