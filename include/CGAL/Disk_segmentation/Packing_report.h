// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_PACKING_REPORT_H
#define CGAL_DISK_SEGMENTATION_PACKING_REPORT_H

#include <CGAL/disable_warnings.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// What `pack_patches()` did.
struct Packing_report
{
  /// Number of charts (patches) placed.
  std::size_t number_of_charts = 0;
  /// Sum of the UV areas of all faces after packing over the number of
  /// pages, i.e. the covered fraction of a page, on the mean (in `[0, 1]`).
  double efficiency = 0;
  /// `Packing_method::TIGHT`: texels of the target texture per unit of 3D
  /// length, the same for all charts (the `texels_per_unit` parameter when
  /// it is given). `Packing_method::GRID`: 0.
  double texels_per_unit = 0;
  /// Number of pages (textures of `texture_resolution` texels) the charts
  /// fill: 1 unless `texels_per_unit` is given.
  std::size_t number_of_pages = 0;
  /// The page of every chart (patch id), in `[0, number_of_pages)`; each
  /// chart lies whole in the unit square of its page.
  std::vector<std::size_t> page_of_chart;
  /// Per page, the covered fraction of its square.
  std::vector<double> page_efficiency;
  /// Charts whose longest side is shorter than one texel of the texture
  /// (e.g. the charts of a tiny mesh packed with huge ones, or a low
  /// `texels_per_unit`): they hold no texel of their own.
  std::size_t number_of_charts_below_a_texel = 0;
};

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_PACKING_REPORT_H
