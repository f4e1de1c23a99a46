// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The measures of an atlas's quality: distortion statistics, texel
// overlaps and seam length, per face and over the atlas.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_ATLAS_ATLAS_MEASURES_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_ATLAS_ATLAS_MEASURES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Distortion_statistics.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Triangle_distortion.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

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

typedef std::vector<std::array<std::array<double, 2>, 3> > Corner_uvs;

// The UVs of every face of `m` in its corner order, read from `uv_map`;
// returns the first face with a non-finite UV, or no_index.
template <typename TriangleMesh, typename UVMap, typename FaceHandles, typename VertexHandles>
Index read_corner_uvs(const TriangleMesh& tm, const UVMap& uv_map, const Indexed_triangle_mesh& m,
                      const FaceHandles& face_handles, const VertexHandles& vertex_handles, Corner_uvs& uv)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  uv.assign(m.number_of_faces(), std::array<std::array<double, 2>, 3>());
  // Three halfedges: build_indexed_triangle_mesh checked the triangles.
  for(Index f = 0; f < m.number_of_faces(); ++f)
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_handles[f], tm), tm))
      for(int j = 0; j < 3; ++j)
        if(vertex_handles[m.corners[f][j]] == target(h, tm))
        {
          const auto p = get(uv_map, h);
          uv[f][j] = {{ CGAL::to_double(p.x()), CGAL::to_double(p.y()) }};
          if(!std::isfinite(uv[f][j][0]) || !std::isfinite(uv[f][j][1]))
            return f;
        }
  return no_index;
}

// The Jacobian of every face in the common frame of the components, and
// the faces, 3D and UV areas of every chart.
struct Face_measures
{
  std::vector<Triangle_jacobian> jacobians;
  std::vector<std::size_t> chart_faces;
  std::vector<double> chart_area_3d, chart_area_uv;
  double total_3d = 0, total_uv = 0;
  double mean_abs_det = 0;  // over the faces whose Jacobian is valid
};

inline Face_measures measure_faces(const Indexed_triangle_mesh& m, const Corner_uvs& uv,
                                   const std::vector<std::size_t>& ids, std::size_t charts)
{
  const std::size_t F = m.number_of_faces();
  Face_measures fm;
  fm.jacobians.resize(F);
  fm.chart_faces.assign(charts, 0);
  fm.chart_area_3d.assign(charts, 0);
  fm.chart_area_uv.assign(charts, 0);
  std::size_t measured = 0;
  for(Index f = 0; f < F; ++f)
  {
    fm.jacobians[f] = triangle_jacobian(m.point(f, 0), m.point(f, 1), m.point(f, 2), uv[f][0], uv[f][1], uv[f][2]);
    Triangle_jacobian& j = fm.jacobians[f];
    // Each component has its own frame: measures that compare faces across
    // charts need the common one (a component too small to register in it
    // gets zero 3D area, as it would at one shared scale).
    const double unit = m.common_unit(f);
    if(unit != 1.)
    {
      j.area_3d *= unit * unit;
      j.determinant /= unit * unit;
      j.sigma_max /= unit;
      j.sigma_min /= unit;
    }
    ++fm.chart_faces[ids[f]];
    fm.chart_area_3d[ids[f]] += j.area_3d;
    // Unsigned: a flipped face still covers its UV area.
    const double a_uv = 0.5 * std::abs((uv[f][1][0] - uv[f][0][0]) * (uv[f][2][1] - uv[f][0][1]) -
                                       (uv[f][1][1] - uv[f][0][1]) * (uv[f][2][0] - uv[f][0][0]));
    fm.chart_area_uv[ids[f]] += a_uv;
    fm.total_uv += a_uv;
    fm.total_3d += j.area_3d;
    if(j.valid())
    {
      fm.mean_abs_det += std::abs(j.determinant);
      ++measured;
    }
  }
  if(measured > 0)
    fm.mean_abs_det /= double(measured);
  return fm;
}

