// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Straightens the borders between disk regions, one arc at a time, keeping
// both regions disks; undoes a change on demand.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_BORDER_REROUTING_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_BORDER_REROUTING_H

#include <CGAL/Disk_segmentation/internal/Chart_selection/Arc_sides.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Border_arcs.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Border_path_search.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Round_stamps.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_topology.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Straightens the borders between disk regions: each arc is replaced by a
// shorter edge path between its two ends, near it, inside the union of its
// two regions (see Border_path_search), and the faces between the old and the
// new path change sides.
// Unlike Border_smoother's single-face moves this removes steps several
// triangles high, which are most of the length a border loses (the teeth of
// Voronoi cells on the dual graph, and the borders that splits and merges of
// charts leave). The new path touches no other region and the mesh's border
// only at its ends, so the other arcs do not move; both regions must stay
// disks of at least `smallest_region` faces.
class Border_router
{
public:
  explicit Border_router(const Indexed_triangle_mesh& m)
    : m_(m), borders_(m), path_search_(borders_), sides_(borders_), vertex_stamp_(m.number_of_vertices())
  {}
  // Its parts refer to each other.
  Border_router(const Border_router&) = delete;
  Border_router& operator=(const Border_router&) = delete;

  static constexpr std::size_t smallest_region = 3;

  // Starts from the regions `labels` gives (per face, below `regions` or
  // no_index).
  void assign(const std::vector<Index>& labels, std::size_t regions)
  {
    members_.assign(regions, std::vector<Index>());
    for(Index f = 0; f < labels.size(); ++f)
      if(labels[f] != no_index)
        members_[labels[f]].push_back(f);
    shared_vertices_.clear();
    for(Index v = 0; v < m_.number_of_vertices(); ++v)
      count_pairs_around(labels, v, 1);
  }

  // The arcs between regions given by `labels` (see Region_borders::arcs()).
  std::vector<Border_arc> arcs(const std::vector<Index>& labels) const { return borders_.arcs(labels); }

  // Replaces `arc` by the cheapest path between its ends (Border_path_search)
  // if that is shorter by more than `least_gain` (a fraction of the arc's
  // length) and costs less, the faces in between changing sides, when both
  // regions stay disks of `smallest_region` faces or more and no face in
  // `locked` (per face, non-zero: keep) would change. `size` holds the
  // number of faces of each region and is updated. On success, `change`
  // says which faces moved (see Arc_sides).
  bool reroute(std::vector<Index>& labels, std::vector<std::size_t>& size, const std::vector<char>& locked,
               Region_topology& topology, const Border_arc& arc, double least_gain, Arc_change& change)
  {
    const Index a = arc.a, b = arc.b;
    if(size[a] < smallest_region || size[b] < smallest_region)
      return false;
    std::vector<Index> path;
    if(!path_search_.shortest_path(labels, arc, (1. - least_gain) * arc.length, path))
      return false;
    // Two disks that share one arc and no other vertex make a disk, which a
    // path inside it between two points of its border cuts into two disks:
    // only the faces between the old arc and the new path change sides, and
    // neither the union nor the disk tests need to be visited (they took
    // 0.1 s of the 0.25 s of serial rerouting on refined_elephant x4; the
    // same faces move on 35 meshes, checked against flood_union()).
    if(shared_vertices(a, b) == arc.vertices.size())
    {
      std::size_t size_a = 0, size_b = 0;
      const Arc_sides::Local_result local =
        sides_.flip_between(labels, size, arc, path, locked, change, size_a, size_b);
      if(local == Arc_sides::Local_result::refused)
        return false;
      if(local == Arc_sides::Local_result::done)
      {
        if(size_a < smallest_region || size_b < smallest_region)
          return false;
        apply(labels, change);
        size[a] = size_a;
        size[b] = size_b;
        return true;
      }
    }

    std::vector<Index> new_a, new_b;
    if(!sides_.flood_union(labels, arc, path, region_faces(labels, a, b), locked, change, new_a, new_b))
      return false;
    if(change.old_labels.empty() || new_a.size() < smallest_region || new_b.size() < smallest_region)
      return false;
    if(!topology.is_disk(new_a) || !topology.is_disk(new_b))
      return false;
    apply(labels, change);
    size[a] = new_a.size();
    size[b] = new_b.size();
    return true;
  }

