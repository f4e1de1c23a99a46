// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How much of its convex hull a chart's UV layout fills: the shape bound of
// Distortion_bound::min_convexity.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_CONVEXITY_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_CONVEXITY_H

#include <CGAL/Disk_segmentation/internal/Parameterization/Chart.h>
#include <CGAL/Disk_segmentation/internal/Geometry/Planar_hull.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// UV area over the area of the UV convex hull of chart `c` under the map
// `uv`, in (0, 1]; 1 for a layout without area (nothing to pack).
inline double chart_convexity(const Chart& c, const Chart_uv& uv)
{
  std::vector<Planar_point> points(uv.size()), hull;
  for(std::size_t i = 0; i < uv.size(); ++i)
    points[i] = { uv[i][0], uv[i][1] };
  double twice_area = 0.;
  for(const auto& t : c.triangles)
    twice_area += planar_cross(points[t[0]], points[t[1]], points[t[2]]);
  convex_hull(points, hull);
  double twice_hull_area = 0.;
  for(std::size_t i = 0; i + 2 < hull.size(); ++i)
    twice_hull_area += planar_cross(hull[0], hull[i + 1], hull[i + 2]);
  if(!(twice_hull_area > 0.))
    return 1.;
  return std::abs(twice_area) / twice_hull_area;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_CONVEXITY_H