// Per-face distortion into `q` (an Atlas_quality): flipped, degenerate and
// zero-area faces are counted, the others measured; s1 s2 is rescaled by
// the chart's (or the atlas's) 3D-to-UV area ratio so that the normalized
// map preserves area overall.
template <typename Quality>
void measure_distortion(const Face_measures& fm, const std::vector<std::size_t>& ids, Quality& q)
{
  const std::size_t F = fm.jacobians.size();
  std::vector<std::pair<double, double> > angle, area, atlas_area;
  std::vector<double> ratios;
  double weight = 0, ratio = 0, dirichlet = 0;
  double b_area = 0, b_angle = 0, b_dirichlet = 0, b_atlas_area = 0, b_atlas_dirichlet = 0;
  const double atlas_normalization = (fm.total_uv > 0) ? fm.total_3d / fm.total_uv : 1.;
  for(Index f = 0; f < F; ++f)
  {
    const Triangle_jacobian& j = fm.jacobians[f];
    if(!(j.area_3d > 0))
    {
      ++q.zero_area_faces;
      continue;
    }
    if(j.determinant < 0 && std::abs(j.determinant) > 1e-12 * fm.mean_abs_det)
    {
      ++q.flipped_faces;
      continue;
    }
    if(!(std::abs(j.determinant) > 1e-12 * fm.mean_abs_det))
    {
      ++q.degenerate_faces;
      continue;
    }
    const std::size_t c = ids[f];
    const double chart_normalization =
      fm.chart_area_uv[c] > 0 ? fm.chart_area_3d[c] / fm.chart_area_uv[c] : 1.;
    const double s1 = j.sigma_max, s2 = j.sigma_min, w = j.area_3d;
    // Scaling UVs by k multiplies both singular values by k; areas by k^2.
    const double chart_k = std::sqrt(chart_normalization), atlas_k = std::sqrt(atlas_normalization);
    const double c1 = s1 * chart_k, c2 = s2 * chart_k, a1 = s1 * atlas_k, a2 = s2 * atlas_k;
    angle.emplace_back(std::abs(std::log(s1 / s2)), w);
    area.emplace_back(std::abs(std::log(c1 * c2)), w);
    atlas_area.emplace_back(std::abs(std::log(a1 * a2)), w);
    ratio += w * s1 / s2;
    ratios.push_back(s1 / s2);
    q.min_area_scale = ratios.size() == 1 ? c1 * c2 : (std::min)(q.min_area_scale, c1 * c2);
    q.max_area_scale = ratios.size() == 1 ? c1 * c2 : (std::max)(q.max_area_scale, c1 * c2);
    dirichlet += w * (c1 * c1 + c2 * c2 + 1 / (c1 * c1) + 1 / (c2 * c2)) / 4;
    b_area += w * (c1 * c2 + 1 / (c1 * c2) - 2);
    b_angle += w * (s1 / s2 + s2 / s1 - 2);
    b_dirichlet += w * (c1 * c1 + c2 * c2 + 1 / (c1 * c1) + 1 / (c2 * c2)) / 2;
    b_atlas_area += w * (a1 * a2 + 1 / (a1 * a2) - 2);
    b_atlas_dirichlet += w * (a1 * a1 + a2 * a2 + 1 / (a1 * a1) + 1 / (a2 * a2)) / 2;
    weight += w;
  }
  q.flipped_percent = F > 0 ? 100. * double(q.flipped_faces) / double(F) : 0.;
  q.degenerate_percent = F > 0 ? 100. * double(q.degenerate_faces) / double(F) : 0.;
  if(!ratios.empty())
  {
    // The nearest-rank percentile: the value below which 95% of the triangles lie.
    const std::size_t rank = (std::min)(ratios.size() - 1,
                                        static_cast<std::size_t>(std::ceil(0.95 * double(ratios.size()))) - 1);
    std::nth_element(ratios.begin(), ratios.begin() + rank, ratios.end());
    q.conformal_ratio_p95 = ratios[rank];
    q.max_conformal_ratio = *std::max_element(ratios.begin(), ratios.end());
  }
  q.angle_distortion = distortion_statistics(std::move(angle));
  q.area_distortion = distortion_statistics(std::move(area));
  q.atlas_area_distortion = distortion_statistics(std::move(atlas_area));
  if(weight > 0)
  {
    q.conformal_ratio = ratio / weight;
    q.symmetric_dirichlet = dirichlet / weight;
    q.benchmark_area_distortion = b_area / weight;
    q.benchmark_angle_distortion = b_angle / weight;
    q.benchmark_symmetric_dirichlet = b_dirichlet / weight;
    q.benchmark_atlas_area_distortion = b_atlas_area / weight;
    q.benchmark_atlas_symmetric_dirichlet = b_atlas_dirichlet / weight;
  }
}

// The length of the seams, in the common frame: each interior edge once,
// from its face of smaller index, whose two faces give its ends different
// UVs (the neighbor's corners are matched by vertex index).
inline double seam_length(const Indexed_triangle_mesh& m, const Corner_uvs& uv)
{
  double seam = 0;
  for(Index f = 0; f < m.number_of_faces(); ++f)
    for(int i = 0; i < 3; ++i)
    {
      const Index g = m.neighbors[f][i];
      if(g == no_index || g < f)
        continue;
      bool agree = true;
      for(int e = 0; e < 2 && agree; ++e)
      {
        const Index v = m.corners[f][(i + e) % 3];
        for(int k = 0; k < 3; ++k)
          if(m.corners[g][k] == v)
            agree = (uv[g][k] == uv[f][(i + e) % 3]);
      }
      if(!agree)
        seam += m.edge_length(f, i) * m.common_unit(f);
    }
  return seam;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_ATLAS_ATLAS_MEASURES_H