  // Takes back a change that reroute() made.
  void undo(std::vector<Index>& labels, std::vector<std::size_t>& size, const Arc_change& change)
  {
    relabel(labels, change, [&](Index f, Index old_label) {
      ++size[old_label];
      --size[labels[f]];
      labels[f] = old_label;
    });
  }

private:
  static std::uint64_t pair_key(Index a, Index b) { return Region_borders::edge_key(a, b); }

  // The number of vertices around which both regions have faces.
  std::size_t shared_vertices(Index a, Index b) const
  {
    const auto found = shared_vertices_.find(pair_key(a, b));
    return found == shared_vertices_.end() ? 0 : found->second;
  }

  // Adds `sign` to the shared vertex count of every pair of regions around v.
  void count_pairs_around(const std::vector<Index>& labels, Index v, int sign)
  {
    around_.clear();
    for(Index k = borders_.vertex_faces().begin[v]; k < borders_.vertex_faces().begin[v + 1]; ++k)
    {
      const Index l = labels[borders_.vertex_faces().faces[k]];
      if(l != no_index && std::find(around_.begin(), around_.end(), l) == around_.end())
        around_.push_back(l);
    }
    for(std::size_t i = 0; i < around_.size(); ++i)
      for(std::size_t j = i + 1; j < around_.size(); ++j)
        shared_vertices_[pair_key(around_[i], around_[j])] += sign;
  }

  // Calls visit(v) once for each corner of the faces `change` moved.
  template <typename Visit>
  void for_vertices_of(const Arc_change& change, const Visit& visit)
  {
    const std::uint32_t stamp = vertex_stamp_.next_round();
    for(const auto& moved : change.old_labels)
      for(Index v : m_.corners[moved.first])
        if(vertex_stamp_[v] != stamp)
        {
          vertex_stamp_[v] = stamp;
          visit(v);
        }
  }

  // Moves the faces of `change` to their new regions.
  void apply(std::vector<Index>& labels, const Arc_change& change)
  {
    relabel(labels, change, [&](Index f, Index old_label) {
      const Index now = old_label == change.a ? change.b : change.a;
      labels[f] = now;
      members_[now].push_back(f);
    });
  }

  // Calls `move(f, old label)` on each face of `change`, with the shared
  // vertex counts of the pairs around its corners taken out before and
  // counted again after.
  template <typename Move>
  void relabel(std::vector<Index>& labels, const Arc_change& change, const Move& move)
  {
    for_vertices_of(change, [&](Index v) { count_pairs_around(labels, v, -1); });
    for(const auto& moved : change.old_labels)
      move(moved.first, moved.second);
    for_vertices_of(change, [&](Index v) { count_pairs_around(labels, v, 1); });
  }

  // The faces labeled a or b (each region's list holds the faces it had
  // and those it gained).
  std::vector<Index> region_faces(const std::vector<Index>& labels, Index a, Index b) const
  {
    std::vector<Index> out;
    for(Index r : { a, b })
      for(Index f : members_[r])
        if(labels[f] == a || labels[f] == b)
          out.push_back(f);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  const Indexed_triangle_mesh& m_;
  Region_borders borders_;
  Border_path_search path_search_;
  Arc_sides sides_;
  Round_stamps vertex_stamp_;  // of for_vertices_of()
  std::vector<std::vector<Index> > members_;
  std::unordered_map<std::uint64_t, std::ptrdiff_t> shared_vertices_;  // per pair of regions (pair_key())
  std::vector<Index> around_;  // scratch of count_pairs_around()
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_BORDER_REROUTING_H
