// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Parameterizes a chart from a given start map (a parent's, two glued
// maps), falling back to the full chain when that fails.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_WARM_START_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_WARM_START_H

#include <CGAL/Disk_segmentation/Parameterization_method.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_method_chain.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_methods.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_parameterization.h>

#include <array>
#include <cmath>
#include <complex>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// parameterize_chart() from a start map, for a method that iterates from
// one, when one is given and gives a valid chart. When it does not, the
// full chain (the method's own start, fallbacks) with On_invalid_map::redo;
// with On_invalid_map::report the chart is reported invalid at once: a
// union whose glued maps fold under ARAP is one the merge gives up.
// Measured on fandisk, 14 such unions were redone from LSCM and none met
// the bound (0.19 of its 0.70 s).
inline Chart_outcome parameterize_chart_from(const Indexed_triangle_mesh& m, Chart& c, const Chart_method& requested,
                                             bool use_fallback, const Chart_uv* start, On_invalid_map on_invalid,
                                             Early_look* look, Solve_tally& tally)
{
  if(start != nullptr && requested.starts_from_a_map() && c.triangles.size() > 1)
  {
    tally.add(c);
    Chart_outcome outcome;
    outcome.used = requested.id();
    outcome.problem = requested.parameterize_from_map(m, c, *start, look);
    outcome.valid = outcome.problem.empty();
    if(outcome.valid || on_invalid == On_invalid_map::report)
      return outcome;
  }
  return parameterize_chart(m, c, requested, use_fallback, on_invalid, look, tally);
}

// A start map for the union `u` of two parameterized charts `a` and `b`
// that share border vertices: `a` as it is, `b` moved by the similarity
// that best fits its shared vertices onto `a`'s (least squares in the
// complex plane), shared vertices at the mean of the two. Both maps keep
// the 3D winding, so no reflection is needed. Empty if fewer than two
// vertices are shared or a vertex of `u` is in neither.
inline Chart_uv glue_chart_maps(const Chart& a, const Chart& b, const Chart& u)
{
  typedef std::complex<double> C;
  auto z = [](const std::array<double, 2>& p) { return C(p[0], p[1]); };
  std::unordered_map<Index, Index> in_a;
  in_a.reserve(2 * a.vertices.size());
  for(Index i = 0; i < a.vertices.size(); ++i)
    in_a.emplace(a.vertices[i], i);
  C mean_a(0, 0), mean_b(0, 0);
  std::vector<std::pair<Index, Index> > shared;  // (local vertex of a, of b)
  for(Index j = 0; j < b.vertices.size(); ++j)
  {
    const auto it = in_a.find(b.vertices[j]);
    if(it == in_a.end())
      continue;
    shared.emplace_back(it->second, j);
    mean_a += z(a.uv[it->second]);
    mean_b += z(b.uv[j]);
  }
  if(shared.size() < 2)
    return Chart_uv();
  mean_a /= double(shared.size());
  mean_b /= double(shared.size());
  C cross(0, 0);
  double norm = 0;
  for(const auto& s : shared)
  {
    const C pb = z(b.uv[s.second]) - mean_b;
    cross += std::conj(pb) * (z(a.uv[s.first]) - mean_a);
    norm += std::norm(pb);
  }
  if(!(norm > 0) || !std::isfinite(norm))
    return Chart_uv();
  const C scale = cross / norm;

  std::unordered_map<Index, C> sum;
  std::unordered_map<Index, int> count;
  sum.reserve(2 * u.vertices.size());
  count.reserve(2 * u.vertices.size());
  for(Index i = 0; i < a.vertices.size(); ++i)
  {
    sum[a.vertices[i]] += z(a.uv[i]);
    ++count[a.vertices[i]];
  }
  for(Index j = 0; j < b.vertices.size(); ++j)
  {
    sum[b.vertices[j]] += mean_a + scale * (z(b.uv[j]) - mean_b);
    ++count[b.vertices[j]];
  }
  Chart_uv uv(u.vertices.size());
  for(Index k = 0; k < u.vertices.size(); ++k)
  {
    const auto it = count.find(u.vertices[k]);
    if(it == count.end())
      return Chart_uv();
    const C p = sum[u.vertices[k]] / double(it->second);
    uv[k] = {{ p.real(), p.imag() }};
  }
  return uv;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_WARM_START_H
