// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_ATLAS_QUALITY_H
#define CGAL_DISK_SEGMENTATION_ATLAS_QUALITY_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Distortion_statistics.h>
#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/internal/Atlas/Atlas_measures.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Triangle_distortion.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>
#include <CGAL/Disk_segmentation/parameters.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// The quality of a UV atlas, with the measures of the benchmark of Shay,
/// Solomon and Stein (2022) that the paper uses (Tables 1 and 2), and their
/// log variants (see \ref DS_Quality in the user manual).
///
/// For every face, the Jacobian \f$ J_f \f$ of its linear map from 3D to UV
/// (3D triangle laid in an orthonormal frame of its plane) has singular
/// values \f$ s_1 \ge s_2 \f$. A face is flipped if \f$ \det J_f < 0 \f$ and
/// degenerate if \f$ |\det J_f| \le 10^{-12} \f$ times the mean \f$ |\det J| \f$;
/// faces of zero 3D area are counted apart. Distortions skip flipped,
/// degenerate and zero-area faces and are weighted by 3D area.
/// "Chart-normalized" measures first scale each chart's UVs so that its UV
/// area equals its 3D area (the parameterization alone); "atlas-normalized"
/// measures use one scale for the whole atlas (which also exposes uneven
/// texel density).
struct Atlas_quality
{
  std::size_t number_of_faces = 0;
  /// Faces with \f$ \det J < 0 \f$.
  std::size_t flipped_faces = 0;
  /// Faces with a (near) zero UV area.
  std::size_t degenerate_faces = 0;
  /// Faces with zero 3D area (no Jacobian).
  std::size_t zero_area_faces = 0;
  /// `flipped_faces` in percent of all faces.
  double flipped_percent = 0;
  /// `degenerate_faces` in percent of all faces.
  double degenerate_percent = 0;

  /// \f$ |\log(s_1/s_2)| \f$ (0 for a conformal map).
  Distortion_statistics angle_distortion;
  /// \f$ |\log(s_1 s_2)| \f$, chart-normalized (0 for an area-preserving map).
  Distortion_statistics area_distortion;
  /// \f$ |\log(s_1 s_2)| \f$, atlas-normalized.
  Distortion_statistics atlas_area_distortion;
  /// Mean of \f$ s_1/s_2 \f$ (1 is ideal).
  double conformal_ratio = 0;
  /// 95th percentile of \f$ s_1/s_2 \f$ over the measured triangles, unweighted (as the peers' tables).
  double conformal_ratio_p95 = 1;
  /// Largest \f$ s_1/s_2 \f$.
  double max_conformal_ratio = 1;
  /// Smallest and largest \f$ s_1 s_2 \f$, chart-normalized: how much the worst triangles are
  /// shrunk or blown up in the texture.
  double min_area_scale = 1, max_area_scale = 1;
  /// Mean of \f$ (s_1^2 + s_2^2 + s_1^{-2} + s_2^{-2})/4 \f$, chart-normalized (1 is ideal).
  double symmetric_dirichlet = 0;

  /// The benchmark's variants: means of \f$ s_1 s_2 + 1/(s_1 s_2) - 2 \f$ (area),
  /// \f$ s_1/s_2 + s_2/s_1 - 2 \f$ (angle) and \f$ (s_1^2 + s_2^2 + s_1^{-2} + s_2^{-2})/2 \f$,
  /// chart-normalized and atlas-normalized.
  double benchmark_area_distortion = 0, benchmark_angle_distortion = 0, benchmark_symmetric_dirichlet = 0;
  double benchmark_atlas_area_distortion = 0, benchmark_atlas_symmetric_dirichlet = 0;

  /// Total 3D length of the seam edges: interior edges whose two faces disagree on the UV of an endpoint.
  double seam_length = 0;
  /// `seam_length` divided by the square root of the total 3D area (scale free).
  double cut_length = 0;

  std::size_t number_of_charts = 0;
  /// Faces of the smallest chart.
  std::size_t smallest_chart_faces = 0;
  /// Charts made of one face.
  std::size_t single_face_charts = 0;
  /// Sum of the UV areas of all faces (the fraction of the unit square used, once packed).
  double packing_efficiency = 0;
  /// Texel centers of a `texture_resolution` grid strictly inside two or more UV triangles
  /// (0 for an atlas without overlap); not computed when the resolution is 0.
  std::size_t texel_overlaps = 0;

