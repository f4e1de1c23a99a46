// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which faces change region when a border arc is replaced by a new path:
// found between the two, or by flooding the union of the two regions.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_ARC_SIDES_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_ARC_SIDES_H

#include <CGAL/Disk_segmentation/internal/Chart_selection/Border_arcs.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Vertex_faces.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Which faces change region when a border arc between regions a and b is
// replaced by a new path: those between the two. Keeps its per-face marks
// from one arc to the next.
class Arc_sides
{
public:
  explicit Arc_sides(const Region_borders& borders)
    : m_(borders.mesh()), borders_(borders), vertex_faces_(borders.vertex_faces()),
      face_stamp_(m_.number_of_faces(), 0), edge_mark_stamp_(m_.number_of_faces(), 0),
      edge_marks_(m_.number_of_faces(), 0), side_(m_.number_of_faces(), 0)
  {}

  enum class Local_result { done, refused, undecided };

  // The faces between the old arc and the new path, found from the new
  // path's two sides: a face on the left of the path must take the region
  // on the left of the arc, and faces of its region reached from it without
  // crossing the path or the arc take it too (the pockets between the two).
  // `undecided` when a pocket reaches the union's border or a face both
  // sides claim: the union was not the disk its shared vertices said, and
  // the whole union is flooded instead (flood_union()). `done` leaves the
  // sizes of the two regions after the change, `size_a` and `size_b`, to
  // the caller to check.
  Local_result flip_between(const std::vector<Index>& labels, const std::vector<std::size_t>& size,
                            const Border_arc& arc, const std::vector<Index>& path, const std::vector<char>& locked,
                            Arc_change& change, std::size_t& size_a, std::size_t& size_b)
  {
    const Index a = arc.a, b = arc.b;
    const std::uint32_t stamp = next_face_stamp();
    for(std::size_t i = 0; i + 1 < path.size(); ++i)
      mark_edge(path[i], path[i + 1], barrier_edge, stamp);
    Index left_of_arc = no_index;
    {
      Index f, g;
      if(!borders_.directed_faces(arc.vertices[0], arc.vertices[1], f, g))
        return Local_result::undecided;
      left_of_arc = labels[f];
    }
    const Index right_of_arc = left_of_arc == a ? b : a;
    auto in_union = [&](Index g) { return g != no_index && (labels[g] == a || labels[g] == b); };
    // side_[f]: 1 to take the left region, 2 the right one (stamped).
    std::vector<Index> queue;
    auto claim = [&](Index f, unsigned char side) {
      if(face_stamp_[f] == stamp)
        return side_[f] == side;
      face_stamp_[f] = stamp;
      side_[f] = side;
      if(labels[f] != (side == 1 ? left_of_arc : right_of_arc))
        queue.push_back(f);
      return true;
    };
    for(std::size_t i = 0; i + 1 < path.size(); ++i)
    {
      Index f, g;
      if(!borders_.directed_faces(path[i], path[i + 1], f, g) || !in_union(f) || !in_union(g) || !claim(f, 1) || !claim(g, 2))
        return Local_result::undecided;
    }
    change.a = a;
    change.b = b;
    change.old_labels.clear();
    for(std::size_t q = 0; q < queue.size(); ++q)
    {
      const Index f = queue[q];
      change.old_labels.emplace_back(f, labels[f]);
      for(int e = 0; e < 3; ++e)
      {
        const Index g = m_.neighbors[f][e];
        if(!in_union(g))
          return Local_result::undecided;
        // Faces of the other region lie across the old arc: a pocket ends there.
        if(has_mark(f, e, barrier_edge, stamp) || labels[g] != labels[f])
          continue;
        if(!claim(g, side_[f]))
          return Local_result::undecided;
      }
    }
    if(change.old_labels.empty())
      return Local_result::refused;
    std::sort(change.old_labels.begin(), change.old_labels.end());
    std::ptrdiff_t to_a = 0;
    for(const auto& moved : change.old_labels)
    {
      if(locked[moved.first])
        return Local_result::refused;
      to_a += moved.second == a ? -1 : 1;
    }
    size_a = std::size_t(std::ptrdiff_t(size[a]) + to_a);
    size_b = std::size_t(std::ptrdiff_t(size[b]) - to_a);
    return Local_result::done;
  }

