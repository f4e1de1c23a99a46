// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Removes the saw teeth of the borders between disk regions by single
// face moves that keep both regions disks.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_BORDER_SMOOTHER_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_BORDER_SMOOTHER_H

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>

#include <deque>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Removes the saw teeth of the borders between disk regions. Borders of
// Voronoi cells on the dual graph follow mesh edges and zigzag: a face of
// region A with two edges on the border of region B sticks into B. Giving
// it to B replaces those two edges by its third one, which is shorter
// (triangle inequality), and keeps both regions disks when:
// - the third edge is shared with A (the face hangs on A by that edge), and
// - no other face of A touches the apex, the vertex between the two edges.
// Then the face meets B along a path of two edges, so B plus the face is a
// disk; and it meets the rest of A along one edge, so A minus the face is a
// disk (the union of two disks is a disk iff they meet along one path, see
// Disk_region_merger.h, and A is that union). The second condition needs no
// test: the faces across the two edges are B's, so around the apex the face
// is a fan of A on its own, and A, a disk, has one fan at each vertex.
// Whether a face is a tooth thus depends on its neighbors only, and a move
// queues only the moved face's neighbors again: the cost stays linear
// around a vertex of high valence (walking its faces for each move was
// quadratic). A region never drops below three faces this way: smoothing
// should not leave slivers as charts.
class Border_smoother
{
public:
  explicit Border_smoother(const Indexed_triangle_mesh& m) : m_(m) {}

  // Moves teeth among the faces of `faces`, whose regions are given by
  // `labels` (indexed by mesh face; faces outside `faces` must have a label
  // none of them has, e.g. no_index, and are left alone). Every region
  // must be a disk; they stay disks. Returns the number of moves.
  std::size_t smooth(std::vector<Index>& labels, const std::vector<Index>& faces) const
  {
    Mesh_labels mesh_labels{ labels };
    return smooth_labels(mesh_labels, faces);
  }

  // The same with `labels` a model of: Index at(Index face) const (no_index
  // outside `faces`) and void set(Index face, Index label).
  template <typename Labels>
  std::size_t smooth_labels(Labels& labels, const std::vector<Index>& faces) const
  {
    std::deque<Index> queue(faces.begin(), faces.end());
    std::unordered_map<Index, std::size_t> region_size;
    for(Index f : faces)
      ++region_size[labels.at(f)];
    std::size_t moves = 0;
    // Each move shortens the total border length strictly (for faces of
    // non-zero area), so a face cannot come back; the cap stops cycles
    // between degenerate faces, whose third edge is as long as the two
    // others together.
    const std::size_t max_moves = 4 * faces.size();
    while(!queue.empty() && moves < max_moves)
    {
      const Index f = queue.front();
      queue.pop_front();
      if(labels.at(f) == no_index)
        continue;
      Index b = no_index;
      if(region_size[labels.at(f)] <= smallest_region || !find_tooth(labels, f, b))
        continue;
      --region_size[labels.at(f)];
      ++region_size[b];
      labels.set(f, b);
      ++moves;
      for(Index g : m_.neighbors[f])
        if(g != no_index && labels.at(g) != no_index)
          queue.push_back(g);
    }
    return moves;
  }

  static constexpr std::size_t smallest_region = 3;

private:
  struct Mesh_labels
  {
    std::vector<Index>& labels;
    Index at(Index f) const { return labels[f]; }
    void set(Index f, Index label) { labels[f] = label; }
  };

  // Whether f is a tooth of its region into another region `b`.
  template <typename Labels>
  bool find_tooth(const Labels& labels, Index f, Index& b) const
  {
    const Index a = labels.at(f);
    Index across[3];
    for(int i = 0; i < 3; ++i)
    {
      const Index g = m_.neighbors[f][i];
      across[i] = (g == no_index) ? no_index : labels.at(g);
    }
    for(int i = 0; i < 3; ++i)
    {
      const Index x = across[(i + 1) % 3], y = across[(i + 2) % 3];
      if(across[i] != a || x != y || x == a || x == no_index)
        continue;
      b = x;
      return true;
    }
    return false;
  }

  const Indexed_triangle_mesh& m_;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_BORDER_SMOOTHER_H
