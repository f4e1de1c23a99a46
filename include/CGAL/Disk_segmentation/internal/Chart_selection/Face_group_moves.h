// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Moves faces between disk patches so that each group of faces (a
// polygon of the caller's mesh) lies in one patch.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_FACE_GROUP_MOVES_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_FACE_GROUP_MOVES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_topology.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Vertex_faces.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// What keep_face_groups_whole() did.
struct Face_group_moves
{
  std::size_t moved = 0;  // groups moved whole into one patch
  std::size_t left = 0;   // groups left across patches
};

// Moves faces between disk patches so that a group of faces (a polygon of
// the caller's mesh, triangulated) lies in one patch, when every patch
// stays a disk (or empties).
//
// A move changes the patches around the group only, so it is tested
// locally where the parts are disks: T plus a disk P is a disk iff they
// share one path of edges (see Disk_region_merger.h); S minus a disk Q is
// a disk iff the rest shares one path with Q and has no pinched vertex
// (only Q's vertices change fans; two components of the rest would share
// disjoint parts with Q, since touching each other they would pinch).
// The faces of each patch around a vertex are counted once (a hash of
// (vertex, patch) pairs), so testing a quad on the border of a patch of
// 100k faces, or at a vertex of valence 200k, costs about the quad's size.
// Parts that are not disks (a material group, a ring) are tested whole.
// Testing every patch whole for every target instead took 4.9 s and 200 MB
// on an 11k-face torus cut in 10k charts with 4 groups.
class Face_group_mover
{
public:
  Face_group_mover(const Indexed_triangle_mesh& m, std::vector<Index>& labels)
    : m_(m), labels_(labels), faces_around_(m), topology_(m), mark_(m.number_of_faces(), 0),
      counted_(m.number_of_vertices(), 0), on_mesh_border_(m.number_of_vertices(), 0)
  {
    for(Index f = 0; f < m.number_of_faces(); ++f)
    {
      for(int i = 0; i < 3; ++i)
        if(m.neighbors[f][i] == no_index)
        {
          on_mesh_border_[m.corners[f][i]] = 1;
          on_mesh_border_[m.corners[f][(i + 1) % 3]] = 1;
        }
      if(labels[f] >= members_.size())
        members_.resize(std::size_t(labels[f]) + 1);
      members_[labels[f]].push_back(f);
    }
    for(const std::vector<Index>& faces : members_)
      size_.push_back(faces.size());
  }

  // Moves the faces of `group` (distinct faces) into one patch if allowed:
  // the patches holding most of it are tried first (ties by patch), at
  // most `max_targets` of them. Returns whether the group lies in one patch.
  bool keep_whole(std::vector<Index> group, std::size_t max_targets)
  {
    std::sort(group.begin(), group.end());
    std::vector<Index> patches;
    for(Index f : group)
      patches.push_back(labels_[f]);
    std::sort(patches.begin(), patches.end());
    std::vector<std::pair<long, Index> > shares;  // (-faces, patch)
    for(Index p : patches)
      if(shares.empty() || shares.back().second != p)
        shares.emplace_back(-1, p);
      else
        --shares.back().first;
    if(shares.size() < 2)
      return true;
    std::sort(shares.begin(), shares.end());

    // Whether a patch may give its part away does not depend on where the
    // part goes: if two patches may not, no target is possible.
    std::vector<char> may_give(shares.size(), 1);
    std::size_t refusals = 0;
    for(std::size_t i = 0; i < shares.size() && refusals < 2; ++i)
      if(!leaves_disk(shares[i].second, part(group, [&](Index f) { return labels_[f] == shares[i].second; })))
      {
        may_give[i] = 0;
        ++refusals;
      }
    if(refusals > 1)
      return false;
    for(std::size_t i = 0, tried = 0; i < shares.size() && tried < max_targets; ++i)
    {
      if(refusals == 1 && may_give[i])
        continue;
      ++tried;
      const Index target = shares[i].second;
      const std::vector<Index> joining = part(group, [&](Index f) { return labels_[f] != target; });
      if(!joins_disk(target, joining))
        continue;
      for(Index f : joining)
        relabel(f, target);
      return true;
    }
    return false;
  }

private:
  template <typename Keep>
  std::vector<Index> part(const std::vector<Index>& group, const Keep& keep) const
  {
    std::vector<Index> faces;
    for(Index f : group)
      if(keep(f))
        faces.push_back(f);
    return faces;
  }

  static std::uint64_t key(Index v, Index patch) { return (std::uint64_t(v) << 32) | patch; }

  // Faces of `patch` around v, counted on first use.
  Index faces_of_patch_at(Index v, Index patch)
  {
    if(!counted_[v])
    {
      counted_[v] = 1;
      for(Index k = faces_around_.begin[v]; k < faces_around_.begin[v + 1]; ++k)
        ++count_[key(v, labels_[faces_around_.faces[k]])];
    }
    const auto it = count_.find(key(v, patch));
    return it == count_.end() ? 0 : it->second;
  }

