// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_UV_ATLAS_H
#define CGAL_DISK_SEGMENTATION_UV_ATLAS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Atlas_report.h>
#include <CGAL/Disk_segmentation/Merge_tree.h>
#include <CGAL/Disk_segmentation/internal/Atlas/Atlas_pipeline.h>
#include <CGAL/Disk_segmentation/internal/Execution/Progress.h>
#include <CGAL/Disk_segmentation/internal/Packing/Packing_settings.h>
#include <CGAL/Disk_segmentation/internal/Packing/Patch_packing.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Parameterization_settings.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Region_merging.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Region_refinement.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Segmentation_pipeline.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Voronoi_fps_labels.h>
#include <CGAL/Disk_segmentation/pack_patches.h>
#include <CGAL/Disk_segmentation/parameterize_patches.h>
#include <CGAL/Disk_segmentation/parameters.h>
#include <CGAL/Disk_segmentation/segment_into_disks.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Real_timer.h>

#include <boost/graph/graph_traits.hpp>

#include <type_traits>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
///
/// Checks every parameter that `uv_atlas()` reads, without a mesh, so that a
/// program can refuse a bad parameter before it reads or computes anything.
/// `uv_atlas()` runs the same checks first. Constant time and memory.
///
/// @tparam NamedParameters a sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters"
/// @param np the named parameters that will be given to `uv_atlas()`
///
/// @throws Input_error naming the first parameter out of its range.
template <typename NamedParameters = parameters::Default_named_parameters>
void check_uv_atlas_parameters(const NamedParameters& np = parameters::default_values())
{
  static_assert(internal::Check_named_parameters<NamedParameters>::value, "");
  internal::segmentation_settings(np);
  internal::parameterization_settings(np);
  internal::packing_settings(np);
}