  // The faces of `faces_ab` (the union of the arc's two regions, sorted) on
  // each side of the new path: reached from the union's border without
  // crossing the new path or any other edge between a and b (the old arc's
  // edges may be crossed). Fills `change` with the faces that change sides,
  // in the order of `faces_ab`, and `new_a` and `new_b` with the two regions
  // after it (sorted). False when a face is reached from both sides or from
  // none (the path does not cut the union in two), or when a face of
  // `locked` would move.
  bool flood_union(const std::vector<Index>& labels, const Border_arc& arc, const std::vector<Index>& path,
                   const std::vector<Index>& faces_ab, const std::vector<char>& locked, Arc_change& change,
                   std::vector<Index>& new_a, std::vector<Index>& new_b)
  {
    const Index a = arc.a, b = arc.b;
    const std::uint32_t stamp = next_face_stamp();
    for(std::size_t i = 0; i + 1 < path.size(); ++i)
      mark_edge(path[i], path[i + 1], barrier_edge, stamp);
    for(std::size_t i = 0; i + 1 < arc.vertices.size(); ++i)
      mark_edge(arc.vertices[i], arc.vertices[i + 1], old_arc_edge, stamp);
    std::vector<Index> queue;
    auto in_union = [&](Index g) { return g != no_index && (labels[g] == a || labels[g] == b); };
    for(Index f : faces_ab)
      for(int e = 0; e < 3; ++e)
        if(!in_union(m_.neighbors[f][e]))
        {
          face_stamp_[f] = stamp;
          side_[f] = labels[f] == a ? 1 : 2;
          queue.push_back(f);
          break;
        }
    bool conflict = false;
    for(std::size_t q = 0; q < queue.size() && !conflict; ++q)
    {
      const Index f = queue[q];
      for(int e = 0; e < 3; ++e)
      {
        const Index g = m_.neighbors[f][e];
        if(!in_union(g))
          continue;
        if(has_mark(f, e, barrier_edge, stamp) || (labels[f] != labels[g] && !has_mark(f, e, old_arc_edge, stamp)))
          continue;
        if(face_stamp_[g] == stamp)
        {
          if(side_[g] != side_[f])
          {
            conflict = true;
            break;
          }
          continue;
        }
        face_stamp_[g] = stamp;
        side_[g] = side_[f];
        queue.push_back(g);
      }
    }
    if(conflict || queue.size() != faces_ab.size())
      return false;

    change.a = a;
    change.b = b;
    change.old_labels.clear();
    for(Index f : faces_ab)
    {
      const Index now = side_[f] == 1 ? a : b;
      if(now != labels[f])
      {
        if(locked[f])
          return false;
        change.old_labels.emplace_back(f, labels[f]);
      }
    }
    new_a.clear();
    new_b.clear();
    for(Index f : faces_ab)
      (side_[f] == 1 ? new_a : new_b).push_back(f);
    return true;
  }

private:
  // Edges of the new path and of the old arc, marked on their faces for the
  // flood fill (bit e, or e + 3, of a face for its edge e).
  static constexpr int barrier_edge = 0, old_arc_edge = 3;

  void mark_edge(Index u, Index w, int kind, std::uint32_t stamp)
  {
    const std::uint64_t key = Region_borders::edge_key(u, w);
    for(Index k = vertex_faces_.begin[u]; k < vertex_faces_.begin[u + 1]; ++k)
    {
      const Index f = vertex_faces_.faces[k];
      for(int e = 0; e < 3; ++e)
        if(Region_borders::edge_key(m_.corners[f][e], m_.corners[f][(e + 1) % 3]) == key)
        {
          if(edge_mark_stamp_[f] != stamp)
          {
            edge_mark_stamp_[f] = stamp;
            edge_marks_[f] = 0;
          }
          edge_marks_[f] = static_cast<unsigned char>(edge_marks_[f] | (1u << (kind + e)));
        }
    }
  }

  bool has_mark(Index f, int e, int kind, std::uint32_t stamp) const
  {
    return edge_mark_stamp_[f] == stamp && (edge_marks_[f] >> (kind + e) & 1u) != 0;
  }

  std::uint32_t next_face_stamp()
  {
    if(++face_clock_ == 0)
    {
      std::fill(face_stamp_.begin(), face_stamp_.end(), 0);
      std::fill(edge_mark_stamp_.begin(), edge_mark_stamp_.end(), 0);
      face_clock_ = 1;
    }
    return face_clock_;
  }

  const Indexed_triangle_mesh& m_;
  const Region_borders& borders_;
  const Vertex_faces& vertex_faces_;
  std::vector<std::uint32_t> face_stamp_, edge_mark_stamp_;
  std::vector<unsigned char> edge_marks_;
  std::vector<unsigned char> side_;  // per face (stamped): 1 to take one region, 2 the other
  std::uint32_t face_clock_ = 0;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_ARC_SIDES_H
