// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_PACKING_METHOD_H
#define CGAL_DISK_SEGMENTATION_PACKING_METHOD_H

#include <CGAL/disable_warnings.h>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// How `pack_patches()` places the charts in the unit square.
enum class Packing_method
{
  /// One texel density for all charts (each chart keeps its 3D size
  /// relative to the others), charts packed tightly by their shapes (or by
  /// their minimum-area rectangles when that fits better). The default.
  TIGHT,
  /// The paper's packer: a `ceil(sqrt(P)) x ceil(sqrt(P))` grid of equal
  /// square cells in patch id order, every chart rotated and scaled to fill
  /// its cell. Texel density differs from chart to chart.
  GRID
};

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_PACKING_METHOD_H
