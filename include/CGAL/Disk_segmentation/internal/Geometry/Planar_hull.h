// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Points of the plane and their convex hull: the shape of a chart's UVs,
// measured by the distortion bound (convexity) and by the packers.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_GEOMETRY_PLANAR_HULL_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_GEOMETRY_PLANAR_HULL_H

#include <CGAL/disable_warnings.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

struct Planar_point
{
  double x, y;
};

inline double planar_dot(const Planar_point& a, const Planar_point& b) { return a.x * b.x + a.y * b.y; }

// Twice the signed area of (o, a, b): positive for a left turn.
inline double planar_cross(const Planar_point& o, const Planar_point& a, const Planar_point& b)
{
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Drops the points strictly inside the octagon of the extreme points in eight
// directions (Akl-Toussaint): they cannot be hull vertices, and in a chart
// they are most of the corners, so the sort that follows stays short.
inline void discard_inner_points(std::vector<Planar_point>& points)
{
  if(points.size() < 32)
    return;
  // Directions at 0, 45, ..., 315 degrees (unnormalized): their support
  // points come in counterclockwise order around the hull.
  auto project = [](const Planar_point& p, double* v)
  {
    v[0] = p.x; v[1] = p.x + p.y; v[2] = p.y; v[3] = p.y - p.x;
    v[4] = -p.x; v[5] = -p.x - p.y; v[6] = -p.y; v[7] = p.x - p.y;
  };
  double best_value[8], value[8];
  std::size_t best[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
  project(points[0], best_value);
  for(std::size_t i = 1; i < points.size(); ++i)
  {
    project(points[i], value);
    for(int k = 0; k < 8; ++k)
      if(value[k] > best_value[k])
      {
        best_value[k] = value[k];
        best[k] = i;
      }
  }
  Planar_point octagon[8];
  for(int k = 0; k < 8; ++k)
    octagon[k] = points[best[k]];

  std::size_t kept = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    bool inside = true;
    for(int k = 0; k < 8 && inside; ++k)
      inside = planar_cross(octagon[k], octagon[(k + 1) & 7], points[i]) > 0.;
    if(!inside)
      points[kept++] = points[i];
  }
  points.resize(kept);
}

// Convex hull, counterclockwise, without collinear vertices (Andrew's
// monotone chain). Reorders `points`. Fewer than three distinct or only
// collinear points give the one or two extreme points.
inline void convex_hull(std::vector<Planar_point>& points, std::vector<Planar_point>& hull)
{
  hull.clear();
  discard_inner_points(points);
  std::sort(points.begin(), points.end(), [](const Planar_point& a, const Planar_point& b)
            { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  points.erase(std::unique(points.begin(), points.end(), [](const Planar_point& a, const Planar_point& b)
                           { return a.x == b.x && a.y == b.y; }),
               points.end());
  const std::size_t n = points.size();
  if(n < 3)
  {
    hull = points;
    return;
  }
  hull.resize(2 * n);
  // The inner loops pop only what was pushed: at most 2 n pops in all.
  std::size_t k = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    while(k >= 2 && planar_cross(hull[k - 2], hull[k - 1], points[i]) <= 0.) --k;
    hull[k++] = points[i];
  }
  for(std::size_t i = n - 1, lower = k + 1; i-- > 0;)
  {
    while(k >= lower && planar_cross(hull[k - 2], hull[k - 1], points[i]) <= 0.) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_GEOMETRY_PLANAR_HULL_H
