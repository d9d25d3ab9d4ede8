// SPDX-License-Identifier: MIT
// mesh.cell and the simplex elements: the defaults the cell shape sets, and every pair
// of cell, element, pressure and formulation that is refused, by the key to change.
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"
#include "formflow/io/case_validation_simplex.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace formflow::io {
namespace {

Case loaded(const std::string& text) {
  return load_case_text(text, "case.toml", {});
}

/// The InputError of `text`, checked to blame `key` at `line`.
InputError refusal(const std::string& text, const std::string& key, int line) {
  try {
    loaded(text);
  } catch (const InputError& error) {
    EXPECT_EQ(error.key, key) << error.what();
    EXPECT_EQ(error.line, line) << error.what();
    return error;
  }
  ADD_FAILURE() << "no InputError for\n" << text;
  return InputError("", -1, "", "");
}

TEST(CellKeys, DefaultsAreTodaysCubesInBothDimensions) {
  EXPECT_EQ(loaded("").mesh.cell, mesh::CellKind::Quadrilateral);
  const Case solid = loaded("[geometry]\ndimension = 3\nsection = \"slab\"\n");
  EXPECT_EQ(solid.mesh.cell, mesh::CellKind::Hexahedron);
  EXPECT_EQ(solid.element, fem::ElementKind::Q2);
  EXPECT_EQ(case_cell_type(solid), (mesh::CellType{mesh::CellShape::Cube, 2, false}));
}

TEST(CellKeys, TrianglesDefaultToMixedP2WithBubblesForTheDiscontinuousPressure) {
  const Case case_ = loaded("[mesh]\ncell = \"triangle\"\n");
  EXPECT_EQ(case_.element, fem::ElementKind::P2);
  EXPECT_EQ(case_.formulation.type, assembly::FormulationType::Mixed);
  EXPECT_EQ(case_.formulation.pressure, fem::PressureSpace::P1disc);
  EXPECT_EQ(case_cell_type(case_), (mesh::CellType{mesh::CellShape::Simplex, 2, true}));
  // Taylor–Hood needs no bubbles.
  const Case taylor_hood =
      loaded("[mesh]\ncell = \"triangle\"\n[formulation]\npressure = \"P1\"\n");
  EXPECT_EQ(case_cell_type(taylor_hood), (mesh::CellType{mesh::CellShape::Simplex, 2, false}));
}

TEST(CellKeys, MiniElementTakesTheContinuousP1PressureUnlessTold) {
  const Case case_ = loaded("[mesh]\ncell = \"triangle\"\nelement = \"P1b\"\n");
  EXPECT_EQ(case_.formulation.pressure, fem::PressureSpace::P1);
  EXPECT_EQ(case_cell_type(case_), (mesh::CellType{mesh::CellShape::Simplex, 1, true}));
}

TEST(CellKeys, TheResolvedSimplexCaseLoadsAgain) {
  // Every key written (as summary.json's resolved case does) must load: mixed and the
  // element are then explicit, which is what the defaults chose.
  const Case case_ = loaded("[mesh]\ncell = \"triangle\"\nelement = \"P2\"\n"
                            "[formulation]\ntype = \"mixed\"\npressure = \"P1disc\"\n"
                            "[integration]\nvolumetric = 2\n");
  EXPECT_EQ(case_.element, fem::ElementKind::P2);
}

TEST(CellKeys, CellAndDimensionMustAgree) {
  const InputError error = refusal("[mesh]\ncell = \"tetrahedron\"\n", "mesh.cell", 2);
  EXPECT_NE(std::string(error.what()).find("geometry.dimension = 2"), std::string::npos);
  refusal("[mesh]\ncell = \"quadrilateral\"\n[geometry]\ndimension = 3\nsection = \"slab\"\n",
          "geometry.dimension", 4);
}

TEST(CellKeys, ElementsBelongToTheirCells) {
  refusal("[mesh]\ncell = \"triangle\"\nelement = \"Q2\"\n", "mesh.element", 3);
  refusal("[mesh]\nelement = \"P2\"\n", "mesh.element", 2);
  const InputError error =
      refusal("[mesh]\nelement = \"P1b\"\ncell = \"quadrilateral\"\n", "mesh.cell", 3);
  EXPECT_NE(std::string(error.what()).find("\"Q2\" or \"Q1\""), std::string::npos);
}

TEST(CellKeys, SimplicesRefuseTheVolumetricPenaltyAndTheCubesPressures) {
  const InputError penalty = refusal(
      "[mesh]\ncell = \"triangle\"\n[formulation]\ntype = \"penalty\"\n", "formulation.type", 4);
  EXPECT_NE(std::string(penalty.what()).find("penalty.d > 0"), std::string::npos);
  refusal("[mesh]\ncell = \"triangle\"\n[formulation]\npressure = \"Q1\"\n", "formulation.pressure",
          4);
  refusal("[formulation]\ntype = \"mixed\"\npressure = \"P1\"\n", "formulation.pressure", 3);
  refusal("[mesh]\ncell = \"triangle\"\nelement = \"P1b\"\n[formulation]\npressure = \"P0\"\n",
          "formulation.pressure", 5);
  refusal("[mesh]\ncell = \"triangle\"\n[integration]\nvolumetric = 3\n", "integration.volumetric",
          4);
}

TEST(CellKeys, WhatSimplicesDoNotRunYetIsRefusedByItsKey) {
  refusal("[mesh]\ncell = \"triangle\"\n[adapt]\ntarget_error = 0.01\n", "adapt.target_error", 4);
  refusal("[geometry]\ndimension = 3\nsection = \"slab\"\n[mesh]\ncell = \"tetrahedron\"\n"
          "[adapt]\ntarget_error = 0.01\n",
          "adapt.target_error", 7);
}

TEST(CellKeys, TetrahedraDefaultToP2Mixed) {
  const Case case_ =
      loaded("[geometry]\ndimension = 3\nsection = \"slab\"\n[mesh]\ncell = \"tetrahedron\"\n");
  EXPECT_EQ(case_.element, fem::ElementKind::P2);
  EXPECT_EQ(case_.formulation.type, assembly::FormulationType::Mixed);
}

} // namespace
} // namespace formflow::io
