// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_MERGE_TREE_H
#define CGAL_DISK_SEGMENTATION_MERGE_TREE_H

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// The merges done by `merge_disk_regions()` (or `segment_into_disks()`), as
/// a forest of binary trees whose every node is a topological disk.
///
/// Nodes `0` to `number_of_leaves - 1` are the regions given to the merging
/// (the disks of `refine_to_topological_disks()`); node
/// `number_of_leaves + i` is the union of the two nodes `merges[i]`, made by
/// the `i`-th merge. The roots (nodes that are no merge's child) are the
/// patches of the result. `face_leaves` gives the leaf of every face, in the
/// order of `faces(tm)`.
///
/// `parameterize_patches()` reads it (named parameter `merge_tree`) to
/// choose the charts top-down: a patch whose chart exceeds the distortion
/// bound is replaced by its two children, and so on down to the leaves.
struct Merge_tree
{
  /// Number of regions before merging.
  std::size_t number_of_leaves = 0;
  /// The two children of node `number_of_leaves + i`.
  std::vector<std::array<std::size_t, 2> > merges;
  /// Leaf of every face, in the order of `faces(tm)`.
  std::vector<std::size_t> face_leaves;

  std::size_t number_of_nodes() const { return number_of_leaves + merges.size(); }
  bool is_leaf(std::size_t node) const { return node < number_of_leaves; }
  /// The children of an internal node.
  const std::array<std::size_t, 2>& children(std::size_t node) const { return merges[node - number_of_leaves]; }

  /// The parent of every node (`number_of_nodes()` for a root).
  std::vector<std::size_t> parents() const
  {
    std::vector<std::size_t> parent(number_of_nodes(), number_of_nodes());
    for(std::size_t i = 0; i < merges.size(); ++i)
      for(std::size_t child : merges[i])
        parent[child] = number_of_leaves + i;
    return parent;
  }

  /// The root above a leaf.
  std::size_t root_of_leaf(std::size_t leaf, const std::vector<std::size_t>& parent) const
  {
    // Ends: a parent is always made after its children, so ids increase.
    while(parent[leaf] != number_of_nodes())
      leaf = parent[leaf];
    return leaf;
  }
};

} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_MERGE_TREE_H
