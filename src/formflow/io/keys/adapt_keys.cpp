// SPDX-License-Identifier: MIT
// Case keys of the [adapt] section (adaptive refinement, issue 17): rows of the table in
// io/case_keys.cpp.
#include "formflow/io/keys/key_spec.hpp"

namespace formflow::io::keys {

std::vector<CaseKey> adapt_keys() {
  return {
      real_key(
          "adapt.target_error", 0.0, [](auto& c) -> auto& { return c.adapt.target_error; })
          .within(0, 1)
          .why("a fraction of the load: 0 switches adaptivity off, 1 is a 100 % error")
          .constraint("> 0 needs a plane or axisymmetric channel from mesh.source = \"structured\" "
                      "or \"gmsh\" (the cycles remesh it with Gmsh), a build with Gmsh, Newton, "
                      "penalties d > 0 and dN > 0 and regularised friction (else refused); where "
                      "the load's error is not estimated (Coulomb friction, Taylor–Hood) the "
                      "cycles stop after the first, summary.json adapt.stop saying why")
          .doc(
              "relative error of the load to reach: the cycles stop once the estimate of "
              "|p_h − p| (the full, \"refined\" estimate; cycles far from the target mark with the "
              "cheap one on Q2 unless solver.load_error = \"refined\") is at most "
              "this times |p_h|, or once the regularisations' offset |p(2ε) − p(ε)| alone "
              "is (no mesh lowers it: summary.json adapt.stop names the keys to lower); 0: no "
              "adaptivity"),
      integer_key(
          "adapt.max_cycles", 8, [](auto& c) -> auto& { return c.adapt.max_cycles; })
          .at_least(1)
          .at_most(50)
          .doc("at most this many solves, the first on the case's mesh; reaching it without the "
               "target is a result, not an error (summary.json adapt.stop)"),
      integer_key(
          "adapt.max_dofs", 400000, [](auto& c) -> auto& { return c.adapt.max_dofs; })
          .at_least(100)
          .at_most(1e9)
          .doc("no cycle on a mesh expected to have more velocity dofs than this (the estimate "
               "solves on 4 times as many)"),
      real_key(
          "adapt.fraction", 0.5, [](auto& c) -> auto& { return c.adapt.fraction; })
          .within(0.05, 1)
          .why("Dörfler's θ: below 0.05 a cycle refines almost nothing, 1 refines every cell "
               "with a nonzero indicator")
          .doc("Dörfler marking: refine (halve the size of) the fewest cells, largest |η_K| "
               "first, that hold this share of Σ|η_K|"),
      real_key(
          "adapt.coarsen_fraction", 0.05, [](auto& c) -> auto& { return c.adapt.coarsen_fraction; })
          .within(0, 0.5)
          .why("a share of Σ|η_K| to give up: beyond a half, coarsening would undo what "
               "Dörfler's θ (0.5 by default) refines")
          .doc("coarsen (double the size of, up to mesh.size) the most cells, smallest |η_K| "
               "first, that hold at most this share of Σ|η_K|; 0: never coarsen"),
  };
}

} // namespace formflow::io::keys
