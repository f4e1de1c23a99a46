// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A chart: faces of the indexed mesh with their own vertex numbering and
// UVs, built from a list of faces; and the loop of its border.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_H

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_slots.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// One chart cut out of the indexed mesh, with its own vertex numbering so that
// charts can be parameterized independently (and in parallel).
struct Chart
{
  std::vector<Index> faces;                     // faces of the indexed mesh
  std::vector<Index> vertices;                  // local vertex -> indexed-mesh vertex
  std::vector<std::array<Index, 3> > triangles; // local corners of each face
  std::vector<std::array<double, 2> > uv;       // local vertex -> UV
  // Its indexed-mesh vertices in the order the solvers eliminate them:
  // recorded when the chart is first solved, or inherited from the charts
  // it was built from (see Inherited_elimination_order.h); empty until then.
  std::vector<Index> elimination_order;
};

// Per-thread local numbering of the vertices of a chart being built or
// read, sized to the chart (a mesh-sized array per thread grew with mesh
// size times threads; std::unordered_map was 1 % of the time).
inline Region_slots& chart_vertex_slots()
{
  thread_local Region_slots slots;
  return slots;
}

// Local vertices are numbered as first met.
inline Chart make_chart(const Indexed_triangle_mesh& m, const std::vector<Index>& faces)
{
  Region_slots& slots = chart_vertex_slots();
  slots.clear_for_corners(m, faces);
  Chart c;
  c.faces = faces;
  c.triangles.reserve(faces.size());
  for(Index f : faces)
  {
    std::array<Index, 3> t;
    for(int i = 0; i < 3; ++i)
    {
      t[i] = slots.insert(m.corners[f][i]);
      if(t[i] == c.vertices.size())
        c.vertices.push_back(m.corners[f][i]);
    }
    c.triangles.push_back(t);
  }
  return c;
}

// The border of a chart that is a disk, as one cycle of local vertices in
// the orientation of its triangles; empty if the border edges do not form
// one cycle through distinct vertices.
inline std::vector<Index> chart_border_loop(const Chart& c)
{
  // Directed edges as the triangles give them, grouped by their source
  // (counting sort): an edge is on the border when its reverse is not
  // among the edges out of its target.
  const std::size_t nv = c.vertices.size();
  std::vector<std::size_t> first(nv + 1, 0);
  for(const auto& t : c.triangles)
    for(int i = 0; i < 3; ++i)
      ++first[t[i] + 1];
  for(std::size_t v = 0; v < nv; ++v)
    first[v + 1] += first[v];
  std::vector<Index> out(first[nv]);
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(const auto& t : c.triangles)
      for(int i = 0; i < 3; ++i)
        out[fill[t[i]]++] = t[(i + 1) % 3];
  }
  // The edges out of a vertex of high valence are sorted and searched in
  // halves (looking each up in turn was quadratic there); the few out of
  // any other vertex are scanned.
  const std::size_t few = 16;
  for(std::size_t v = 0; v < nv; ++v)
    if(first[v + 1] - first[v] > few)
      std::sort(out.begin() + first[v], out.begin() + first[v + 1]);
  auto has_edge = [&](Index a, Index b) {
    const auto begin = out.begin() + first[a], end = out.begin() + first[a + 1];
    return end - begin > std::ptrdiff_t(few) ? std::binary_search(begin, end, b) : std::find(begin, end, b) != end;
  };
  std::vector<Index> next(nv, no_index);
  std::size_t border_edges = 0;
  Index start = no_index;
  for(const auto& t : c.triangles)
    for(int i = 0; i < 3; ++i)
    {
      const std::pair<Index, Index> e(t[i], t[(i + 1) % 3]);
      if(has_edge(e.second, e.first))
        continue;
      if(next[e.first] != no_index)
        return std::vector<Index>();  // a vertex on the border twice
      next[e.first] = e.second;
      ++border_edges;
      start = e.first;
    }
  std::vector<Index> loop;
  if(start == no_index)
    return loop;
  // Ends: each step follows a distinct border edge, at most border_edges.
  Index v = start;
  do
  {
    loop.push_back(v);
    v = next[v];
  } while(v != no_index && v != start && loop.size() <= border_edges);
  if(v != start || loop.size() != border_edges)
    return std::vector<Index>();
  return loop;
}

typedef std::vector<std::array<double, 2> > Chart_uv;

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_H
