// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Gives a sub-disk of a parameterized chart the UVs its parent has:
// a valid map for it at no solver cost.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_RESTRICTION_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_RESTRICTION_H

#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_parameterization.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_slots.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Gives chart `c` (a sub-disk of `parent`) the UVs that `parent` has at its
// vertices. An injective map restricted to a sub-disk is still injective,
// so a valid parent gives a valid child at no solver cost; the result is
// still validated. `parent_vertices` is scratch. Returns what is wrong with
// the child's UVs, or an empty string.
inline std::string restrict_chart(const Chart& parent, Chart& c, Region_slots& parent_vertices)
{
  // The parent's vertices are distinct: each gets its own local index.
  parent_vertices.clear_for_keys(parent.vertices);
  for(Index v : parent.vertices)
    parent_vertices.insert(v);
  c.uv.assign(c.vertices.size(), {{ 0., 0. }});
  bool inside = true;
  for(Index i = 0; i < c.vertices.size(); ++i)
  {
    const Index p = parent_vertices.find(c.vertices[i]);
    if(p == no_index)
      inside = false;
    else
      c.uv[i] = parent.uv[p];
  }
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

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_RESTRICTION_H