  void relabel(Index f, Index patch)
  {
    const Index old = labels_[f];
    for(Index v : m_.corners[f])
      if(counted_[v])
      {
        const auto it = count_.find(key(v, old));
        if(--it->second == 0)
          count_.erase(it);
        ++count_[key(v, patch)];
      }
    --size_[old];
    ++size_[patch];
    members_[patch].push_back(f);
    labels_[f] = patch;
  }

  Index next_stamp()
  {
    if(++stamp_ == 0)
    {
      std::fill(mark_.begin(), mark_.end(), 0);
      stamp_ = 1;
    }
    return stamp_;
  }

  // Local tests count vertices as fans: with copies of pinched input
  // vertices, which Region_topology counts as one, the whole test runs.
  bool is_local(const std::vector<Index>& part) { return m_.split_from.empty() && topology_.is_disk(part); }

  // The vertices of `part`'s faces, sorted, and for each the number of
  // those faces around it.
  void part_vertices(const std::vector<Index>& part)
  {
    vertices_.clear();
    for(Index f : part)
      for(Index v : m_.corners[f])
        vertices_.push_back(v);
    std::sort(vertices_.begin(), vertices_.end());
    in_part_.clear();
    std::size_t unique = 0;
    for(std::size_t i = 0; i < vertices_.size(); ++i)
      if(unique > 0 && vertices_[unique - 1] == vertices_[i])
        ++in_part_[unique - 1];
      else
      {
        vertices_[unique++] = vertices_[i];
        in_part_.push_back(1);
      }
    vertices_.resize(unique);
  }

  std::size_t slot(Index v) const
  {
    return static_cast<std::size_t>(std::lower_bound(vertices_.begin(), vertices_.end(), v) - vertices_.begin());
  }

  // Whether the shared part of `part` (marked with `stamp`) and the faces
  // `other` (of `other_at(v)` faces around v) is one path: a forest with
  // one edge fewer than vertices is a tree, and at most two shared edges
  // meet at a vertex of a disk.
  template <typename Other, typename OtherAt>
  bool shares_one_path(const std::vector<Index>& part, const Other& other, const OtherAt& other_at)
  {
    std::vector<char> shared(vertices_.size(), 0);
    std::size_t shared_vertices = 0;
    for(std::size_t i = 0; i < vertices_.size(); ++i)
      if(other_at(i) > 0)
      {
        shared[i] = 1;
        ++shared_vertices;
      }
    std::vector<std::size_t> root(vertices_.size());
    std::iota(root.begin(), root.end(), std::size_t(0));
    auto find = [&](std::size_t x) {
      while(root[x] != x)
        x = root[x] = root[root[x]];
      return x;
    };
    std::size_t shared_edges = 0;
    for(Index f : part)
      for(int i = 0; i < 3; ++i)
      {
        const Index g = m_.neighbors[f][i];
        if(g == no_index || !other(g))
          continue;
        const std::size_t a = find(slot(m_.corners[f][i])), b = find(slot(m_.corners[f][(i + 1) % 3]));
        if(a == b)
          return false;  // a cycle
        root[a] = b;
        ++shared_edges;
      }
    return shared_edges > 0 && shared_vertices == shared_edges + 1;
  }

  // Whether `patch` less its faces `part` is a disk or empty.
  bool leaves_disk(Index patch, const std::vector<Index>& part)
  {
    if(part.size() == size_[patch])
      return true;
    if(!is_local(part))
    {
      const Index stamp = next_stamp();
      for(Index f : part)
        mark_[f] = stamp;
      return patch_is_disk(patch, [&](Index f) { return mark_[f] != stamp; }, nullptr);
    }
    const Index stamp = next_stamp();
    for(Index f : part)
      mark_[f] = stamp;
    part_vertices(part);
    auto rest = [&](Index g) { return labels_[g] == patch && mark_[g] != stamp; };
    auto rest_at = [&](std::size_t i) { return faces_of_patch_at(vertices_[i], patch) - in_part_[i]; };
    if(!shares_one_path(part, rest, rest_at))
      return false;
    // The rest's fans at v: its faces less its inner edges there, which
    // are the patch's (one fan, closed when all faces at v are the
    // patch's) less those that touch the part.
    std::vector<Index> inner_edges(vertices_.size());
    for(std::size_t i = 0; i < vertices_.size(); ++i)
    {
      const Index v = vertices_[i];
      const Index all = faces_of_patch_at(v, patch);
      const bool closed = !on_mesh_border_[v] && all == faces_around_.begin[v + 1] - faces_around_.begin[v];
      inner_edges[i] = closed ? all : all - 1;
    }
    for(Index f : part)
      for(int k = 0; k < 3; ++k)
      {
        const Index g = m_.neighbors[f][k];
        if(g == no_index || labels_[g] != patch || (mark_[g] == stamp && g < f))
          continue;  // not inner, or an edge of two faces of the part seen from the other one
        --inner_edges[slot(m_.corners[f][k])];
        --inner_edges[slot(m_.corners[f][(k + 1) % 3])];
      }
    for(std::size_t i = 0; i < vertices_.size(); ++i)
    {
      const Index rest_faces = rest_at(i);
      if(rest_faces > 0 && rest_faces - inner_edges[i] >= 2)
        return false;  // a pinched vertex
    }
    return true;
  }

