// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_ATLAS_QUALITY_H
#define CGAL_DISK_SEGMENTATION_ATLAS_QUALITY_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Distortion_statistics.h>
#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/default_values.h>
#include <CGAL/Disk_segmentation/internal/Atlas/Atlas_measures.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Packing/Packing_settings.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>
#include <CGAL/Disk_segmentation/parameters.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
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
/// @tparam FacePatchMap a model of `ReadablePropertyMap` with `face_descriptor` as key type and an
///         integral value type (chart ids)
/// @tparam UVMap a model of `ReadablePropertyMap` with `halfedge_descriptor` as key type and a 2D
///         point type as value type (per-corner UVs, see `parameterize_patches()`)
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
template <typename TriangleMesh, typename FacePatchMap, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
Atlas_quality atlas_quality(const TriangleMesh& tm, FacePatchMap face_patch_map, UVMap uv_map,
                            const NamedParameters& np = parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh> GT;
  using internal::Index;

  static_assert(internal::Check_patch_map<FacePatchMap>::value, "");
  static_assert(internal::Check_named_parameters<NamedParameters>::value, "");
  const std::size_t resolution = internal::texture_resolution_parameter(np);
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

  internal::Corner_uvs uv;
  const Index non_finite = internal::read_corner_uvs(tm, uv_map, m, face_handles, vertex_handles, uv);
  if(non_finite != internal::no_index)
  {
    q.failed = true;
    q.failure_reason = "non-finite UV at face #" + std::to_string(m.input_position(non_finite));
    return q;
  }

  // The indexed mesh is normalized by a power of two (see
  // normalize_coordinates); only the seam length is reported in the
  // input's units, every other measure is scale free.
  const std::vector<std::size_t> ids = internal::read_face_labels(face_handles, face_patch_map);
  const std::size_t charts = ids.empty() ? 0 : *std::max_element(ids.begin(), ids.end()) + 1;
  const internal::Face_measures measures = internal::measure_faces(m, uv, ids, charts);
  q.packing_efficiency = measures.total_uv;
  q.number_of_charts = 0;
  q.smallest_chart_faces = F;
  for(std::size_t c = 0; c < charts; ++c)
  {
    const std::size_t faces = measures.chart_faces[c];
    if(faces == 0)
      continue;
    ++q.number_of_charts;
    q.smallest_chart_faces = (std::min)(q.smallest_chart_faces, faces);
    q.single_face_charts += (faces == 1) ? 1 : 0;
  }
  internal::measure_distortion(measures, ids, q);

  const double seam = internal::seam_length(m, uv);
  q.cut_length = measures.total_3d > 0 ? seam / std::sqrt(measures.total_3d) : 0.;
  q.seam_length = seam / m.normalization_scale;  // back to the input's units

  if(resolution > 0)
    q.texel_overlaps = internal::count_texel_overlaps(uv, static_cast<unsigned int>(resolution));
  return q;
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_ATLAS_QUALITY_H