  /// `true` when the atlas cannot be measured: a UV coordinate is not finite.
  bool failed = false;
  /// Why `failed` is set.
  std::string failure_reason;
};

/// \ingroup PkgDiskSegmentationRef
///
/// Measures a UV atlas: flipped and degenerate faces, angle and area
/// distortion (log and benchmark variants, chart- and atlas-normalized,
/// with their 95th percentile and maximum), seam and cut length, chart
/// counts, packing efficiency and texel overlaps. See `Atlas_quality` for
/// the definitions.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` whose faces are triangles
/// @tparam UVMap a model of `ReadablePropertyMap` with `halfedge_descriptor` as key type and a 2D
///         point type as value type (per-corner UVs, see `parameterize_patches()`)
/// @tparam FacePatchMap a model of `ReadablePropertyMap` with `face_descriptor` as key type and an
///         integral value type (chart ids)
/// @tparam NamedParameters a sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters"
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{texture_resolution}
///     \cgalParamDescription{side of the texel grid on which overlaps are counted; 0 skips the count}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`1024`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, geom_traits, face_index_map, vertex_index_map}
///     \cgalParamDescription{as in `voronoi_fps_segmentation()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// @throws Input_error on a bad mesh (see `voronoi_fps_segmentation()`); non-finite UVs are not
///         an exception but a failed measurement (`Atlas_quality::failed`).
///
/// Complexity, for `F` faces, `V` vertices and a texture of side `r`
/// (`texture_resolution`): \f$ O(F \log F + V) \f$ time plus \f$ O(r^2) \f$
/// and the texels covered by the UV triangles for the overlap count; memory
/// \f$ O(F + V + r^2) \f$ (one byte per texel). UVs and coordinates are
/// converted to `double` whatever the kernel.
template <typename TriangleMesh, typename UVMap, typename FacePatchMap,
          typename NamedParameters = parameters::Default_named_parameters>
