// SPDX-License-Identifier: MIT
// A strict scan of an MSH file's sections, in the order and sizes Gmsh reads them,
// refusing what would make Gmsh allocate by a lie, cut a tag or carry an absurd number.
#include "formflow/mesh/msh_data.hpp"

#include "formflow/mesh/msh_scanner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <set>
#include <vector>

namespace formflow::mesh {

namespace {

using msh_scan::Position;
using msh_scan::Refusal;
using msh_scan::Scanner;

/// Nodes of Gmsh's element types 1…31 (Gmsh's `ElementType`; index = type).
constexpr std::array<int, 32> nodes_of_type = {0,  2,  3,  4,  4, 8, 6,  5,  3,  6, 9,
                                               10, 27, 18, 14, 1, 8, 20, 15, 13, 9, 10,
                                               12, 15, 15, 21, 4, 5, 6,  20, 35, 56};

/// The largest tag a section of `count` entries may use (max_msh_tag at most).
std::int64_t tag_bound(std::int64_t count) {
  const auto sparse = static_cast<std::uint64_t>(count) * sparse_tag_factor + sparse_tag_slack;
  return static_cast<std::int64_t>(std::min<std::uint64_t>(max_msh_tag, sparse));
}

/// Tags of one section: each checked against its bounds; node tags also for repeats,
/// one bit per admissible tag.
class TagRange {
public:
  /// `count` entries (already held by the file's size), tags in [first, last] as
  /// declared (2.2: [1, any]).
  TagRange(std::string_view what, std::int64_t count, std::int64_t first, std::int64_t last,
           bool track_repeats)
      : what_(what), first_(std::max<std::int64_t>(first, 1)) {
    last_ = tag_bound(count);
    why_last_ = fmt::format("the largest a section of {} may use ({} × count + {}; at most {})",
                            count, sparse_tag_factor, sparse_tag_slack, max_msh_tag);
    if (last < last_) {
      last_ = last;
      why_last_ = "the section's declared maximum tag";
    }
    if (track_repeats) seen_.assign(static_cast<std::size_t>(last_) + 1, false);
  }

