// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_REGULAR_POLYGON_THRESHOLD_H
#define CGAL_DISK_SEGMENTATION_REGULAR_POLYGON_THRESHOLD_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>

#include <CGAL/number_type_config.h>

#include <cmath>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// The paper's threshold \f$ \epsilon_N = 2 / \sqrt{N \cot(\pi / N)} \f$
/// (its Equation 5): one side of a regular `N`-gon over the square root of its
/// area, i.e.\ the merge score of a regular `N`-gon and a smaller neighbor
/// sharing one full side. `regular_polygon_threshold(5)` (about 0.7624) is
/// the default of `merge_disk_regions()`. Constant time and memory.
///
/// @throws Input_error if `N < 3`, in release builds too.
template <typename Integer>
double regular_polygon_threshold(Integer N)
{
  static_assert(std::is_integral<Integer>::value && !std::is_same<Integer, bool>::value,
                "CGAL::Disk_segmentation::regular_polygon_threshold() takes an integer number of sides");
  if(!(N >= 3))
    throw Input_error("regular_polygon_threshold: a polygon has at least 3 sides (got " + std::to_string(N) + ")");
  const double n = static_cast<double>(N);
  return 2. / std::sqrt(n / std::tan(CGAL_PI / n));
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_REGULAR_POLYGON_THRESHOLD_H
