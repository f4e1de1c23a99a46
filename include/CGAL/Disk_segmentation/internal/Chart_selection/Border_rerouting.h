// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_BORDER_REROUTING_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_BORDER_REROUTING_H

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_topology.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Vertex_faces.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <queue>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// A maximal path of edges between two regions `a` and `b`, from one
// junction vertex to another (a vertex on a third region, on the mesh's
// border, or where the border branches).
struct Border_arc
{
  Index a = no_index, b = no_index;
  std::vector<Index> vertices;
  double length = 0.;
};

// A rerouted arc: the faces that changed region, and the region each had.
struct Arc_change
{
  Index a = no_index, b = no_index;
  std::vector<std::pair<Index, Index> > old_labels;
};

// Straightens the borders between disk regions: each arc is replaced by a
// shorter edge path between its two ends, near it, inside the union of its
// two regions (see shortest_path()), and the faces between the old and the
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
    : m_(m), vertex_faces_(m), distance_(m.number_of_vertices(), 0.), length_(m.number_of_vertices(), 0.),
      previous_(m.number_of_vertices(), no_index), vertex_stamp_(m.number_of_vertices(), 0),
      band_stamp_(m.number_of_vertices(), 0), face_stamp_(m.number_of_faces(), 0),
      edge_mark_stamp_(m.number_of_faces(), 0), edge_marks_(m.number_of_faces(), 0), side_(m.number_of_faces(), 0)
  {}

  static constexpr std::size_t smallest_region = 3;
  static constexpr int band_rings = 2;
  static constexpr double crease_weight = 4.;

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

  // The arcs between regions given by `labels` (per face; `no_index` for
  // faces that belong to none), in a deterministic order. Closed borders
  // without a junction are left out: they have no ends to join.
  std::vector<Border_arc> arcs(const std::vector<Index>& labels) const
  {
    const std::size_t nv = m_.number_of_vertices();
    // Edges between two labeled regions, per vertex.
    std::vector<Index> begin(nv + 1, 0);
    for(Index f = 0; f < m_.number_of_faces(); ++f)
      for(int e = 0; e < 3; ++e)
        if(separates(labels, f, e))
        {
          ++begin[m_.corners[f][e] + 1];
          ++begin[m_.corners[f][(e + 1) % 3] + 1];
        }
    for(std::size_t v = 0; v < nv; ++v)
      begin[v + 1] += begin[v];
    std::vector<Index> other(begin[nv]), fill(begin.begin(), begin.end() - 1);
    for(Index f = 0; f < m_.number_of_faces(); ++f)
      for(int e = 0; e < 3; ++e)
        if(separates(labels, f, e))
        {
          const Index u = m_.corners[f][e], w = m_.corners[f][(e + 1) % 3];
          other[fill[u]++] = w;
          other[fill[w]++] = u;
        }
    // A border vertex is a junction unless it has exactly two border edges
    // and only the two regions around it.
    std::vector<char> junction(nv, 0);
    for(Index v = 0; v < nv; ++v)
    {
      const Index border_edges = begin[v + 1] - begin[v];
      junction[v] = border_edges != 0 && (border_edges != 2 || !inside_two_regions(labels, v)) ? 1 : 0;
    }

    std::vector<Border_arc> result;
    std::unordered_set<std::uint64_t> walked;
    for(Index s = 0; s < nv; ++s)
    {
      if(!junction[s] || begin[s] == begin[s + 1])
        continue;
      for(Index k = begin[s]; k < begin[s + 1]; ++k)
      {
        Index from = s, to = other[k];
        if(walked.count(edge_key(from, to)) != 0)
          continue;
        Border_arc arc;
        regions_of_edge(labels, from, to, arc.a, arc.b);
        arc.vertices.push_back(from);
        for(;;)
        {
          walked.insert(edge_key(from, to));
          arc.length += Indexed_triangle_mesh::distance(m_.points[from], m_.points[to]);
          arc.vertices.push_back(to);
          if(junction[to])
            break;
          const Index next = other[begin[to]] == from ? other[begin[to] + 1] : other[begin[to]];
          from = to;
          to = next;
        }
        if(arc.vertices.front() != arc.vertices.back() && arc.a != no_index && arc.b != no_index)
          result.push_back(std::move(arc));
      }
    }
    return result;
  }

  // Replaces `arc` by the cheapest path between its ends (shortest_path())
  // if that is shorter by more than `least_gain` (a fraction of the arc's
  // length) and costs less, the faces in between changing sides, when both
  // regions stay disks of `smallest_region` faces or more and no face in
  // `locked` (per face, non-zero: keep) would change. `size` holds the
  // number of faces of each region and is updated. On success, `change`
  // says which faces moved.
  bool reroute(std::vector<Index>& labels, std::vector<std::size_t>& size, const std::vector<char>& locked,
               Region_topology& topology, const Border_arc& arc, double least_gain, Arc_change& change)
  {
    const Index a = arc.a, b = arc.b;
    if(size[a] < smallest_region || size[b] < smallest_region)
      return false;
    std::vector<Index> path;
    if(!shortest_path(labels, arc, (1. - least_gain) * arc.length, path))
      return false;
    // Two disks that share one arc and no other vertex make a disk, which a
    // path inside it between two points of its border cuts into two disks:
    // only the faces between the old arc and the new path change sides, and
    // neither the union nor the disk tests need to be visited (they took
    // 0.1 s of the 0.25 s of serial rerouting on refined_elephant x4; the
    // same faces move on 35 meshes, checked against the flood below).
    if(shared_vertices(a, b) == arc.vertices.size())
    {
      std::size_t size_a = 0, size_b = 0;
      const Local_result local = flip_between(labels, size, arc, path, locked, change, size_a, size_b);
      if(local == Local_result::refused)
        return false;
      if(local == Local_result::done)
      {
        apply(labels, change);
        size[a] = size_a;
        size[b] = size_b;
        return true;
      }
    }

    // Faces of the two regions on each side of the new path: reached from
    // the union's border without crossing the new path or any other edge
    // between a and b (the old arc's edges may be crossed).
    const std::uint32_t stamp = next_face_stamp();
    for(std::size_t i = 0; i + 1 < path.size(); ++i)
      mark_edge(path[i], path[i + 1], barrier_edge, stamp);
    for(std::size_t i = 0; i + 1 < arc.vertices.size(); ++i)
      mark_edge(arc.vertices[i], arc.vertices[i + 1], old_arc_edge, stamp);
    std::vector<Index> queue, faces_ab;
    auto in_union = [&](Index g) { return g != no_index && (labels[g] == a || labels[g] == b); };
    for(Index f : region_faces(labels, a, b))
    {
      faces_ab.push_back(f);
      for(int e = 0; e < 3; ++e)
        if(!in_union(m_.neighbors[f][e]))
        {
          face_stamp_[f] = stamp;
          side_[f] = labels[f] == a ? 1 : 2;
          queue.push_back(f);
          break;
        }
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
    std::size_t size_a = 0;
    for(Index f : faces_ab)
    {
      const Index now = side_[f] == 1 ? a : b;
      size_a += side_[f] == 1 ? 1 : 0;
      if(now != labels[f])
      {
        if(locked[f])
          return false;
        change.old_labels.emplace_back(f, labels[f]);
      }
    }
    const std::size_t size_b = faces_ab.size() - size_a;
    if(change.old_labels.empty() || size_a < smallest_region || size_b < smallest_region)
      return false;
    std::vector<Index> new_a, new_b;  // sorted, as faces_ab is
    for(Index f : faces_ab)
      (side_[f] == 1 ? new_a : new_b).push_back(f);
    if(!topology.is_disk(new_a) || !topology.is_disk(new_b))
      return false;
    apply(labels, change);
    size[a] = size_a;
    size[b] = size_b;
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
  // Edges of the new path and of the old arc, marked on their faces for the
  // flood fill (bit e, or e + 3, of a face for its edge e).
  static constexpr int barrier_edge = 0, old_arc_edge = 3;

  enum class Local_result { done, refused, undecided };

  static std::uint64_t pair_key(Index a, Index b) { return edge_key(a, b); }

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
    for(Index k = vertex_faces_.begin[v]; k < vertex_faces_.begin[v + 1]; ++k)
    {
      const Index l = labels[vertex_faces_.faces[k]];
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
    const std::uint32_t stamp = next_vertex_stamp();
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

  // The faces f on the left (counterclockwise) and g on the right of the
  // edge from u to w: false on the mesh's border or if it is no edge.
  bool directed_faces(Index u, Index w, Index& f, Index& g) const
  {
    for(Index k = vertex_faces_.begin[u]; k < vertex_faces_.begin[u + 1]; ++k)
    {
      f = vertex_faces_.faces[k];
      for(int e = 0; e < 3; ++e)
        if(m_.corners[f][e] == u && m_.corners[f][(e + 1) % 3] == w)
        {
          g = m_.neighbors[f][e];
          return g != no_index;
        }
    }
    return false;
  }

  // The faces between the old arc and the new path, found from the new
  // path's two sides: a face on the left of the path must take the region
  // on the left of the arc, and faces of its region reached from it without
  // crossing the path or the arc take it too (the pockets between the two).
  // `undecided` when a pocket reaches the union's border or a face both
  // sides claim: the union was not the disk its shared vertices said, and
  // the whole union is flooded instead.
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
      if(!directed_faces(arc.vertices[0], arc.vertices[1], f, g))
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
      if(!directed_faces(path[i], path[i + 1], f, g) || !in_union(f) || !in_union(g) || !claim(f, 1) || !claim(g, 2))
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
    if(size_a < smallest_region || size_b < smallest_region)
      return Local_result::refused;
    return Local_result::done;
  }

  void mark_edge(Index u, Index w, int kind, std::uint32_t stamp)
  {
    const std::uint64_t key = edge_key(u, w);
    for(Index k = vertex_faces_.begin[u]; k < vertex_faces_.begin[u + 1]; ++k)
    {
      const Index f = vertex_faces_.faces[k];
      for(int e = 0; e < 3; ++e)
        if(edge_key(m_.corners[f][e], m_.corners[f][(e + 1) % 3]) == key)
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

  static std::uint64_t edge_key(Index u, Index w)
  {
    return u < w ? (std::uint64_t(u) << 32 | w) : (std::uint64_t(w) << 32 | u);
  }

  // Whether edge e of f lies between two different labeled regions (seen
  // from the face of smaller index only).
  bool separates(const std::vector<Index>& labels, Index f, int e) const
  {
    const Index g = m_.neighbors[f][e];
    return g != no_index && f < g && labels[f] != no_index && labels[g] != no_index && labels[f] != labels[g];
  }

  // Whether every face around v belongs to one of at most two regions (all
  // labeled) and v is not on the mesh's border.
  bool inside_two_regions(const std::vector<Index>& labels, Index v) const
  {
    Index first = no_index, second = no_index;
    for(Index k = vertex_faces_.begin[v]; k < vertex_faces_.begin[v + 1]; ++k)
    {
      const Index f = vertex_faces_.faces[k];
      const Index l = labels[f];
      if(l == no_index || on_mesh_border_at(f, v))
        return false;
      if(l == first || l == second)
        continue;
      if(first == no_index)
        first = l;
      else if(second == no_index)
        second = l;
      else
        return false;
    }
    return true;
  }

  // Whether f has a border edge of the mesh at its corner v.
  bool on_mesh_border_at(Index f, Index v) const
  {
    for(int e = 0; e < 3; ++e)
      if(m_.neighbors[f][e] == no_index && (m_.corners[f][e] == v || m_.corners[f][(e + 1) % 3] == v))
        return true;
    return false;
  }

  // The faces on both sides of the edge (u, w): false if it has only one
  // (on the mesh's border) or is not an edge.
  bool faces_of_edge(Index u, Index w, Index& f, Index& g) const
  {
    return directed_faces(u, w, f, g) || directed_faces(w, u, f, g);
  }

  // The regions on both sides of the edge (u, w), smaller first.
  void regions_of_edge(const std::vector<Index>& labels, Index u, Index w, Index& a, Index& b) const
  {
    a = b = no_index;
    Index f, g;
    if(!faces_of_edge(u, w, f, g))
      return;
    a = (std::min)(labels[f], labels[g]);
    b = (std::max)(labels[f], labels[g]);
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

  std::array<double, 3> unit_normal(Index f) const
  {
    const std::array<double, 3>& p = m_.point(f, 0);
    const std::array<double, 3>& q = m_.point(f, 1);
    const std::array<double, 3>& r = m_.point(f, 2);
    const double u[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] }, v[3] = { r[0] - p[0], r[1] - p[1], r[2] - p[2] };
    std::array<double, 3> n = {{ u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] }};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if(length > 0)
      for(double& x : n)
        x /= length;
    return n;
  }

  // The cost of a border along an edge of the given length between faces f
  // and g: its length, less where the surface bends. A border on a crease
  // costs the charts nothing, and a path that leaves one to cut a corner
  // hands faces across the crease to the other chart, which then breaks the
  // bound. Measured on the 23 shipped meshes (cut length summed, median UV
  // area): plain length 424.7 and 0.588, crease_weight 4 422.0 and 0.592,
  // 16 422.9 and 0.602, 64 424.4 and 0.573.
  double edge_cost(Index f, Index g, double length) const
  {
    const std::array<double, 3> nf = unit_normal(f), ng = unit_normal(g);
    const double cosine = nf[0] * ng[0] + nf[1] * ng[1] + nf[2] * ng[2];
    return length / (1. + crease_weight * (1. - cosine));
  }

  // The cost of the arc as it is.
  double arc_cost(const Border_arc& arc) const
  {
    double cost = 0.;
    for(std::size_t i = 0; i + 1 < arc.vertices.size(); ++i)
    {
      const Index u = arc.vertices[i], w = arc.vertices[i + 1];
      Index f, g;
      if(faces_of_edge(u, w, f, g))
        cost += edge_cost(f, g, Indexed_triangle_mesh::distance(m_.points[u], m_.points[w]));
    }
    return cost;
  }

  // Dijkstra by edge_cost() from one end of the arc to the other, over
  // edges inside the union of its two regions whose inner vertices touch no
  // other region and lie in the band around the arc (mark_band()). Paths
  // are pruned by their length plus the straight line to the far end: only
  // those shorter than `bound` matter. Fails unless the path found costs
  // less than the arc.
  bool shortest_path(const std::vector<Index>& labels, const Border_arc& arc, double bound, std::vector<Index>& path)
  {
    const Index s = arc.vertices.front(), t = arc.vertices.back(), a = arc.a, b = arc.b;
    const std::uint32_t band = mark_band(labels, arc);
    const std::uint32_t stamp = next_vertex_stamp();
    typedef std::pair<double, Index> Entry;  // cost so far, vertex
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > open;
    auto straight = [&](Index v) { return Indexed_triangle_mesh::distance(m_.points[v], m_.points[t]); };
    distance_[s] = 0.;
    length_[s] = 0.;
    previous_[s] = no_index;
    vertex_stamp_[s] = stamp;
    open.emplace(0., s);
    bool reached = false;
    while(!open.empty())
    {
      const Entry top = open.top();
      open.pop();
      const Index v = top.second;
      if(top.first > distance_[v])
        continue;  // a stale entry
      if(v == t)
      {
        reached = true;
        break;
      }
      if(v != s && !inside_two_regions_of(labels, v, a, b))
        continue;
      for(Index k = vertex_faces_.begin[v]; k < vertex_faces_.begin[v + 1]; ++k)
      {
        const Index f = vertex_faces_.faces[k];
        if(labels[f] != a && labels[f] != b)
          continue;
        for(int e = 0; e < 3; ++e)
        {
          const Index u = m_.corners[f][e], w = m_.corners[f][(e + 1) % 3];
          if(u != v && w != v)
            continue;
          const Index g = m_.neighbors[f][e];
          if(g == no_index || (labels[g] != a && labels[g] != b))
            continue;  // the edge itself must lie inside the union
          const Index x = u == v ? w : u;
          if(band_stamp_[x] != band)
            continue;
          const double len = Indexed_triangle_mesh::distance(m_.points[v], m_.points[x]);
          const double l = length_[v] + len;
          if(!(l + straight(x) < bound))
            continue;
          const double d = distance_[v] + edge_cost(f, g, len);
          if(vertex_stamp_[x] == stamp && !(d < distance_[x]))
            continue;
          vertex_stamp_[x] = stamp;
          distance_[x] = d;
          length_[x] = l;
          previous_[x] = v;
          open.emplace(d, x);
        }
      }
    }
    if(!reached || !(distance_[t] < arc_cost(arc)))
      return false;
    path.clear();
    for(Index v = t; v != no_index; v = previous_[v])
      path.push_back(v);
    std::reverse(path.begin(), path.end());
    return true;
  }

  // Marks the vertices at most `band_rings` edges (inside the union of the
  // arc's two regions) from the arc: the new path stays in that band, so
  // that rerouting removes steps without moving a border off the crease or
  // the change of curvature the segmentation put it on. Returns the mark.
  std::uint32_t mark_band(const std::vector<Index>& labels, const Border_arc& arc)
  {
    if(++band_clock_ == 0)
    {
      std::fill(band_stamp_.begin(), band_stamp_.end(), 0);
      band_clock_ = 1;
    }
    const std::uint32_t mark = band_clock_;
    std::vector<Index> ring(arc.vertices), next;
    for(Index v : ring)
      band_stamp_[v] = mark;
    for(int r = 0; r < band_rings; ++r)
    {
      next.clear();
      for(Index v : ring)
        for(Index k = vertex_faces_.begin[v]; k < vertex_faces_.begin[v + 1]; ++k)
        {
          const Index f = vertex_faces_.faces[k];
          if(labels[f] != arc.a && labels[f] != arc.b)
            continue;
          for(Index x : m_.corners[f])
            if(band_stamp_[x] != mark)
            {
              band_stamp_[x] = mark;
              next.push_back(x);
            }
        }
      ring.swap(next);
    }
    return mark;
  }

  bool inside_two_regions_of(const std::vector<Index>& labels, Index v, Index a, Index b) const
  {
    for(Index k = vertex_faces_.begin[v]; k < vertex_faces_.begin[v + 1]; ++k)
    {
      const Index f = vertex_faces_.faces[k];
      if((labels[f] != a && labels[f] != b) || on_mesh_border_at(f, v))
        return false;
    }
    return true;
  }

  std::uint32_t next_vertex_stamp()
  {
    if(++vertex_clock_ == 0)
    {
      std::fill(vertex_stamp_.begin(), vertex_stamp_.end(), 0);
      vertex_clock_ = 1;
    }
    return vertex_clock_;
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
  Vertex_faces vertex_faces_;
  std::vector<double> distance_, length_;
  std::vector<Index> previous_;
  std::vector<std::uint32_t> vertex_stamp_, band_stamp_, face_stamp_, edge_mark_stamp_;
  std::vector<unsigned char> edge_marks_;
  std::uint32_t vertex_clock_ = 0, band_clock_ = 0, face_clock_ = 0;
  std::vector<unsigned char> side_;
  std::vector<std::vector<Index> > members_;
  std::unordered_map<std::uint64_t, std::ptrdiff_t> shared_vertices_;  // per pair of regions (pair_key())
  std::vector<Index> around_;  // scratch of count_pairs_around()
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_BORDER_REROUTING_H
