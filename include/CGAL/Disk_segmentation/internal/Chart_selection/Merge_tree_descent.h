// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The top-down choice of charts in the merge tree: the candidates to try
// and the tasks of the descent.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_MERGE_TREE_DESCENT_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_MERGE_TREE_DESCENT_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Merge_tree.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Chart_merging.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Chart_splitting.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// One chart to try: a node of the merge tree, or a whole patch when there is
// no tree. `path` (the child indices from the patch's root) orders the
// charts of a patch the same way whatever the schedule.
struct Chart_candidate
{
  std::size_t patch;
  std::size_t node;  // Merge_tree node, or no_node
  std::vector<std::size_t> path;
  double excess_density;  // of the nearest parameterized ancestor (see Split_rule)
  Parent_chart parent;    // the nearest valid parameterized ancestor, if any
  static constexpr std::size_t no_node = std::size_t(-1);
};

// A task of the top-down choice (see parameterize_indexed_patches()): a
// candidate of the merge tree (or a whole patch), or, `in_split`, a region
// of the split below the rejected leaf `candidate`.
struct Descent_task
{
  Chart_candidate candidate;
  bool in_split;
  Split_task region;
};

// Where a kept chart comes in the merges' order: the charts the tree gave,
// level by level (tree depth, then patch and path), then the pieces of the
// splits, by the depth, patch and path of their leaf and then in the order
// of a recursion (their path, which extends the leaf's).
struct Found_chart
{
  bool in_split;
  std::size_t depth;  // of the tree candidate the chart comes from
  Kept_chart kept;

  bool operator<(const Found_chart& o) const
  {
    return std::tie(in_split, depth, kept.patch, kept.path) < std::tie(o.in_split, o.depth, o.kept.patch, o.kept.path);
  }
};

// Faces of every node's leaves, gathered from the tree (or the patches).
class Candidate_faces
{
public:
  Candidate_faces(const Merge_tree* tree, const std::vector<std::vector<Index> >& patch_faces)
    : tree_(tree), patch_faces_(patch_faces)
  {
    if(tree_ == nullptr)
      return;
    leaf_faces_.resize(tree_->number_of_leaves);
    for(Index f = 0; f < tree_->face_leaves.size(); ++f)
      leaf_faces_[tree_->face_leaves[f]].push_back(f);
  }

  std::vector<Index> operator()(const Chart_candidate& c) const
  {
    if(c.node == Chart_candidate::no_node)
      return patch_faces_[c.patch];
    std::vector<Index> faces;
    // Ends: every internal node has two children of smaller id.
    std::vector<std::size_t> stack(1, c.node);
    while(!stack.empty())
    {
      const std::size_t n = stack.back();
      stack.pop_back();
      if(tree_->is_leaf(n))
        faces.insert(faces.end(), leaf_faces_[n].begin(), leaf_faces_[n].end());
      else
        for(std::size_t child : tree_->children(n))
          stack.push_back(child);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
  }

private:
  const Merge_tree* tree_;
  const std::vector<std::vector<Index> >& patch_faces_;
  std::vector<std::vector<Index> > leaf_faces_;
};

// The root of every patch in `tree`, after checking that the tree's roots
// are exactly the patches.
inline std::vector<std::size_t> patch_roots(const Indexed_triangle_mesh& m, const Merge_tree& tree,
                                            const std::vector<std::size_t>& face_patches, std::size_t number_of_patches)
{
  if(tree.face_leaves.size() != face_patches.size())
    throw Input_error("merge_tree: it has " + std::to_string(tree.face_leaves.size()) + " faces, the mesh " +
                      std::to_string(face_patches.size()));
  for(const auto& children : tree.merges)
    for(std::size_t i = 0; i < 2; ++i)
      if(children[i] >= tree.number_of_nodes())
        throw Input_error("merge_tree: a merge names node " + std::to_string(children[i]) + " which does not exist");
  for(std::size_t i = 0; i < tree.merges.size(); ++i)
    if(tree.merges[i][0] >= tree.number_of_leaves + i || tree.merges[i][1] >= tree.number_of_leaves + i ||
       tree.merges[i][0] == tree.merges[i][1])
      throw Input_error("merge_tree: merge " + std::to_string(i) + " does not join two earlier nodes");
  const std::vector<std::size_t> parent = tree.parents();
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> root_of_patch(number_of_patches, none), patch_of_root(tree.number_of_nodes(), none);
  for(std::size_t f = 0; f < face_patches.size(); ++f)
  {
    if(tree.face_leaves[f] >= tree.number_of_leaves)
      throw Input_error("merge_tree: face #" + std::to_string(m.input_position(Index(f))) + " has no leaf");
    const std::size_t root = tree.root_of_leaf(tree.face_leaves[f], parent);
    const std::size_t p = face_patches[f];
    if(root_of_patch[p] == none && patch_of_root[root] == none)
    {
      root_of_patch[p] = root;
      patch_of_root[root] = p;
    }
    else if(root_of_patch[p] != root || patch_of_root[root] != p)
      throw Input_error("merge_tree: its roots are not the patches of face_patch_map (face #" +
                        std::to_string(m.input_position(Index(f))) + ")");
  }
  return root_of_patch;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_MERGE_TREE_DESCENT_H
