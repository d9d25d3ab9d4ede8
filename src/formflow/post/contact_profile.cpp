// SPDX-License-Identifier: MIT
// The contact boundary Γ3 as a profile along its arc length.
#include "formflow/post/post_process.hpp"

#include <algorithm>
#include <map>

namespace formflow::post {

std::vector<ContactSample> contact_profile(const assembly::FormingProblem<2>& problem,
                                           const std::vector<assembly::ContactPoint<2>>& contact) {
  const auto& mesh = problem.mesh();
  const int n_q = problem.facet_rule().size();
  // Each contact face is a segment between its first and last face node;
  // chain the segments, starting from the end that touches the rear.
  struct Segment {
    std::size_t first_point;
    Index from, to;
  };
  std::vector<Segment> segments;
  std::multimap<Index, std::size_t> by_node;
  for (std::size_t first = 0; first < contact.size(); first += n_q) {
    const mesh::BoundaryFacet& facet = mesh.facets[contact[first].facet];
    const auto face = mesh::face_local_nodes<2>(mesh.nodes_per_side(), facet.local_face);
    segments.push_back({first, mesh.cells(face.front(), facet.cell), mesh.cells(face.back(), facet.cell)});
    by_node.emplace(segments.back().from, segments.size() - 1);
    by_node.emplace(segments.back().to, segments.size() - 1);
  }
  if (segments.empty()) return {};
  const std::vector<Index> rear = assembly::nodes_on(mesh, mesh::BoundaryLabel::Rear);
  Index start = segments.front().from;
  Real best = std::numeric_limits<Real>::max();
  for (const auto& [node, segment] : by_node) {
    if (by_node.count(node) != 1) continue;  // interior joint, not a chain end
    const bool on_rear = std::binary_search(rear.begin(), rear.end(), node);
    const Real key = on_rear ? -1.0 : mesh.nodes(0, node);
    if (key < best) best = key, start = node;
  }

  std::vector<ContactSample> samples;
  std::vector<bool> used(segments.size(), false);
  Real arc_length = 0.0;
  for (Index node = start;;) {
    auto range = by_node.equal_range(node);
    auto next = std::find_if(range.first, range.second, [&](const auto& entry) { return !used[entry.second]; });
    if (next == range.second) break;
    const Segment& segment = segments[next->second];
    used[next->second] = true;
    const Point<2> origin = mesh.nodes.col(node);
    std::vector<ContactSample> along;
    for (int q = 0; q < n_q; ++q) {
      const auto& point = contact[segment.first_point + q];
      ContactSample sample;
      sample.arc_length = arc_length + (point.position - origin).norm();
      sample.x = point.position[0];
      sample.y = point.position[1];
      sample.contact_pressure = point.contact_pressure;
      sample.slip_velocity = point.tangential_velocity.norm();
      sample.friction_stress = point.friction_traction.norm();
      sample.sticking = point.sticking;
      sample.part = mesh.facets[point.facet].label == mesh::BoundaryLabel::Die ? 1 : 0;
      along.push_back(sample);
    }
    std::sort(along.begin(), along.end(), [](const auto& a, const auto& b) { return a.arc_length < b.arc_length; });
    samples.insert(samples.end(), along.begin(), along.end());
    for (int q = 0; q < n_q; ++q) {
      const auto& point = contact[segment.first_point + q];
      // Axisymmetric weights are r dΓ (per radian): the arc length wants dΓ.
      arc_length += problem.axisymmetric() ? point.weight / point.position[1] : point.weight;
    }
    node = segment.from == node ? segment.to : segment.from;
  }
  return samples;
}

}  // namespace formflow::post
