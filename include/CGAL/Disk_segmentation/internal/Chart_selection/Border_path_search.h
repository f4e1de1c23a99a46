// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cheapest edge path that could replace a border arc: Dijkstra inside
// the arc's two regions, near the arc, with creases made cheap.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_BORDER_PATH_SEARCH_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_BORDER_PATH_SEARCH_H

#include <CGAL/Disk_segmentation/internal/Chart_selection/Border_arcs.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Round_stamps.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Vertex_faces.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Searches the path that replaces a border arc: the cheapest edge path
// between its ends, near it and inside its two regions (shortest_path()).
// Keeps its per-vertex arrays from one search to the next.
class Border_path_search
{
public:
  explicit Border_path_search(const Region_borders& borders)
    : m_(borders.mesh()), borders_(borders), vertex_faces_(borders.vertex_faces()),
      distance_(m_.number_of_vertices(), 0.), length_(m_.number_of_vertices(), 0.),
      previous_(m_.number_of_vertices(), no_index), vertex_stamp_(m_.number_of_vertices()),
      band_stamp_(m_.number_of_vertices())
  {}

  static constexpr int band_rings = 2;
  static constexpr double crease_weight = 4.;

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
    const std::uint32_t stamp = vertex_stamp_.next_round();
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

private:
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
      if(borders_.faces_of_edge(u, w, f, g))
        cost += edge_cost(f, g, Indexed_triangle_mesh::distance(m_.points[u], m_.points[w]));
    }
    return cost;
  }

  // Marks the vertices at most `band_rings` edges (inside the union of the
  // arc's two regions) from the arc: the new path stays in that band, so
  // that rerouting removes steps without moving a border off the crease or
  // the change of curvature the segmentation put it on. Returns the mark.
  std::uint32_t mark_band(const std::vector<Index>& labels, const Border_arc& arc)
  {
    const std::uint32_t mark = band_stamp_.next_round();
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
      if((labels[f] != a && labels[f] != b) || borders_.on_mesh_border_at(f, v))
        return false;
    }
    return true;
  }

  const Indexed_triangle_mesh& m_;
  const Region_borders& borders_;
  const Vertex_faces& vertex_faces_;
  std::vector<double> distance_, length_;
  std::vector<Index> previous_;
  Round_stamps vertex_stamp_, band_stamp_;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_BORDER_PATH_SEARCH_H