  // Whether `patch` plus the faces `part` (of other patches) is a disk.
  bool joins_disk(Index patch, const std::vector<Index>& part)
  {
    if(!is_local(part))
      return patch_is_disk(patch, [](Index) { return true; }, &part);
    part_vertices(part);
    return shares_one_path(part, [&](Index g) { return labels_[g] == patch; },
                           [&](std::size_t i) { return faces_of_patch_at(vertices_[i], patch); });
  }

  // The whole test: the faces of `patch` that `keep` keeps, and `extra`.
  template <typename Keep>
  bool patch_is_disk(Index patch, const Keep& keep, const std::vector<Index>* extra)
  {
    // Drop the faces that left the patch since it was listed.
    std::vector<Index>& faces = members_[patch];
    faces.erase(std::remove_if(faces.begin(), faces.end(), [&](Index f) { return labels_[f] != patch; }),
                faces.end());
    std::vector<Index> region;
    for(Index f : faces)
      if(keep(f))
        region.push_back(f);
    if(extra != nullptr)
      region.insert(region.end(), extra->begin(), extra->end());
    return region.empty() || topology_.is_disk(region);
  }

  const Indexed_triangle_mesh& m_;
  std::vector<Index>& labels_;
  Vertex_faces faces_around_;
  Region_topology topology_;
  std::vector<Index> mark_;
  Index stamp_ = 0;
  std::vector<char> counted_, on_mesh_border_;
  std::unordered_map<std::uint64_t, Index> count_;
  std::vector<std::vector<Index> > members_;
  std::vector<std::size_t> size_;
  std::vector<Index> vertices_, in_part_;  // of the part under test
};

// Keeps each group of `groups` (lists of distinct faces, tried in this
// order) in one patch of `labels` where Face_group_mover allows it. Patches
// may empty: ids are not renumbered.
inline Face_group_moves keep_face_groups_whole(const Indexed_triangle_mesh& m,
                                               const std::vector<std::vector<Index> >& groups,
                                               std::vector<Index>& labels, std::size_t max_targets = 8)
{
  Face_group_moves result;
  Face_group_mover mover(m, labels);
  for(const std::vector<Index>& group : groups)
  {
    if(group.empty())
      continue;
    const Index first = labels[group.front()];
    const bool split = std::any_of(group.begin(), group.end(), [&](Index f) { return labels[f] != first; });
    if(!split)
      continue;
    ++(mover.keep_whole(group, max_targets) ? result.moved : result.left);
  }
  return result;
}

// keep_face_groups_whole() for the polygons of the caller's mesh:
// `polygon_of[f]` is the polygon of indexed face f. Polygons are tried in
// the input order of their first face, so that the result does not depend
// on the indexed mesh's numbering; the labels are then renumbered 0..P-1 in
// input order of first face, as patches emptied by the moves leave gaps.
template <typename PolygonId>
Face_group_moves keep_polygons_whole(const Indexed_triangle_mesh& m, const std::vector<PolygonId>& polygon_of,
                                     std::vector<Index>& labels)
{
  const std::size_t n = m.number_of_faces();
  std::vector<Index> in_input_order(n);
  for(Index f = 0; f < n; ++f)
    in_input_order[m.input_position(f)] = f;
  std::vector<Index> by_polygon = in_input_order;
  std::stable_sort(by_polygon.begin(), by_polygon.end(),
                   [&](Index a, Index b) { return polygon_of[a] < polygon_of[b]; });
  std::vector<std::vector<Index> > groups;
  for(std::size_t i = 0; i < n; ++i)
  {
    if(i == 0 || polygon_of[by_polygon[i]] != polygon_of[by_polygon[i - 1]])
      groups.emplace_back();
    groups.back().push_back(by_polygon[i]);
  }
  if(groups.size() == n)
    return Face_group_moves();  // every polygon a triangle: nothing to keep whole
  std::sort(groups.begin(), groups.end(), [&](const std::vector<Index>& a, const std::vector<Index>& b) {
    return m.input_position(a.front()) < m.input_position(b.front());
  });
  const Face_group_moves moves = keep_face_groups_whole(m, groups, labels);
  std::vector<Index> renumbered(n, no_index);
  Index next = 0;
  for(Index f : in_input_order)
  {
    Index& id = renumbered[labels[f]];
    if(id == no_index)
      id = next++;
    labels[f] = id;
  }
  return moves;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_FACE_GROUP_MOVES_H
