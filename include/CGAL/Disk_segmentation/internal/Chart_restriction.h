// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_RESTRICTION_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_RESTRICTION_H

#include <CGAL/Disk_segmentation/internal/Chart_parameterization.h>
#include <CGAL/Disk_segmentation/internal/Indexed_triangle_mesh.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// The border of a chart that is a disk, as one cycle of local vertices in
// the orientation of its triangles; empty if the border edges do not form
// one cycle through distinct vertices.
inline std::vector<Index> chart_border_loop(const Chart& c)
{
  std::vector<std::pair<Index, Index> > edges;  // directed, as the triangles give them
  edges.reserve(3 * c.triangles.size());
  for(const auto& t : c.triangles)
    for(int i = 0; i < 3; ++i)
      edges.emplace_back(t[i], t[(i + 1) % 3]);
  std::vector<std::pair<Index, Index> > sorted = edges;
  std::sort(sorted.begin(), sorted.end());
  std::vector<Index> next(c.vertices.size(), no_index);
  std::size_t border_edges = 0;
  Index start = no_index;
  for(const auto& e : edges)
    if(!std::binary_search(sorted.begin(), sorted.end(), std::make_pair(e.second, e.first)))
    {
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

// Gives chart `c` (a sub-disk of `parent`) the UVs that `parent` has at its
// vertices. An injective map restricted to a sub-disk is still injective,
// so a valid parent gives a valid child at no solver cost; the result is
// still validated. `slot` is scratch of the mesh's vertex count, all
// no_index, and left so. Returns what is wrong with the child's UVs, or an
// empty string.
inline std::string restrict_chart(const Chart& parent, Chart& c, std::vector<Index>& slot)
{
  for(Index i = 0; i < parent.vertices.size(); ++i)
    slot[parent.vertices[i]] = i;
  c.uv.assign(c.vertices.size(), {{ 0., 0. }});
  bool inside = true;
  for(Index i = 0; i < c.vertices.size(); ++i)
  {
    const Index p = slot[c.vertices[i]];
    if(p == no_index)
      inside = false;
    else
      c.uv[i] = parent.uv[p];
  }
  for(Index v : parent.vertices)
    slot[v] = no_index;
  if(!inside)
    return "not a part of its parent";
  const std::vector<Index> border = chart_border_loop(c);
  if(border.empty())
    return "chart is not a disk";
  return chart_uv_problem(c, c.uv, border);
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_RESTRICTION_H
