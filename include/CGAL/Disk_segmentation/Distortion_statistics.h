// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_DISTORTION_STATISTICS_H
#define CGAL_DISK_SEGMENTATION_DISTORTION_STATISTICS_H

#include <CGAL/disable_warnings.h>



namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// Area-weighted statistics of one per-triangle distortion measure.
struct Distortion_statistics
{
  /// Area-weighted mean.
  double mean = 0;
  /// Area-weighted 95th percentile: 95% of the surface has at most this distortion.
  double percentile_95 = 0;
  /// Largest value over the measured triangles.
  double max = 0;
};

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_DISTORTION_STATISTICS_H
