// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_PARAMETERIZATION_REPORT_H
#define CGAL_DISK_SEGMENTATION_PARAMETERIZATION_REPORT_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Parameterization_method.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// What happened to one chart in `parameterize_patches()`.
struct Chart_report
{
  /// Patch id of the chart (after splits, see `split`).
  std::size_t patch = 0;
  /// Number of faces of the chart.
  std::size_t faces = 0;
  /// Method asked for.
  Parameterization_method requested = Parameterization_method::LSCM;
  /// Method whose result was kept.
  Parameterization_method used = Parameterization_method::LSCM;
  /// `true` if `used` differs from `requested` because the requested result was invalid.
  bool fallback = false;
  /// `true` if the chart is a piece of a patch that was split (no method gave a valid chart,
  /// it exceeded the distortion bound, or it had more than `max_chart_faces` faces).
  bool split = false;
  /// `true` if the chart's UVs are valid (finite, no flipped or degenerate triangle, simple border).
  bool valid = false;
  /// `true` if the requested method itself failed (solver error, no border, non-manifold chart,
  /// non-finite UVs) rather than returning a map with flipped triangles or an overlapping border.
  bool method_error = false;
  /// Why the requested method's result was rejected; empty if it was kept.
  std::string problem;
  /// Area-weighted mean of |log(s1/s2)| over the chart (0 for an isometry).
  double angle_distortion = 0;
  /// Area-weighted mean of |log(s1 s2)| with the chart scaled to its 3D area (0 for an isometry).
  double area_distortion = 0;
  /// Largest s1/s2 of a triangle of the chart.
  double max_stretch = 1;
  /// Smallest and largest s1 s2 of a triangle, the chart scaled to its 3D area.
  double min_area_scale = 1, max_area_scale = 1;
  /// 95th percentile of s1/s2 over the chart's triangles.
  double stretch_p95 = 1;
};

/// \ingroup PkgDiskSegmentationRef
/// Summary of `parameterize_patches()`.
struct Parameterization_report
{
  /// One entry per chart, by patch id.
  std::vector<Chart_report> charts;
  /// Charts that needed a fallback method.
  std::size_t number_of_fallbacks = 0;
  /// Patches split because no method gave a valid chart, or because of their area distortion or size.
  std::size_t number_of_split_patches = 0;
  /// Charts left invalid (only possible with `use_fallback(false)`).
  std::size_t number_of_invalid_charts = 0;
  /// Charts where the requested method itself failed (see `Chart_report::method_error`),
  /// whether or not a fallback then repaired them.
  std::size_t number_of_method_errors = 0;
  /// With `max_number_of_charts`: how many charts there were under the distortion bound before
  /// merges brought them down to the budget (0 when they were within it).
  std::size_t charts_before_budget = 0;
  /// `false` when the charts are more than `max_number_of_charts`: no two adjacent charts have a
  /// union that is a disk with a valid map (and at most `max_chart_faces` faces).
  bool chart_budget_met = true;
  /// What choosing the charts cost: each time a method ran on a chart (a
  /// patch or a piece of one, a union a merge tried, a chart a rerouted
  /// border changed, a fallback; the tries that were rejected too), that
  /// chart's faces. Divided by the number of faces of the mesh: how many
  /// times a face was solved (1 when every patch is solved once and kept).
  std::size_t solved_faces = 0;
  /// Of `solved_faces`, those of the unions that merges tried (`merge_charts`, the chart budget).
  std::size_t solved_faces_in_merges = 0;
  /// Of `solved_faces`, those of the charts that rerouted borders changed (`straighten_borders`).
  std::size_t solved_faces_in_reroutes = 0;
  /// How many times a method ran on a chart (the charts counted in `solved_faces`).
  std::size_t number_of_solves = 0;
};

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_PARAMETERIZATION_REPORT_H