Atlas_quality atlas_quality(const TriangleMesh& tm, UVMap uv_map, FacePatchMap face_patch_map,
                            const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  using internal::Index;
  using internal::no_index;

  static_assert(internal::Check_patch_map<FacePatchMap>::value, "");
  static_assert(internal::Check_named_parameters<NamedParameters>::value, "");
  const std::size_t resolution = internal::count_parameter(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::texture_resolution), default_texture_resolution),
    "texture_resolution");
  if(resolution > (std::size_t(1) << 16))
    throw Input_error("atlas_quality: texture_resolution (" + std::to_string(resolution) +
                      ") is above 65536; the overlap count needs resolution^2 bytes");

  Atlas_quality q;
  internal::Indexed_triangle_mesh m;
  std::vector<typename GT::face_descriptor> face_handles;
  std::vector<typename GT::vertex_descriptor> vertex_handles;
  internal::build_indexed_triangle_mesh(tm, np, m, face_handles, &vertex_handles);
  const std::size_t F = m.number_of_faces();
  q.number_of_faces = F;

  // UVs in the indexed mesh's corner order.
  std::vector<std::array<std::array<double, 2>, 3> > uv(F);
  // Three halfedges: build_indexed_triangle_mesh checked the triangles.
  for(Index f = 0; f < F; ++f)
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_handles[f], tm), tm))
      for(int j = 0; j < 3; ++j)
        if(vertex_handles[m.corners[f][j]] == target(h, tm))
        {
          const auto p = get(uv_map, h);
          uv[f][j] = {{ CGAL::to_double(p.x()), CGAL::to_double(p.y()) }};
          if(!std::isfinite(uv[f][j][0]) || !std::isfinite(uv[f][j][1]))
          {
            q.failed = true;
            q.failure_reason = "non-finite UV at face #" + std::to_string(m.input_position(f));
            return q;
          }
        }

  // Charts: ids, sizes, 3D and UV areas. The indexed mesh is normalized by
  // a power of two (see normalize_coordinates); only the seam length is
  // reported in the input's units, every other measure is scale free.
  const std::vector<std::size_t> ids = internal::read_face_labels(face_handles, face_patch_map);
  const std::size_t charts = ids.empty() ? 0 : *std::max_element(ids.begin(), ids.end()) + 1;
  std::vector<std::size_t> chart_faces(charts, 0);
  std::vector<double> chart_area_3d(charts, 0), chart_area_uv(charts, 0);
  std::vector<internal::Triangle_jacobian> jacobians(F);
  double total_3d = 0, total_uv = 0, mean_abs_det = 0;
  std::size_t measured = 0;
  for(Index f = 0; f < F; ++f)
  {
    jacobians[f] = internal::triangle_jacobian(m.point(f, 0), m.point(f, 1), m.point(f, 2),
                                               uv[f][0], uv[f][1], uv[f][2]);
    internal::Triangle_jacobian& j = jacobians[f];
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
    ++chart_faces[ids[f]];
    chart_area_3d[ids[f]] += j.area_3d;
    // Unsigned: a flipped face still covers its UV area.
    const double a_uv = 0.5 * std::abs((uv[f][1][0] - uv[f][0][0]) * (uv[f][2][1] - uv[f][0][1]) -
                                       (uv[f][1][1] - uv[f][0][1]) * (uv[f][2][0] - uv[f][0][0]));
    chart_area_uv[ids[f]] += a_uv;
    total_uv += a_uv;
    total_3d += j.area_3d;
    if(j.valid())
    {
      mean_abs_det += std::abs(j.determinant);
      ++measured;
    }
  }
  q.packing_efficiency = total_uv;
  q.number_of_charts = 0;
  q.smallest_chart_faces = F;
  for(std::size_t c = 0; c < charts; ++c)
  {
    if(chart_faces[c] == 0)
      continue;
    ++q.number_of_charts;
    q.smallest_chart_faces = (std::min)(q.smallest_chart_faces, chart_faces[c]);
    q.single_face_charts += (chart_faces[c] == 1) ? 1 : 0;
  }
  if(measured > 0)
    mean_abs_det /= double(measured);

  // Per-face distortion; s1 s2 is rescaled by the chart's (or the atlas's)
  // 3D-to-UV area ratio so that the normalized map preserves area overall.
  std::vector<std::pair<double, double> > angle, area, atlas_area;
  std::vector<double> ratios;
  double weight = 0, ratio = 0, dirichlet = 0;
  double b_area = 0, b_angle = 0, b_dirichlet = 0, b_atlas_area = 0, b_atlas_dirichlet = 0;
  const double atlas_normalization = (total_uv > 0) ? total_3d / total_uv : 1.;
  for(Index f = 0; f < F; ++f)
  {
    const internal::Triangle_jacobian& j = jacobians[f];
    if(!(j.area_3d > 0))
    {
      ++q.zero_area_faces;
      continue;
    }
    if(j.determinant < 0 && std::abs(j.determinant) > 1e-12 * mean_abs_det)
    {
      ++q.flipped_faces;
      continue;
    }
    if(!(std::abs(j.determinant) > 1e-12 * mean_abs_det))
    {
      ++q.degenerate_faces;
      continue;
    }
    const std::size_t c = ids[f];
    const double chart_normalization = chart_area_uv[c] > 0 ? chart_area_3d[c] / chart_area_uv[c] : 1.;
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
  q.angle_distortion = internal::distortion_statistics(std::move(angle));
  q.area_distortion = internal::distortion_statistics(std::move(area));
  q.atlas_area_distortion = internal::distortion_statistics(std::move(atlas_area));
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

  // Seams: each interior edge once, from its face of smaller index; the
  // neighbor's corners are matched by vertex index.
  double seam = 0;
  for(Index f = 0; f < F; ++f)
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
  q.cut_length = total_3d > 0 ? seam / std::sqrt(total_3d) : 0.;
  q.seam_length = seam / m.normalization_scale;  // back to the input's units

  if(resolution > 0)
    q.texel_overlaps = internal::count_texel_overlaps(uv, static_cast<unsigned int>(resolution));
  return q;
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_ATLAS_QUALITY_H
