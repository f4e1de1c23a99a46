// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_ATLAS_REPORT_H
#define CGAL_DISK_SEGMENTATION_ATLAS_REPORT_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Packing_report.h>
#include <CGAL/Disk_segmentation/Parameterization_report.h>

#include <cstddef>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// What `uv_atlas()` did, stage by stage. Times are wall-clock seconds.
struct Atlas_report
{
  /// Number of faces of the mesh.
  std::size_t number_of_faces = 0;
  /// Voronoi cells (at least the number of connected components).
  std::size_t number_of_voronoi_cells = 0;
  /// Disks after refinement, before merging.
  std::size_t number_of_refined_regions = 0;
  /// Charts of the atlas (patches after merging, plus pieces of split patches).
  std::size_t number_of_charts = 0;
  /// Per-chart methods, fallbacks and distortion.
  Parameterization_report parameterization;
  /// Packing efficiency and texel density.
  Packing_report packing;
  /// With `face_polygon_map`: polygons split by the charts and moved whole into one of them,
  /// and those left across charts (a move would have left a chart that is not a disk).
  std::size_t polygons_moved_whole = 0, polygons_left_across_charts = 0;

  double voronoi_seconds = 0, refine_seconds = 0, merge_seconds = 0;
  double parameterization_seconds = 0, packing_seconds = 0, total_seconds = 0;

  /// How many times a face was solved on average (`Parameterization_report::solved_faces` per
  /// face of the mesh; 0 without faces).
  double solves_per_face() const
  {
    return number_of_faces == 0 ? 0. : double(parameterization.solved_faces) / double(number_of_faces);
  }
};

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_ATLAS_REPORT_H
