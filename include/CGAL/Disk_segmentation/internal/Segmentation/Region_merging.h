// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The merging step on an indexed mesh, and the merge tree's face order
// (the mesh's or the input's).

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_REGION_MERGING_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_REGION_MERGING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Merge_tree.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Disk_region_merger.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// `labels` numbers disk regions canonically; merges them and renumbers.
// `tree`, if not null, receives the merges and the leaf of every face.
inline std::size_t merge_regions(const Indexed_triangle_mesh& m, std::vector<Index>& labels,
                                 std::size_t number_of_regions, double threshold, Merge_tree* tree = nullptr)
{
  if(tree != nullptr)
  {
    tree->number_of_leaves = number_of_regions;
    tree->face_leaves.assign(labels.begin(), labels.end());
  }
  Disk_region_merger merger(m, labels, number_of_regions);
  merger.run(threshold);
  if(tree != nullptr)
    tree->merges = merger.merges();
  return make_canonical(labels);
}

// A Merge_tree lists the leaves of the faces in the order of faces(tm),
// the indexed mesh in its own (Indexed_triangle_mesh::input_face): from
// the mesh's order to the input's, in place.
inline void face_leaves_to_input_order(const Indexed_triangle_mesh& m, Merge_tree& tree)
{
  if(m.input_face.empty() || tree.face_leaves.size() != m.number_of_faces())
    return;
  std::vector<std::size_t> leaves(tree.face_leaves.size());
  for(std::size_t f = 0; f < leaves.size(); ++f)
    leaves[m.input_face[f]] = tree.face_leaves[f];
  tree.face_leaves.swap(leaves);
}

// A copy of `tree` with its faces in the indexed mesh's order. A tree of
// another size is copied as it is, for the checks to name it.
inline Merge_tree face_leaves_to_mesh_order(const Indexed_triangle_mesh& m, const Merge_tree& tree)
{
  Merge_tree out = tree;
  if(!m.input_face.empty() && tree.face_leaves.size() == m.number_of_faces())
    for(std::size_t f = 0; f < out.face_leaves.size(); ++f)
      out.face_leaves[f] = tree.face_leaves[m.input_face[f]];
  return out;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_REGION_MERGING_H
