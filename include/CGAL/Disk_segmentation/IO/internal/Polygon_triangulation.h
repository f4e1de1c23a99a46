// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Triangulation of the polygons of a mesh file (disk_uv --triangulate), by
// ear clipping in the polygon's best-fitting plane, in bounded time.
//
// Not CGAL's triangulate_faces: on a self-intersecting polygon its
// constrained Delaunay triangulation (exact intersections) inserts a new
// vertex at every crossing of two edges, the crossings of edges through
// those vertices need ever longer exact numbers, and a 120-corner polygon of
// a 474-byte OBJ file ran for minutes (the fuzzer's hang).

#ifndef CGAL_DISK_SEGMENTATION_IO_INTERNAL_POLYGON_TRIANGULATION_H
#define CGAL_DISK_SEGMENTATION_IO_INTERNAL_POLYGON_TRIANGULATION_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {
namespace internal {

// Polygons with more corners are fanned: ear clipping costs up to
// O(corners^3) on a polygon with few ears (about 1e9 steps here).
constexpr std::size_t max_ear_clipped_corners = 1000;


// The polygon's corners in its best-fitting plane (Newell's normal, largest
// axis dropped), oriented so that the polygon turns counterclockwise;
// false if the polygon has no area or a non-finite coordinate.
template <typename Point>
bool project_polygon(const std::vector<Point>& points, const std::vector<std::size_t>& polygon,
                     std::vector<CGAL::Epick::Point_2>& projected)
{
  const std::size_t n = polygon.size();
  // Coordinates relative to the first corner and divided by the largest
  // offset: Newell's sums then neither overflow nor underflow.
  std::vector<std::array<double, 3> > p(n);
  double largest = 0;
  for(std::size_t i = 0; i < n; ++i)
    for(int k = 0; k < 3; ++k)
    {
      p[i][k] = CGAL::to_double(points[polygon[i]][k]) - CGAL::to_double(points[polygon[0]][k]);
      largest = (std::max)(largest, std::abs(p[i][k]));
    }
  if(!(largest > 0) || !std::isfinite(largest))
    return false;
  std::array<double, 3> normal{{ 0, 0, 0 }};
  for(std::size_t i = 0; i < n; ++i)
  {
    for(int k = 0; k < 3; ++k)
      p[i][k] /= largest;
  }
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::array<double, 3>& a = p[i];
    const std::array<double, 3>& b = p[(i + 1) % n];
    normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
    normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
    normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  int dropped = 0;
  for(int k = 1; k < 3; ++k)
    if(std::abs(normal[k]) > std::abs(normal[dropped]))
      dropped = k;
  if(!(std::abs(normal[dropped]) > 0))
    return false;
  // (u, v) = the two other axes in cyclic order, swapped when the normal
  // points down the dropped axis, so that the polygon turns to the left.
  int u = (dropped + 1) % 3, v = (dropped + 2) % 3;
  if(normal[dropped] < 0)
    std::swap(u, v);
  projected.clear();
  for(std::size_t i = 0; i < n; ++i)
    projected.emplace_back(p[i][u], p[i][v]);
  return true;
}


// The triangles of one polygon, as indices into `points`, in the polygon's
// orientation. `used_fan` tells whether the polygon was fanned from one
// corner instead (it has no area, no ear could be found, e.g. when it
// crosses itself, or it has more than `max_ear_clipped_corners` corners).
//
// Bound: each step of the loop either cuts an ear (at most n - 3 times) or
// moves the cursor; a cursor that goes once around the remaining corners
// without an ear ends the loop with a fan. So at most (n - 2) (n + 1) steps,
// each testing O(n) corners.
template <typename Point>
std::vector<std::vector<std::size_t> > triangulate_polygon(const std::vector<Point>& points,
                                                           const std::vector<std::size_t>& polygon,
                                                           bool& used_fan)
{
  typedef CGAL::Epick::Point_2 Point_2;
  std::vector<std::vector<std::size_t> > triangles;
  const std::size_t n = polygon.size();
  used_fan = false;
  if(n < 3)
    return triangles;
  if(n == 3)
    return { polygon };

  std::vector<Point_2> q;
  std::vector<std::size_t> next(n), previous(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    next[i] = (i + 1) % n;
    previous[i] = (i + n - 1) % n;
  }
  std::size_t remaining = n, cursor = 0;
  if(n <= max_ear_clipped_corners && project_polygon(points, polygon, q))
  {
    // A corner is an ear when it turns strictly left and no other remaining
    // corner lies in its triangle (corners at the same place as the ear's
    // neighbors do not block it: the polygon touches itself there).
    auto is_ear = [&](std::size_t b) {
      const std::size_t a = previous[b], c = next[b];
      if(CGAL::orientation(q[a], q[b], q[c]) != CGAL::LEFT_TURN)
        return false;
      for(std::size_t p = next[c]; p != a; p = next[p])
      {
        if(q[p] == q[a] || q[p] == q[b] || q[p] == q[c])
          continue;
        if(CGAL::orientation(q[a], q[b], q[p]) != CGAL::RIGHT_TURN &&
           CGAL::orientation(q[b], q[c], q[p]) != CGAL::RIGHT_TURN &&
           CGAL::orientation(q[c], q[a], q[p]) != CGAL::RIGHT_TURN)
          return false;
      }
      return true;
    };
    std::size_t steps_without_ear = 0;
    while(remaining > 3 && steps_without_ear <= remaining)
    {
      if(is_ear(cursor))
      {
        const std::size_t a = previous[cursor], c = next[cursor];
        triangles.push_back({ polygon[a], polygon[cursor], polygon[c] });
        next[a] = c;
        previous[c] = a;
        --remaining;
        cursor = a;
        steps_without_ear = 0;
      }
      else
      {
        cursor = next[cursor];
        ++steps_without_ear;
      }
    }
  }
  used_fan = remaining > 3;
  // A fan of what is left (the whole polygon if no ear was cut).
  const std::size_t apex = cursor;
  for(std::size_t b = next[apex]; next[b] != apex; b = next[b])
    triangles.push_back({ polygon[apex], polygon[b], polygon[next[b]] });
  return triangles;
}

} // namespace internal
} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_INTERNAL_POLYGON_TRIANGULATION_H
