// SPDX-License-Identifier: MIT
// The contact boundary Γ3 as a profile along its arc length (a point set in 3D).
#include "formflow/post/post_process.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <tuple>

namespace formflow::post {

namespace {

/// The sample of one Γ3 point, arc length left to the caller.
template <int dim>
ContactSample sample_of(const mesh::Mesh<dim>& mesh, const assembly::ContactPoint<dim>& point) {
  ContactSample sample;
  sample.x = point.position[0];
  sample.y = point.position[1];
  if constexpr (dim == 3) sample.z = point.position[2];
  sample.contact_pressure = point.contact_pressure;
  sample.slip_velocity = point.tangential_velocity.norm();
  sample.friction_stress = point.friction_traction.norm();
  sample.sticking = point.sticking;
  sample.part = mesh.facets[point.facet].label == mesh::BoundaryLabel::Die ? 1 : 0;
  return sample;
}

/// Γ3 of a solid is a surface: no chain of faces to walk, so the points are
/// listed in an order that depends only on where they are.
std::vector<ContactSample> surface_samples(const assembly::FormingProblem<3>& problem,
                                           const std::vector<assembly::ContactPoint<3>>& contact) {
  std::vector<ContactSample> samples;
  samples.reserve(contact.size());
  for (const auto& point : contact)
    samples.push_back(sample_of(problem.discretisation().mesh(), point));
  std::sort(samples.begin(), samples.end(), [](const auto& a, const auto& b) {
    return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
  });
  return samples;
}

std::vector<ContactSample> plane_profile(const assembly::FormingProblem<2>& problem,
                                         const std::vector<assembly::ContactPoint<2>>& contact) {
  const auto& mesh = problem.discretisation().mesh();
  const int n_q = problem.discretisation().facet_rule().size();
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
    const auto face = mesh.face_nodes(facet.local_face);
    segments.push_back(
        {first, mesh.cells(face.front(), facet.cell), mesh.cells(face.back(), facet.cell)});
    by_node.emplace(segments.back().from, segments.size() - 1);
    by_node.emplace(segments.back().to, segments.size() - 1);
  }
  if (segments.empty()) return {};
  const std::vector<Index> rear = assembly::nodes_on(mesh, mesh::BoundaryLabel::Rear);
  std::vector<bool> used(segments.size(), false);
  // Where the next chain starts: an end of a chain not walked yet, the one on
  // the rear first, else the one with the smallest x; a closed loop of unused
  // segments starts anywhere on it. Γ3 of a general mesh may have several chains
  // (a die apart from the container): they follow each other along the arc length.
  auto chain_start = [&]() -> std::optional<Index> {
    std::optional<Index> start;
    Real best = std::numeric_limits<Real>::max();
    for (const auto& [node, segment] : by_node) {
      if (used[segment]) continue;
      const auto range = by_node.equal_range(node);
      const auto unused = std::count_if(range.first, range.second,
                                        [&](const auto& entry) { return !used[entry.second]; });
      if (unused != 1) continue; // interior joint, not a chain end
      const bool on_rear = std::binary_search(rear.begin(), rear.end(), node);
      const Real key = on_rear ? -1.0 : mesh.nodes(0, node);
      if (key < best) best = key, start = node;
    }
    if (start) return start;
    for (std::size_t k = 0; k < segments.size(); ++k)
      if (!used[k]) return segments[k].from;
    return std::nullopt;
  };

  std::vector<ContactSample> samples;
  Real arc_length = 0.0;
  for (std::optional<Index> start = chain_start(); start; start = chain_start()) {
    for (Index node = *start;;) {
      auto range = by_node.equal_range(node);
      auto next = std::find_if(range.first, range.second,
                               [&](const auto& entry) { return !used[entry.second]; });
      if (next == range.second) break;
      const Segment& segment = segments[next->second];
      used[next->second] = true;
      // Face points run from `from` to `to`; walk them from `node`, measuring the
      // arc length along the polyline through them (exact on straight faces,
      // a chord error of O(h³/R²) on curved ones).
      const bool forward = segment.from == node;
      Point<2> previous = mesh.nodes.col(node);
      Real along_face = 0.0;
      std::vector<ContactSample> along;
      for (int step = 0; step < n_q; ++step) {
        const int q = forward ? step : n_q - 1 - step;
        const auto& point = contact[segment.first_point + q];
        along_face += (point.position - previous).norm();
        previous = point.position;
        ContactSample sample = sample_of(mesh, point);
        sample.arc_length = arc_length + along_face;
        along.push_back(sample);
      }
      std::sort(along.begin(), along.end(),
                [](const auto& a, const auto& b) { return a.arc_length < b.arc_length; });
      samples.insert(samples.end(), along.begin(), along.end());
      for (int q = 0; q < n_q; ++q) {
        const auto& point = contact[segment.first_point + q];
        // Axisymmetric weights are r dΓ (per radian): the arc length wants dΓ.
        arc_length += problem.discretisation().axisymmetric() ? point.weight / point.position[1]
                                                              : point.weight;
      }
      node = segment.from == node ? segment.to : segment.from;
    }
  }
  return samples;
}

} // namespace

template <int dim>
std::vector<ContactSample>
contact_profile(const assembly::FormingProblem<dim>& problem,
                const std::vector<assembly::ContactPoint<dim>>& contact) {
  if constexpr (dim == 2)
    return plane_profile(problem, contact);
  else
    return surface_samples(problem, contact);
}

template std::vector<ContactSample>
contact_profile<2>(const assembly::FormingProblem<2>&,
                   const std::vector<assembly::ContactPoint<2>>&);
template std::vector<ContactSample>
contact_profile<3>(const assembly::FormingProblem<3>&,
                   const std::vector<assembly::ContactPoint<3>>&);

} // namespace formflow::post