  void check(const Scanner& scanner, Position where, std::int64_t tag) {
    if (tag < 1) scanner.refuse_at(where, fmt::format("{} {} is not positive", what_, tag));
    if (tag > static_cast<std::int64_t>(max_msh_tag))
      scanner.refuse_at(where, fmt::format("{} {} is above {}, the largest tag Gmsh keeps (an "
                                           "int)",
                                           what_, tag, max_msh_tag));
    if (tag > last_)
      scanner.refuse_at(where, fmt::format("{} {} is above {}, {}", what_, tag, last_, why_last_));
    if (tag < first_)
      scanner.refuse_at(where, fmt::format("{} {} is below {}, the section's declared minimum tag",
                                           what_, tag, first_));
    if (seen_.empty()) return;
    if (seen_[static_cast<std::size_t>(tag)])
      scanner.refuse_at(where,
                        fmt::format("{} {} is a duplicate: it was given before", what_, tag));
    seen_[static_cast<std::size_t>(tag)] = true;
  }

private:
  std::string_view what_;
  std::int64_t first_;
  std::int64_t last_ = 0;
  std::string why_last_;
  std::vector<bool> seen_;
};

/// A node an element names: a positive tag Gmsh can keep.
void check_node_reference(const Scanner& scanner, Position where, std::int64_t tag) {
  if (tag < 1 || tag > static_cast<std::int64_t>(max_msh_tag))
    scanner.refuse_at(where,
                      fmt::format("an element names node {}, outside 1…{}", tag, max_msh_tag));
}

void check_coordinate(const Scanner& scanner, Position where, double x, std::string_view axis) {
  if (!std::isfinite(x)) scanner.refuse_at(where, fmt::format("{} is not finite", axis));
  if (std::abs(x) > max_msh_coordinate)
    scanner.refuse_at(
        where, fmt::format("{} = {:g} is outside |{}| ≤ {:g}", axis, x, axis, max_msh_coordinate));
  if (x != 0 && std::abs(x) < std::numeric_limits<double>::min())
    scanner.refuse_at(where, fmt::format("{} = {:g} is subnormal (nonzero, below {:g})", axis, x,
                                         std::numeric_limits<double>::min()));
}

void check_point(Scanner& scanner, int n_coordinates = 3) {
  static constexpr std::array<std::string_view, 6> names = {"x", "y", "z", "x", "y", "z"};
  for (int k = 0; k < n_coordinates; ++k) {
    const Position where = scanner.next();
    check_coordinate(scanner, where, scanner.real("a coordinate"), names[k]);
  }
}

int nodes_of(const Scanner& scanner, Position where, std::int64_t type) {
  if (type < 1 || type >= static_cast<std::int64_t>(nodes_of_type.size()))
    scanner.refuse_at(where, fmt::format("element type {} is not one of Gmsh's types 1…31", type));
  return nodes_of_type[static_cast<std::size_t>(type)];
}

void skip_integers(Scanner& scanner, std::int64_t count, std::string_view what) {
  scanner.hold(count, scanner.int_bytes(), what);
  for (std::int64_t k = 0; k < count; ++k) scanner.integer(what);
}

// ---- format 2.2 -------------------------------------------------------------------

void nodes_22(Scanner& scanner) {
  const Position counted = scanner.next();
  const std::int64_t count = scanner.line_integer("the node count");
  scanner.hold_at(counted, count, scanner.int_bytes() + 3 * scanner.real_bytes(), "nodes");
  TagRange tags("node tag", count, 1, std::numeric_limits<std::int64_t>::max(), true);
  for (std::int64_t k = 0; k < count; ++k) {
    const Position where = scanner.next();
    tags.check(scanner, where, scanner.integer("a node tag"));
    check_point(scanner);
  }
}

void element_22(Scanner& scanner, TagRange& tags, int n_nodes, std::int64_t n_tags) {
  const Position where = scanner.next();
  tags.check(scanner, where, scanner.integer("an element tag"));
  if (scanner.binary()) skip_integers(scanner, n_tags, "element tags");
  for (int a = 0; a < n_nodes; ++a) {
    const Position node = scanner.next();
    check_node_reference(scanner, node, scanner.integer("a node of an element"));
  }
}

void elements_22(Scanner& scanner) {
  const Position counted = scanner.next();
  const std::int64_t count = scanner.line_integer("the element count");
  // A tag, a type, a tag count and a node in ASCII; a tag and a node in binary.
  scanner.hold_at(counted, count, (scanner.binary() ? 2 : 4) * scanner.int_bytes(), "elements");
  TagRange tags("element tag", count, 1, std::numeric_limits<std::int64_t>::max(), false);
  if (!scanner.binary()) {
    for (std::int64_t k = 0; k < count; ++k) {
      // tag, type, number of tags, the tags, the nodes.
      const Position where = scanner.next();
      const std::int64_t tag = scanner.integer("an element tag");
      const Position type_at = scanner.next();
      const int n_nodes = nodes_of(scanner, type_at, scanner.integer("an element type"));
      const std::int64_t n_tags = scanner.integer("an element's number of tags");
      skip_integers(scanner, n_tags, "element tags");
      tags.check(scanner, where, tag);
      for (int a = 0; a < n_nodes; ++a) {
        const Position node = scanner.next();
        check_node_reference(scanner, node, scanner.integer("a node of an element"));
      }
    }
    return;
  }
  // Binary: blocks of one type, each with its count and number of tags.
  for (std::int64_t read = 0; read < count;) {
    const Position type_at = scanner.next();
    const int n_nodes = nodes_of(scanner, type_at, scanner.integer("an element type"));
    const std::int64_t in_block = scanner.integer("a block's element count");
    const std::int64_t n_tags = scanner.integer("an element's number of tags");
    if (in_block < 1 || in_block > count - read)
      scanner.refuse(fmt::format("a block of {} elements, where {} of the declared {} are left",
                                 in_block, count - read, count));
    scanner.hold(n_tags, scanner.int_bytes(), "element tags");
    scanner.hold(in_block, (1 + static_cast<std::size_t>(n_tags) + n_nodes) * scanner.int_bytes(),
                 "elements");
    for (std::int64_t k = 0; k < in_block; ++k) element_22(scanner, tags, n_nodes, n_tags);
    read += in_block;
  }
}

// ---- format 4.1 -------------------------------------------------------------------

/// The four numbers that open $Nodes and $Elements: blocks, entries, minimum and
/// maximum tag; the counts held by the file's size.
struct SectionCounts {
  std::int64_t blocks, entries, first, last;
};

SectionCounts section_counts(Scanner& scanner, std::string_view entries, std::size_t entry_bytes) {
  SectionCounts counts{};
  const Position counted = scanner.next();
  counts.blocks = scanner.size("the block count");
  counts.entries = scanner.size(fmt::format("the {} count", entries));
  counts.first = scanner.size("the minimum tag");
  counts.last = scanner.size("the maximum tag");
  scanner.hold_at(counted, counts.blocks, 3 * scanner.int_bytes() + scanner.size_bytes(), "blocks");
  scanner.hold_at(counted, counts.entries, entry_bytes, entries);
  if (counts.entries > 0 && counts.first < 1)
    scanner.refuse_at(counted,
                      fmt::format("the declared minimum tag {} is not positive", counts.first));
  if (counts.entries > 0 && counts.first > counts.last)
    scanner.refuse_at(counted, fmt::format("the declared minimum tag {} is above the maximum {}",
                                           counts.first, counts.last));
  if (counts.entries > 0 && counts.last > tag_bound(counts.entries))
    scanner.refuse_at(counted,
                      fmt::format("the declared maximum tag {} is above {}, the largest a section "
                                  "of {} {} may use ({} × count + {}; at most {})",
                                  counts.last, tag_bound(counts.entries), counts.entries, entries,
                                  sparse_tag_factor, sparse_tag_slack, max_msh_tag));
  return counts;
}

/// One block's header (entity dimension, entity tag, a third int, its count) with
/// the count checked against what the section has left.
std::pair<std::int64_t, std::int64_t> block_header(Scanner& scanner, std::int64_t& left,
                                                   std::int64_t& third) {
  const Position where = scanner.next();
  const std::int64_t dimension = scanner.integer("an entity dimension");
  if (dimension < 0 || dimension > 3)
    scanner.refuse_at(where, fmt::format("entity dimension {} is not 0, 1, 2 or 3", dimension));
  scanner.integer("an entity tag");
  third = scanner.integer("a block's type");
  const std::int64_t count = scanner.size("a block's count");
  if (count > left)
    scanner.refuse(fmt::format("a block of {} where the section's count leaves {}", count, left));
  left -= count;
  return {dimension, count};
}

void nodes_41(Scanner& scanner) {
  const SectionCounts counts =
      section_counts(scanner, "nodes", scanner.size_bytes() + 3 * scanner.real_bytes());
  TagRange tags("node tag", counts.entries, counts.first, counts.last, true);
  std::int64_t left = counts.entries;
  for (std::int64_t block = 0; block < counts.blocks; ++block) {
    std::int64_t parametric = 0;
    const auto [dimension, count] = block_header(scanner, left, parametric);
    if (parametric != 0 && parametric != 1)
      scanner.refuse("a block's parametric flag is not 0 or 1");
    for (std::int64_t k = 0; k < count; ++k) {
      const Position where = scanner.next();
      tags.check(scanner, where, scanner.size("a node tag"));
    }
    for (std::int64_t k = 0; k < count; ++k) {
      check_point(scanner);
      for (std::int64_t u = 0; u < parametric * dimension; ++u) {
        const Position where = scanner.next();
        if (!std::isfinite(scanner.real("a parametric coordinate")))
          scanner.refuse_at(where, "a parametric coordinate is not finite");
      }
    }
  }
  if (left != 0)
    scanner.refuse(
        fmt::format("the blocks hold {} nodes fewer than the declared {}", left, counts.entries));
}

void elements_41(Scanner& scanner) {
  const SectionCounts counts = section_counts(scanner, "elements", 2 * scanner.size_bytes());
  TagRange tags("element tag", counts.entries, counts.first, counts.last, false);
  std::int64_t left = counts.entries;
  for (std::int64_t block = 0; block < counts.blocks; ++block) {
    std::int64_t type = 0;
    const Position type_at = scanner.next();
    const auto count = block_header(scanner, left, type).second;
    const int n_nodes = nodes_of(scanner, type_at, type);
    scanner.hold(count, (1 + static_cast<std::size_t>(n_nodes)) * scanner.size_bytes(), "elements");
    for (std::int64_t k = 0; k < count; ++k) {
      const Position where = scanner.next();
      tags.check(scanner, where, scanner.size("an element tag"));
      for (int a = 0; a < n_nodes; ++a) {
        const Position node = scanner.next();
        check_node_reference(scanner, node, scanner.size("a node of an element"));
      }
    }
  }
  if (left != 0)
    scanner.refuse(fmt::format("the blocks hold {} elements fewer than the declared {}", left,
                               counts.entries));
}

void entities_41(Scanner& scanner) {
  std::array<std::int64_t, 4> counts{};
  for (auto& count : counts) count = scanner.size("an entity count");
  for (std::size_t dimension = 0; dimension < counts.size(); ++dimension) {
    // A point: tag, x y z, its physical tags; a curve, surface or volume: tag, its
    // box (6 numbers), its physical tags, its bounding entities.
    const int n_box = dimension == 0 ? 3 : 6;
    scanner.hold(counts[dimension],
                 scanner.int_bytes() + n_box * scanner.real_bytes() +
                     (dimension == 0 ? 1 : 2) * scanner.size_bytes(),
                 "entities");
    for (std::int64_t k = 0; k < counts[dimension]; ++k) {
      scanner.integer("an entity tag");
      check_point(scanner, n_box);
      skip_integers(scanner, scanner.size("a physical tag count"), "physical tags");
      if (dimension > 0)
        skip_integers(scanner, scanner.size("a bounding entity count"), "bounding entities");
    }
  }
}

void skip_to_end(Scanner& scanner, std::string_view end) {
  while (!scanner.at_end())
    if (scanner.text_line() == end) return;
  scanner.refuse(fmt::format("no `{}`", end));
}

void expect_end(Scanner& scanner, std::string_view name) {
  scanner.skip_blank();
  const Position where = scanner.next();
  if (scanner.at_end() || scanner.text_line() != fmt::format("$End{}", name))
    scanner.refuse_at(where, fmt::format("`$End{}` expected here, where the section's counts end "
                                         "it",
                                         name));
}

/// Past the header parse_msh_header accepted; notes the binary marker's byte order.
void skip_header(Scanner& scanner) {
  scanner.text_line(); // $MeshFormat
  scanner.text_line(); // version, file type, data size
  if (scanner.binary()) {
    std::int32_t one = 0;
    const std::string_view marker = scanner.text_line();
    std::memcpy(&one, marker.data(), sizeof one);
    scanner.set_swapped(one != 1);
  }
  scanner.text_line(); // $EndMeshFormat
}

} // namespace

std::optional<std::string> msh_data_problem(std::string_view bytes, const MshHeader& header,
                                            std::string_view path) {
  Scanner scanner(bytes, header.binary, path);
  const bool v41 = header.version == "4.1";
  try {
    skip_header(scanner);
    std::set<std::string, std::less<>> seen;
    for (;;) {
      scanner.skip_blank();
      if (scanner.at_end()) return std::nullopt;
      const Position where = scanner.next();
      const std::string_view line = scanner.text_line();
      const std::string_view name = line.substr(line.empty() ? 0 : 1);
      if (line.empty() || line.front() != '$')
        scanner.refuse_at(where, "text outside a section (sections start with `$`)");
      const bool known = name == "PhysicalNames" || name == "Nodes" || name == "Elements" ||
                         (v41 && name == "Entities");
      if (!known)
        scanner.refuse_at(where, fmt::format("section `{:.40}` is not one formflow reads (a mesh "
                                             "has $PhysicalNames, {}$Nodes and $Elements)",
                                             line, v41 ? "$Entities, " : ""));
      if (!seen.emplace(name).second)
        scanner.refuse_at(where, fmt::format("a second `{}` section", line));
      if (name == "PhysicalNames") {
        skip_to_end(scanner, "$EndPhysicalNames");
        continue;
      }
      if (name == "Entities") entities_41(scanner);
      if (name == "Nodes") v41 ? nodes_41(scanner) : nodes_22(scanner);
      if (name == "Elements") v41 ? elements_41(scanner) : elements_22(scanner);
      expect_end(scanner, name);
    }
  } catch (const Refusal& refusal) {
    return refusal.text;
  }
}

} // namespace formflow::mesh
