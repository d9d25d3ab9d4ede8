// SPDX-License-Identifier: MIT
// Hand-written MSH files (2.2 and 4.1, ASCII and binary) whose every number the test
// chooses, lies included: hostile tags, coordinates and counts for the data check.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace formflow::testing {

struct MshNode {
  std::int64_t tag;
  double x, y, z;
};

struct MshElement {
  std::int64_t tag;
  int type; ///< Gmsh's element type (3 quad-4, 5 hexa-8, 1 line-2, 2 triangle-3, ...)
  std::vector<std::int64_t> nodes;
};

/// A mesh as the file states it; `declared_nodes` overrides the node count written.
struct MshContent {
  int dimension = 2; ///< of the one entity (4.1) that holds every node and element
  std::vector<MshNode> nodes;
  std::vector<MshElement> elements;
  std::optional<std::int64_t> declared_nodes;
  /// 4.1: the largest node tag written in $Nodes' header (else the largest tag).
  std::optional<std::int64_t> declared_last_node;
};

/// Two unit quadrilaterals (quad-4, type 3) in the plane: tags 1…6 and 1…2.
inline MshContent two_quads() {
  MshContent mesh;
  mesh.nodes = {{1, 0, 0, 0}, {2, 1, 0, 0}, {3, 2, 0, 0}, {4, 0, 1, 0}, {5, 1, 1, 0}, {6, 2, 1, 0}};
  mesh.elements = {{1, 3, {1, 2, 5, 4}}, {2, 3, {2, 3, 6, 5}}};
  return mesh;
}

/// One unit hexahedron (hexa-8, type 5): tags 1…8 and 1.
inline MshContent one_hexahedron() {
  MshContent mesh;
  mesh.dimension = 3;
  mesh.nodes = {{1, 0, 0, 0}, {2, 1, 0, 0}, {3, 1, 1, 0}, {4, 0, 1, 0},
                {5, 0, 0, 1}, {6, 1, 0, 1}, {7, 1, 1, 1}, {8, 0, 1, 1}};
  mesh.elements = {{1, 5, {1, 2, 3, 4, 5, 6, 7, 8}}};
  return mesh;
}

