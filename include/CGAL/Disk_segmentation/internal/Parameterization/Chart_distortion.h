// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The distortion of one chart under a map: area-weighted means and
// extremes of its triangles' singular values.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_DISTORTION_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_DISTORTION_H

#include <CGAL/Disk_segmentation/internal/Parameterization/Chart.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Triangle_distortion.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// The distortion of one chart, normalized to its 3D area (so that only the
// parameterization is measured, not its scale): area-weighted means and the
// extremes over its triangles. Triangles of zero 3D area have no Jacobian
// and are skipped. Bound_test judges it against a Distortion_bound.
struct Chart_distortion
{
  double angle = 0;           // mean |log(s1 / s2)|
  double area = 0;            // mean |log(s1 s2)|
  double max_stretch = 1;     // largest s1 / s2
  double min_area_scale = 1;  // smallest s1 s2
  double max_area_scale = 1;  // largest s1 s2
  double stretch_p95 = 1;     // 95th percentile of s1 / s2 over the triangles (nearest rank)
};

// The distortion of `c` under the map `uv` (one UV per local vertex).
inline Chart_distortion chart_distortion(const Indexed_triangle_mesh& m, const Chart& c, const Chart_uv& uv)
{
  double area_3d = 0, area_uv = 0;
  std::vector<Triangle_jacobian> jacobians;
  jacobians.reserve(c.triangles.size());
  for(const auto& t : c.triangles)
  {
    jacobians.push_back(triangle_jacobian(m.points[c.vertices[t[0]]], m.points[c.vertices[t[1]]],
                                          m.points[c.vertices[t[2]]], uv[t[0]], uv[t[1]], uv[t[2]]));
    area_3d += jacobians.back().area_3d;
    area_uv += jacobians.back().area_3d * jacobians.back().determinant;
  }
  Chart_distortion d;
  if(!(area_3d > 0) || !(area_uv > 0))
    return d;
  const double normalization = area_3d / area_uv;
  double weight = 0;
  bool first = true;
  std::vector<double> stretches;
  stretches.reserve(jacobians.size());
  for(const Triangle_jacobian& j : jacobians)
  {
    if(!j.valid() || !(j.determinant > 0) || !(j.sigma_min > 0))
      continue;
    const double stretch = j.sigma_max / j.sigma_min;
    const double scale = j.sigma_max * j.sigma_min * normalization;
    d.angle += j.area_3d * std::abs(std::log(stretch));
    d.area += j.area_3d * std::abs(std::log(scale));
    weight += j.area_3d;
    stretches.push_back(stretch);
    d.max_stretch = first ? stretch : (std::max)(d.max_stretch, stretch);
    d.min_area_scale = first ? scale : (std::min)(d.min_area_scale, scale);
    d.max_area_scale = first ? scale : (std::max)(d.max_area_scale, scale);
    first = false;
  }
  if(weight > 0)
  {
    d.angle /= weight;
    d.area /= weight;
  }
  if(!stretches.empty())
  {
    const std::size_t rank = (std::min)(stretches.size() - 1,
                                        static_cast<std::size_t>(std::ceil(0.95 * double(stretches.size()))) - 1);
    std::nth_element(stretches.begin(), stretches.begin() + rank, stretches.end());
    d.stretch_p95 = stretches[rank];
  }
  return d;
}

inline Chart_distortion chart_distortion(const Indexed_triangle_mesh& m, const Chart& c)
{
  return chart_distortion(m, c, c.uv);
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_DISTORTION_H
