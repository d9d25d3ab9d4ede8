// SPDX-License-Identifier: MIT
// Label names and face node numbering of tensor-product cells.
#include "formflow/mesh/mesh.hpp"

namespace formflow::mesh {

std::string_view label_name(BoundaryLabel label) {
  switch (label) {
  case BoundaryLabel::Rear: return "rear";
  case BoundaryLabel::FreeEntry: return "free_entry";
  case BoundaryLabel::Container: return "container";
  case BoundaryLabel::Die: return "die";
  case BoundaryLabel::FreeExit: return "free_exit";
  case BoundaryLabel::Front: return "front";
  case BoundaryLabel::Symmetry: return "symmetry";
  }
  return "unknown";
}

std::optional<BoundaryLabel> label_from_name(std::string_view name) {
  for (int k = 0; k < n_boundary_labels; ++k)
    if (label_name(static_cast<BoundaryLabel>(k)) == name) return static_cast<BoundaryLabel>(k);
  return std::nullopt;
}

template <int dim> std::vector<int> face_local_nodes(int n_side, int local_face) {
  const int axis = local_face / 2;
  const int fixed = (local_face % 2 == 0) ? 0 : n_side - 1;
  int n_cell = 1;
  for (int d = 0; d < dim; ++d) n_cell *= n_side;
  std::vector<int> result;
  // Walking the cell lexicographically keeps the face nodes lexicographic too.
  for (int local = 0; local < n_cell; ++local) {
    int rest = local;
    int coordinate = 0;
    for (int d = 0; d <= axis; ++d) {
      coordinate = rest % n_side;
      rest /= n_side;
    }
    if (coordinate == fixed) result.push_back(local);
  }
  return result;
}

template std::vector<int> face_local_nodes<2>(int, int);
template std::vector<int> face_local_nodes<3>(int, int);

} // namespace formflow::mesh