namespace msh_detail {

/// Appends numbers as the format stores them: text with separators, or raw bytes.
class Out {
public:
  Out(bool binary, bool swapped) : binary_(binary), swapped_(swapped) {}
  void text(const std::string& line) { bytes_ += line; }
  void int32(std::int64_t value) {
    if (!binary_) return word(fmt::format("{}", value));
    raw(static_cast<std::int32_t>(value));
  }
  void size(std::int64_t value) {
    if (!binary_) return word(fmt::format("{}", value));
    raw(static_cast<std::uint64_t>(value));
  }
  void real(double value) {
    if (!binary_) return word(fmt::format("{}", value));
    raw(value);
  }
  void end_line() {
    if (!binary_) bytes_ += '\n';
  }
  std::string bytes() const { return bytes_; }

private:
  template <class T> void raw(T value) {
    char buffer[sizeof(T)];
    std::memcpy(buffer, &value, sizeof(T));
    if (swapped_) std::reverse(buffer, buffer + sizeof(T));
    bytes_.append(buffer, sizeof(T));
  }
  void word(const std::string& text) {
    if (!bytes_.empty() && bytes_.back() != '\n') bytes_ += ' ';
    bytes_ += text;
  }
  bool binary_;
  bool swapped_;
  std::string bytes_;
};

inline void header(Out& out, const std::string& version, bool binary) {
  out.text("$MeshFormat\n" + version + (binary ? " 1 8\n" : " 0 8\n"));
  if (binary) {
    out.int32(1); // in the writer's byte order
    out.text("\n");
  }
  out.text("$EndMeshFormat\n");
}

inline void version_22(Out& out, const MshContent& mesh, bool binary) {
  out.text(fmt::format("$Nodes\n{}\n",
                       mesh.declared_nodes.value_or(static_cast<std::int64_t>(mesh.nodes.size()))));
  for (const MshNode& node : mesh.nodes) {
    out.int32(node.tag);
    out.real(node.x);
    out.real(node.y);
    out.real(node.z);
    out.end_line();
  }
  out.text(binary ? "\n$EndNodes\n" : "$EndNodes\n");
  out.text(fmt::format("$Elements\n{}\n", mesh.elements.size()));
  for (const MshElement& element : mesh.elements) {
    if (binary) { // one block per element: type, one element, two tags
      out.int32(element.type);
      out.int32(1);
      out.int32(2);
    }
    out.int32(element.tag);
    if (!binary) {
      out.int32(element.type);
      out.int32(2);
    }
    out.int32(1); // physical
    out.int32(1); // elementary entity
    for (const std::int64_t node : element.nodes) out.int32(node);
    out.end_line();
  }
  out.text(binary ? "\n$EndElements\n" : "$EndElements\n");
}

inline void version_41(Out& out, const MshContent& mesh, bool binary) {
  const auto n_nodes = static_cast<std::int64_t>(mesh.nodes.size());
  // One entity of the mesh's dimension, no physical tags, no boundary.
  out.text("$Entities\n");
  for (int d = 0; d < 4; ++d) out.size(d == mesh.dimension ? 1 : 0);
  out.end_line();
  out.int32(1);
  for (const double corner : {0.0, 0.0, 0.0, 1.0, 1.0, 1.0}) out.real(corner);
  out.size(0);
  out.size(0);
  out.end_line();
  out.text(binary ? "\n$EndEntities\n" : "$EndEntities\n");
  std::int64_t first = 0, last = 0;
  for (const MshNode& node : mesh.nodes) {
    first = first == 0 ? node.tag : std::min(first, node.tag);
    last = std::max(last, node.tag);
  }
  out.text("$Nodes\n");
  out.size(1);
  out.size(mesh.declared_nodes.value_or(n_nodes));
  out.size(first);
  out.size(mesh.declared_last_node.value_or(last));
  out.end_line();
  out.int32(mesh.dimension);
  out.int32(1);
  out.int32(0);
  out.size(n_nodes);
  out.end_line();
  for (const MshNode& node : mesh.nodes) {
    out.size(node.tag);
    out.end_line();
  }
  for (const MshNode& node : mesh.nodes) {
    out.real(node.x);
    out.real(node.y);
    out.real(node.z);
    out.end_line();
  }
  out.text(binary ? "\n$EndNodes\n" : "$EndNodes\n");
  std::map<int, std::vector<const MshElement*>> by_type;
  std::int64_t first_element = 0, last_element = 0;
  for (const MshElement& element : mesh.elements) {
    by_type[element.type].push_back(&element);
    first_element = first_element == 0 ? element.tag : std::min(first_element, element.tag);
    last_element = std::max(last_element, element.tag);
  }
  out.text("$Elements\n");
  out.size(static_cast<std::int64_t>(by_type.size()));
  out.size(static_cast<std::int64_t>(mesh.elements.size()));
  out.size(first_element);
  out.size(last_element);
  out.end_line();
  for (const auto& [type, elements] : by_type) {
    out.int32(mesh.dimension);
    out.int32(1);
    out.int32(type);
    out.size(static_cast<std::int64_t>(elements.size()));
    out.end_line();
    for (const MshElement* element : elements) {
      out.size(element->tag);
      for (const std::int64_t node : element->nodes) out.size(node);
      out.end_line();
    }
  }
  out.text(binary ? "\n$EndElements\n" : "$EndElements\n");
}

} // namespace msh_detail

/// The bytes of `mesh` as an MSH file of `version` ("2.2" or "4.1"), ASCII or binary
/// (this machine's byte order, or the other one if `swapped`), as Gmsh lays it out.
inline std::string msh_bytes(const MshContent& mesh, const std::string& version, bool binary,
                             bool swapped = false) {
  msh_detail::Out out(binary, swapped);
  msh_detail::header(out, version, binary);
  if (version == "2.2")
    msh_detail::version_22(out, mesh, binary);
  else
    msh_detail::version_41(out, mesh, binary);
  return out.bytes();
}

} // namespace formflow::testing
