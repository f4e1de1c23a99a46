// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_MULTI_MESH_ATLAS_REPORT_H
#define CGAL_DISK_SEGMENTATION_MULTI_MESH_ATLAS_REPORT_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Atlas_report.h>
#include <CGAL/Disk_segmentation/Packing_report.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// What `uv_atlas_of_meshes()` did.
struct Multi_mesh_atlas_report
{
  /// Per mesh, in the order given: its segmentation and parameterization, as `uv_atlas()` reports
  /// them for that mesh alone (its `packing` field is left empty).
  std::vector<Atlas_report> meshes;
  /// Per mesh, the id of its first chart: the charts of mesh `i` are numbered from
  /// `first_chart[i]` to `first_chart[i + 1] - 1` (one more entry than meshes).
  std::vector<std::size_t> first_chart;
  /// The packing of all charts together.
  Packing_report packing;
  double packing_seconds = 0, total_seconds = 0;
};

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_MULTI_MESH_ATLAS_REPORT_H
