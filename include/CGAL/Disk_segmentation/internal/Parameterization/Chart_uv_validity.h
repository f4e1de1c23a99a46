// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether a chart's UVs make a valid map (finite, no flipped or needle
// triangle, a simple border), and keeping the 3D winding of a map.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_UV_VALIDITY_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_UV_VALIDITY_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Parameterization/Chart.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

constexpr const char* non_finite_uv = "non-finite UV";

// Whether a vertex of the closed polygon `border` lies within `tolerance` of
// a border segment it is not an end of. Packing moves every UV by a
// similarity rounded to doubles: such a border could touch itself once
// packed (two copies of a vertex split in 3D, laid out 1e-17 apart, met).
// Each segment is tested against the vertices in its x-range, sorted.
template <typename Point_2>
bool border_nearly_touches_itself(const std::vector<Point_2>& border, double tolerance)
{
  const std::size_t n = border.size();
  if(n < 4)
    return false;
  std::vector<std::pair<double, std::size_t> > by_x(n);
  for(std::size_t i = 0; i < n; ++i)
    by_x[i] = std::make_pair(border[i].x(), i);
  std::sort(by_x.begin(), by_x.end());
  for(std::size_t k = 0; k < n; ++k)
  {
    const Point_2& a = border[k];
    const Point_2& b = border[(k + 1) % n];
    const double dx = b.x() - a.x(), dy = b.y() - a.y(), length2 = dx * dx + dy * dy;
    const double lo = (std::min)(a.x(), b.x()) - tolerance, hi = (std::max)(a.x(), b.x()) + tolerance;
    for(auto it = std::lower_bound(by_x.begin(), by_x.end(), std::make_pair(lo, std::size_t(0)));
        it != by_x.end() && it->first <= hi; ++it)
    {
      const std::size_t i = it->second;
      if(i == k || i == (k + 1) % n)
        continue;
      const Point_2& p = border[i];
      // The closest point of the segment, clamped to its ends.
      const double t = length2 > 0 ? (std::max)(0., (std::min)(1., ((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / length2)) : 0.;
      const double ex = p.x() - (a.x() + t * dx), ey = p.y() - (a.y() + t * dy);
      if(ex * ex + ey * ey <= tolerance * tolerance)
        return true;
    }
  }
  return false;
}

// What is wrong with a chart's UVs, or an empty string. A chart is valid when
// its UVs are finite, every triangle keeps the 3D winding with a non-negligible
// area, and its border is a simple polygon; a locally injective map of a disk
// whose border is simple is globally injective.
inline std::string chart_uv_problem(const Chart& c, const std::vector<std::array<double, 2> >& uv,
                                    const std::vector<Index>& border_loop)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Point_2;
  for(const auto& u : uv)
    if(!std::isfinite(u[0]) || !std::isfinite(u[1]))
      return non_finite_uv;

  double total = 0;
  std::vector<double> areas(c.triangles.size());
  for(std::size_t t = 0; t < c.triangles.size(); ++t)
  {
    const auto& a = uv[c.triangles[t][0]];
    const auto& b = uv[c.triangles[t][1]];
    const auto& d = uv[c.triangles[t][2]];
    if(CGAL::orientation(Point_2(a[0], a[1]), Point_2(b[0], b[1]), Point_2(d[0], d[1])) != CGAL::LEFT_TURN)
      return "flipped or degenerate UV triangle";
    areas[t] = 0.5 * ((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]));
    total += areas[t];
  }
  // Triangles too thin to rasterize or to invert in a texture lookup; and
  // needles whose height is under 1e-10 of the chart's size, which packing
  // (a similarity rounded to doubles in [0, 1]) would flatten to a line.
  const double mean = total / static_cast<double>(c.triangles.size());
  double xmin = uv[0][0], xmax = uv[0][0], ymin = uv[0][1], ymax = uv[0][1];
  for(const auto& u : uv)
  {
    xmin = (std::min)(xmin, u[0]); xmax = (std::max)(xmax, u[0]);
    ymin = (std::min)(ymin, u[1]); ymax = (std::max)(ymax, u[1]);
  }
  // Squared: 2 area > 1e-10 size longest, without a square root per edge.
  const double chart_size2 = (xmax - xmin) * (xmax - xmin) + (ymax - ymin) * (ymax - ymin);
  for(std::size_t t = 0; t < c.triangles.size(); ++t)
  {
    if(!(areas[t] > 1e-12 * mean))
      return "degenerate UV triangle";
    double longest2 = 0;
    for(int i = 0; i < 3; ++i)
    {
      const auto& a = uv[c.triangles[t][i]];
      const auto& b = uv[c.triangles[t][(i + 1) % 3]];
      longest2 = (std::max)(longest2, (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]));
    }
    if(!(4 * areas[t] * areas[t] > 1e-20 * chart_size2 * longest2))
      return "degenerate UV triangle";
  }
  const double chart_size = std::sqrt(chart_size2);

  std::vector<Point_2> polygon;
  polygon.reserve(border_loop.size());
  for(Index v : border_loop)
    polygon.push_back(Point_2(uv[v][0], uv[v][1]));
  if(polygon.size() >= 4 && !CGAL::is_simple_2(polygon.begin(), polygon.end()))
    return "self-intersecting UV border";
  if(border_nearly_touches_itself(polygon, 1e-10 * chart_size))
    return "UV border nearly touches itself";
  return std::string();
}

// Free-border methods may return the mirror image of the surface; mirroring
// it back keeps the 3D winding that normal-map baking relies on.
inline void keep_winding(const Chart& c, Chart_uv& uv)
{
  double signed_area = 0;
  for(const auto& t : c.triangles)
  {
    const auto& a = uv[t[0]]; const auto& b = uv[t[1]]; const auto& d = uv[t[2]];
    signed_area += (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
  }
  if(signed_area < 0)
    for(auto& u : uv)
      u[0] = -u[0];
}

inline void keep_winding(Chart& c) { keep_winding(c, c.uv); }

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_UV_VALIDITY_H
