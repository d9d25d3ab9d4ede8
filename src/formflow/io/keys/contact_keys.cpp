// SPDX-License-Identifier: MIT
// Case keys of the [contact] section (Discretisation of the contact boundary): rows of the table in
// io/case_keys.cpp.
#include "formflow/io/keys/key_spec.hpp"

namespace formflow::io::keys {

std::vector<CaseKey> contact_keys() {
  return {
      enum_key(
          "contact.normals", "faces",
          {{"faces", assembly::ContactNormals::Faces}, {"nodes", assembly::ContactNormals::Nodes}},
          [](auto& c) -> auto& { return c.contact.normals; })
          .doc("normal of the Γ3 penalty and friction: faces = each face's own normal at its "
               "Gauss points (the paper); nodes = one length-weighted mean normal per node, "
               "penalty and friction lumped on the nodes (docs/validation.md, contact normals). "
               "Not given, exact friction's semismooth Newton (friction.stick) puts the points "
               "on the nodes; given, it is honoured"),
      real_key(
          "contact.corner_angle", 60.0, [](auto& c) -> auto& { return c.contact.corner_angle; })
          .above(0)
          .below(180)
          .unit("degree")
          .doc("contact.normals = \"nodes\" only: where Γ3 faces meet at a larger turn of the "
               "normal, the node keeps both face normals and cannot move (a dead-metal corner)"),
  };
}

} // namespace formflow::io::keys
