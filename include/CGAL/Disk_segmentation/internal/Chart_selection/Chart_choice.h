// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every choice of a chart in one call shares: the mesh, the method,
// the fallbacks and the rule that says when a chart is split.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_CHOICE_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_CHOICE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_methods.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_method_chain.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_parameterization.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_warm_start.h>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// What every choice of a chart in one call shares, whether the chart comes
// from the merge tree, a split, a merge or a rerouted border: the mesh, the
// method asked for, whether the fallbacks run, the rule that says when a
// chart is replaced by smaller ones (Split_rule) and that rule's early look
// at ARAP's iterations; and what the solves cost.
template <typename Rule>
struct Chart_choice
{
  const Indexed_triangle_mesh& mesh;
  const Chart_method& method;
  bool use_fallback;
  const Rule& needs_split;
  Arap_early_look early_look;
  mutable Solve_tally tally;

  Chart_choice(const Indexed_triangle_mesh& m, const Chart_method& requested, bool fallback, const Rule& rule)
    : mesh(m), method(requested), use_fallback(fallback), needs_split(rule), early_look(rule.early_look())
  {}

  // The requested method on `c` (from `start`, the glued maps of a union,
  // where one is given and the method starts from a map), then the
  // fallbacks; counted in `tally`.
  Chart_outcome solve(Chart& c, On_invalid_map on_invalid, Early_look* look, const Chart_uv* start = nullptr) const
  {
    return parameterize_chart_from(mesh, c, method, use_fallback, start, on_invalid, look, tally);
  }
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_CHOICE_H
