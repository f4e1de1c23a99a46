// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_ATLAS_ATLAS_MEASURES_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_ATLAS_ATLAS_MEASURES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Distortion_statistics.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Area-weighted percentile of (value, weight) pairs.
inline double weighted_percentile(std::vector<std::pair<double, double> > values, double fraction)
{
  if(values.empty())
    return 0;
  std::sort(values.begin(), values.end());
  double total = 0;
  for(const auto& v : values) total += v.second;
  double accumulated = 0;
  for(const auto& v : values)
  {
    accumulated += v.second;
    if(accumulated >= fraction * total)
      return v.first;
  }
  return values.back().first;
}

inline Distortion_statistics distortion_statistics(std::vector<std::pair<double, double> > values)
{
  Distortion_statistics s;
  double total = 0;
  for(const auto& v : values)
  {
    s.mean += v.first * v.second;
    total += v.second;
    s.max = (std::max)(s.max, v.first);
  }
  if(total > 0)
    s.mean /= total;
  s.percentile_95 = weighted_percentile(std::move(values), 0.95);
  return s;
}

// Texel centers strictly inside two or more of the given UV triangles. A
// center on an edge belongs to no triangle, so that neighbors sharing an
// edge never count as overlapping.
inline std::size_t count_texel_overlaps(const std::vector<std::array<std::array<double, 2>, 3> >& triangles,
                                        unsigned int resolution)
{
  std::vector<unsigned char> coverage(static_cast<std::size_t>(resolution) * resolution, 0);
  std::size_t overlaps = 0;
  const double r = resolution;
  for(const auto& t : triangles)
  {
    double xmin = t[0][0], xmax = t[0][0], ymin = t[0][1], ymax = t[0][1];
    for(int i = 1; i < 3; ++i)
    {
      xmin = (std::min)(xmin, t[i][0]); xmax = (std::max)(xmax, t[i][0]);
      ymin = (std::min)(ymin, t[i][1]); ymax = (std::max)(ymax, t[i][1]);
    }
    // Clamped in floating point first: far-away UVs would overflow a long.
    auto texel_range = [r](double lo, double hi) {
      const double first = (std::max)(0., std::floor(lo * r - 0.5));
      const double last = (std::min)(r - 1, std::ceil(hi * r - 0.5));
      return std::make_pair(static_cast<long>(first), static_cast<long>(last));
    };
    if(!(xmax * r + 0.5 >= 0) || !(ymax * r + 0.5 >= 0) || !(xmin * r - 0.5 <= r) || !(ymin * r - 0.5 <= r))
      continue;
    const std::pair<long, long> ri = texel_range(xmin, xmax), rj = texel_range(ymin, ymax);
    const long i0 = ri.first, i1 = ri.second, j0 = rj.first, j1 = rj.second;
    const double orientation = (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[1][1] - t[0][1]) * (t[2][0] - t[0][0]);
    if(orientation == 0)
      continue;
    // At most resolution^2 texels: both ranges were clamped to [0, resolution).
    for(long j = j0; j <= j1; ++j)
      for(long i = i0; i <= i1; ++i)
      {
        const double px = (i + 0.5) / r, py = (j + 0.5) / r;
        bool inside = true;
        for(int e = 0; e < 3 && inside; ++e)
        {
          const auto& a = t[e];
          const auto& b = t[(e + 1) % 3];
          const double side = (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0]);
          inside = (orientation > 0) ? (side > 0) : (side < 0);
        }
        if(!inside)
          continue;
        unsigned char& c = coverage[static_cast<std::size_t>(j) * resolution + static_cast<std::size_t>(i)];
        if(c == 1)
          ++overlaps;
        if(c < 2)
          ++c;
      }
  }
  return overlaps;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_ATLAS_ATLAS_MEASURES_H