/// \ingroup PkgDiskSegmentationRef
///
/// Computes a complete UV atlas of `tm`: `segment_into_disks()`, then
/// `parameterize_patches()`, then `pack_patches()`. Every chart is a
/// topological disk with valid UVs (no flipped or degenerate triangle, simple
/// border) unless `use_fallback(false)` is given, and the charts are placed
/// without overlap in \f$ [0,1]^2 \f$.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` whose faces are triangles
/// @tparam UVMap a model of `WritablePropertyMap` with `halfedge_descriptor` as key type and a 2D
///         point type (constructible from two `double`, with `x()` and `y()`) as value type
/// @tparam NamedParameters a sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters"
///
/// @param tm a triangle mesh, manifold, without garbage
/// @param uv_map receives per-corner UVs: `uv_map[h]` is the UV of `target(h)` in `face(h)`
/// @param np an optional sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters": those of
///        `segment_into_disks()`, `parameterize_patches()` and `pack_patches()`, and
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{face_patch_map}
///     \cgalParamDescription{receives the chart id of every face}
///     \cgalParamType{a model of `ReadWritePropertyMap` with `face_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{smooth_borders}
///     \cgalParamDescription{whether chart borders lose their saw teeth (see `segment_into_disks()`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`default_smooth_borders` (`true`, not in the paper)}
///   \cgalParamNEnd
///   \cgalParamNBegin{straighten_borders}
///     \cgalParamDescription{whether the borders between the final charts are rerouted along shorter
///       paths where the charts still meet the bound (see `parameterize_patches()`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true` (not in the paper)}
///   \cgalParamNEnd
///   \cgalParamNBegin{merge_tree}
///     \cgalParamDescription{receives the merges of the segmentation, from which the charts are
///       chosen top-down (see `parameterize_patches()`)}
///     \cgalParamType{`Merge_tree*`}
///     \cgalParamDefault{an internal tree}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_material_map}
///     \cgalParamDescription{faces with different values (materials, parts) never share a chart: the
///       mesh is cut along the edges between them before anything else (not in the paper)}
///     \cgalParamType{a model of `ReadablePropertyMap` with `face_descriptor` as key type and an
///       equality-comparable value type}
///     \cgalParamDefault{one material}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_polygon_map}
///     \cgalParamDescription{faces with the same value are one polygon of the caller's mesh
///       (triangulated): a polygon that the charts split is moved whole into one of them where both
///       charts stay disks; the charts are then parameterized again, each whole, without the
///       distortion bound (a split would cut polygons again), and `Atlas_report::polygons_moved_whole` and
///       `polygons_left_across_charts` count them (not in the paper)}
///     \cgalParamType{a model of `ReadablePropertyMap` with `face_descriptor` as key type and an
///       integral value type}
///     \cgalParamDefault{each face its own polygon}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{called with the stage (`"segmentation"`, `"parameterization"`, `"packing"`)
///       and a counter of work done out of a total; a `false` result stops the work with `Cancelled`
///       (see \ref DS_Errors)}
///     \cgalParamType{a callable of `(const std::string&, std::size_t, std::size_t)` returning `bool` or `void`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// @return the sizes and times of every stage, and the reports of `parameterize_patches()` and `pack_patches()`
///
/// @throws Input_error on a bad mesh or parameter (see the three functions), or when the segmentation
///         gives more patches than the padding leaves room for (see \ref DS_Errors)
/// @throws Cancelled when `progress_callback` returns `false`
///
/// Whatever it throws, the caller's maps, merge tree and seeds are as they were: the stages write
/// to maps of their own, copied at the end (one UV per halfedge and one id per face more memory).
///
/// Complexity: the sum of those of `segment_into_disks()`,
/// `parameterize_patches()` and `pack_patches()`; the mesh is indexed once
/// for the first two, in \f$ O(F + V) \f$ time for `F` faces and `V`
/// vertices, and the packing reads its coordinates again. The
/// parameterization takes most of the time in practice. Memory: the largest
/// of the three, plus \f$ O(F) \f$ for the patch ids and the merge tree.
template <typename TriangleMesh, typename UVMap, typename NamedParameters = parameters::Default_named_parameters>
Atlas_report uv_atlas(const TriangleMesh& tm, UVMap uv_map, const NamedParameters& np = parameters::default_values())
{
  static_assert(internal::Check_named_parameters<NamedParameters>::value, "");
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<std::size_t> >::const_type
    Staged_patch_map;

  CGAL::Real_timer total;
  total.start();
  // Every stage's parameters are checked now, before anything is computed.
  check_uv_atlas_parameters(np);
  const auto user_uv_map = internal::checked_uv_map<TriangleMesh>(uv_map);
  typedef typename boost::property_traits<std::decay_t<decltype(user_uv_map)> >::value_type UV_point;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_halfedge_property_t<UV_point> >::const_type
    Staged_uv_map;

  // The stages write to maps of their own: the caller's maps, merge tree and
  // seeds are written at the end, once nothing can throw (a bad mesh, a
  // padding too large for the charts, a cancellation).
  const Staged_patch_map face_patch_map = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
  const bool user_patches = !is_default_parameter<NamedParameters, CGAL::internal_np::face_patch_t>::value;
  const auto user_patch_map = internal::checked_patch_map<TriangleMesh>(
    choose_parameter(get_parameter(np, CGAL::internal_np::face_patch), face_patch_map));
  static_assert(internal::Check_patch_map<std::decay_t<decltype(user_patch_map)> >::value, "");
  internal::Progress progress = internal::Progress::from(np);
  internal::Packing_settings packing = internal::packing_settings(np);
  packing.progress = &progress;
  // The stages see the values as checked settings and a chain whose type
  // depends only on the maps given: they compile once for any chain of values.
  const internal::Segmentation_settings segmentation = internal::segmentation_settings(np);
  const auto stage_parameters = internal::stage_parameters(np, segmentation);
  Merge_tree tree;
  std::vector<face_descriptor> seeds;
  const Staged_uv_map staged_uv = get(CGAL::dynamic_halfedge_property_t<UV_point>(), tm);
  Atlas_report report =
    internal::segment_and_parameterize(tm, face_patch_map, staged_uv, stage_parameters, segmentation,
                                       internal::parameterization_settings(np), packing, progress, tree, seeds);

  // The indexed mesh is freed: the packing reads the mesh again.
  progress("packing", 0, 1);
  CGAL::Real_timer timer;
  timer.start();
  report.packing = internal::pack_checked_patches(tm, face_patch_map, staged_uv, packing, stage_parameters);
  report.packing_seconds = timer.time();
  progress("packing", 1, 1);

  for(face_descriptor f : faces(tm))
  {
    if(user_patches)
      put(user_patch_map, f, static_cast<typename boost::property_traits<
                               std::decay_t<decltype(user_patch_map)> >::value_type>(get(face_patch_map, f)));
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      put(user_uv_map, h, get(staged_uv, h));
  }
  if(Merge_tree* user_tree = internal::merge_tree_parameter(np))
    *user_tree = std::move(tree);
  internal::write_seeds(np, seeds);

  report.total_seconds = total.time();
  return report;
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_UV_ATLAS_H
