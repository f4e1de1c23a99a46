// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters of the Disk_segmentation package.
//
// CGAL 5.5 stamps its chaining builders (`.vertex_point_map(...)`, ...) out of
// one list and offers no hook to add names, so the package keeps its own
// parameter pack type that derives from `CGAL::Named_function_parameters`,
// re-stamps CGAL's builders and adds the package's. CGAL's lookup helpers
// (`get_parameter`, `choose_parameter`, `is_default_parameter`) work on it
// unchanged because they only see the base class.

#ifndef CGAL_DISK_SEGMENTATION_PARAMETERS_H
#define CGAL_DISK_SEGMENTATION_PARAMETERS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/default_values.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Disk_segmentation {

namespace internal_np {

// Tags of the package's own named parameters.
enum number_of_seeds_t { number_of_seeds };
enum number_of_subsamples_t { number_of_subsamples };
enum merge_threshold_t { merge_threshold };
enum crease_penalty_t { crease_penalty };
enum first_seed_t { first_seed };
enum seeds_output_iterator_t { seeds_output_iterator };
enum parameterization_method_t { parameterization_method };
enum parameterizer_t { parameterizer };
enum use_fallback_t { use_fallback };
enum packing_method_t { packing_method };
enum texture_resolution_t { texture_resolution };
enum texture_height_t { texture_height };
enum padding_in_texels_t { padding_in_texels };
enum texels_per_unit_t { texels_per_unit };
enum max_number_of_pages_t { max_number_of_pages };
enum number_of_threads_t { number_of_threads };
enum progress_callback_t { progress_callback };
enum require_disk_patches_t { require_disk_patches };
enum max_area_distortion_t { max_area_distortion };
enum max_chart_faces_t { max_chart_faces };
enum max_number_of_charts_t { max_number_of_charts };
enum max_angle_distortion_t { max_angle_distortion };
enum max_stretch_t { max_stretch };
enum max_area_scale_t { max_area_scale };
enum max_stretch_p95_t { max_stretch_p95 };
enum min_convexity_t { min_convexity };
enum merge_tree_t { merge_tree };
enum distortion_bound_t { distortion_bound };
enum smooth_borders_t { smooth_borders };
enum merge_charts_t { merge_charts };
enum straighten_borders_t { straighten_borders };
enum face_material_map_t { face_material_map };
enum face_polygon_map_t { face_polygon_map };

} // namespace internal_np

/// \ingroup PkgDiskSegmentationRef
/// Named parameter pack of the package. It behaves like
/// `CGAL::Named_function_parameters` (and is one), and also offers the
/// package's own parameters, so that CGAL's and the package's parameters
/// chain in any order, e.g.
/// `parameters::number_of_seeds(20).vertex_point_map(vpm).merge_threshold(0.6)`.
/// The parameters are listed on the page \ref PkgDiskSegmentationNamedParameters.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters
  : public CGAL::Named_function_parameters<T, Tag, Base>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> CGAL_base;
  typedef typename CGAL_base::base base;
  typedef Named_function_parameters<T, Tag, Base> self;

  Named_function_parameters() : CGAL_base() {}
  Named_function_parameters(const T& v) : CGAL_base(v) {}
  Named_function_parameters(const T& v, const Base& b) : CGAL_base(v, b) {}

#define CGAL_add_named_parameter(X, Y, Z)                                         \
  template <typename K>                                                           \
  Named_function_parameters<K, CGAL::internal_np::X, self> Z(const K& k) const    \
  {                                                                               \
    return Named_function_parameters<K, CGAL::internal_np::X, self>(k, *this);   \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define CGAL_DISK_SEGMENTATION_ADD_PARAMETER(X, Z)                                \
  template <typename K>                                                           \
  Named_function_parameters<K, internal_np::X, self> Z(const K& k) const          \
  {                                                                               \
    return Named_function_parameters<K, internal_np::X, self>(k, *this);         \
  }
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(number_of_seeds_t, number_of_seeds)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(number_of_subsamples_t, number_of_subsamples)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(merge_threshold_t, merge_threshold)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(crease_penalty_t, crease_penalty)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(first_seed_t, first_seed)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(seeds_output_iterator_t, seeds_output_iterator)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(parameterization_method_t, parameterization_method)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(parameterizer_t, parameterizer)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(use_fallback_t, use_fallback)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(packing_method_t, packing_method)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(texture_resolution_t, texture_resolution)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(texture_height_t, texture_height)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(padding_in_texels_t, padding_in_texels)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(texels_per_unit_t, texels_per_unit)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_number_of_pages_t, max_number_of_pages)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(number_of_threads_t, number_of_threads)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(progress_callback_t, progress_callback)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(require_disk_patches_t, require_disk_patches)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_area_distortion_t, max_area_distortion)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_chart_faces_t, max_chart_faces)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_number_of_charts_t, max_number_of_charts)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_angle_distortion_t, max_angle_distortion)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_stretch_t, max_stretch)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_area_scale_t, max_area_scale)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_stretch_p95_t, max_stretch_p95)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(min_convexity_t, min_convexity)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(merge_tree_t, merge_tree)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(distortion_bound_t, distortion_bound)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(smooth_borders_t, smooth_borders)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(merge_charts_t, merge_charts)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(straighten_borders_t, straighten_borders)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(face_material_map_t, face_material_map)
  CGAL_DISK_SEGMENTATION_ADD_PARAMETER(face_polygon_map_t, face_polygon_map)
#undef CGAL_DISK_SEGMENTATION_ADD_PARAMETER
};

namespace parameters {

typedef Named_function_parameters<bool, CGAL::internal_np::all_default_t>
  Default_named_parameters;

// `default_values()` and the builders below are documented on the manual's
// page PkgDiskSegmentationNamedParameters and under "Named Parameters" in
// every function that reads them, not as free functions of the reference.
/// \cond SKIP_IN_MANUAL
/// An empty parameter pack: every parameter takes its default value.
inline Default_named_parameters default_values()
{
  return Default_named_parameters();
}

#define CGAL_add_named_parameter(X, Y, Z)                                         \
  template <typename K>                                                           \
  Named_function_parameters<K, CGAL::internal_np::X> Z(const K& k)                \
  {                                                                               \
    return Named_function_parameters<K, CGAL::internal_np::X>(k);                 \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define CGAL_DISK_SEGMENTATION_ADD_PARAMETER(X, Z)                                \
  template <typename K>                                                           \
  Named_function_parameters<K, internal_np::X> Z(const K& k)                      \
  {                                                                               \
    return Named_function_parameters<K, internal_np::X>(k);                       \
  }
/// \ingroup PkgDiskSegmentationRef
/// Number `n` of farthest-point seeds of the Voronoi segmentation.
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(number_of_seeds_t, number_of_seeds)
/// \ingroup PkgDiskSegmentationRef
/// Number `k` of seeds used to re-sample a region that is not a disk.
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(number_of_subsamples_t, number_of_subsamples)
/// \ingroup PkgDiskSegmentationRef
/// Score threshold `eps` of the greedy merging.
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(merge_threshold_t, merge_threshold)
/// \ingroup PkgDiskSegmentationRef
/// Penalty `k` >= 0 on dual arcs across bent edges: an arc between faces whose
/// normals make an angle theta is `1 + k (1 - cos theta)` times its length
/// (0: the paper's geodesic distance).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(crease_penalty_t, crease_penalty)
/// \ingroup PkgDiskSegmentationRef
/// Output iterator receiving the seed faces in the order they were chosen.
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(seeds_output_iterator_t, seeds_output_iterator)
/// \ingroup PkgDiskSegmentationRef
/// Parameterization method of every chart (`Parameterization_method`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(parameterization_method_t, parameterization_method)
/// \ingroup PkgDiskSegmentationRef
/// The user's parameterizer of every chart, instead of a built-in method: a
/// model of SMP's `Parameterizer_3` over `Chart_mesh`, or a factory of one.
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(parameterizer_t, parameterizer)
/// \ingroup PkgDiskSegmentationRef
/// Whether an invalid chart is redone with an injective method (`bool`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(use_fallback_t, use_fallback)
/// \ingroup PkgDiskSegmentationRef
/// How charts are placed in the unit square (`Packing_method`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(packing_method_t, packing_method)
/// \ingroup PkgDiskSegmentationRef
/// Side of the target texture in texels (`unsigned int`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(texture_resolution_t, texture_resolution)
/// \ingroup PkgDiskSegmentationRef
/// Height of a non-square target texture in texels (`unsigned int`);
/// `texture_resolution` is then its width.
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(texture_height_t, texture_height)
/// \ingroup PkgDiskSegmentationRef
/// Gap kept around every chart, in texels of the target texture (`double`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(padding_in_texels_t, padding_in_texels)
/// \ingroup PkgDiskSegmentationRef
/// Texels of the target texture per unit of 3D length (`double`); 0: the
/// largest that fits the charts on one page.
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(texels_per_unit_t, texels_per_unit)
/// \ingroup PkgDiskSegmentationRef
/// Most pages (textures) a fixed `texels_per_unit` may fill (`std::size_t`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_number_of_pages_t, max_number_of_pages)
/// \ingroup PkgDiskSegmentationRef
/// Maximum number of threads; 0 lets TBB decide (`unsigned int`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(number_of_threads_t, number_of_threads)
/// \ingroup PkgDiskSegmentationRef
/// Called as `callback(stage, done, total)` while an atlas is computed (any
/// callable, e.g. `std::function<bool(const std::string&, std::size_t, std::size_t)>`);
/// calls are serialized. A result convertible to `bool` that is `false`
/// stops the computation with `Cancelled`; a `void` result only follows it.
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(progress_callback_t, progress_callback)
/// \ingroup PkgDiskSegmentationRef
/// Largest area-weighted mean \f$ |\log(s_1 s_2)| \f$ of a chart (`double`, see `Distortion_bound`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_area_distortion_t, max_area_distortion)
/// \ingroup PkgDiskSegmentationRef
/// Largest area-weighted mean \f$ |\log(s_1/s_2)| \f$ of a chart (`double`, see `Distortion_bound`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_angle_distortion_t, max_angle_distortion)
/// \ingroup PkgDiskSegmentationRef
/// Largest \f$ s_1/s_2 \f$ of any triangle of a chart (`double`, see `Distortion_bound`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_stretch_t, max_stretch)
/// \ingroup PkgDiskSegmentationRef
/// Largest \f$ \max(s_1 s_2, 1/(s_1 s_2)) \f$ of any triangle of a chart (`double`, see `Distortion_bound`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_area_scale_t, max_area_scale)
/// \ingroup PkgDiskSegmentationRef
/// Largest 95th percentile of \f$ s_1/s_2 \f$ over the triangles of a chart (`double`, see `Distortion_bound`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_stretch_p95_t, max_stretch_p95)
/// \ingroup PkgDiskSegmentationRef
/// Smallest UV area / UV convex hull area of a large chart (`double` in \f$ [0, 1) \f$, see `Distortion_bound`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(min_convexity_t, min_convexity)
/// \ingroup PkgDiskSegmentationRef
/// All the bounds at once (`Distortion_bound`); the six parameters above override its fields.
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(distortion_bound_t, distortion_bound)
/// \ingroup PkgDiskSegmentationRef
/// Whether the saw teeth of region borders are removed (`bool`; see `segment_into_disks()`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(smooth_borders_t, smooth_borders)
/// \ingroup PkgDiskSegmentationRef
/// Whether adjacent charts that meet the distortion bound together are merged (`bool`; see `parameterize_patches()`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(merge_charts_t, merge_charts)
/// \ingroup PkgDiskSegmentationRef
/// Whether the borders between the final charts are rerouted along shorter paths, the charts
/// parameterized again and kept only where they still meet the bound (`bool`; see `parameterize_patches()`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(straighten_borders_t, straighten_borders)
/// \ingroup PkgDiskSegmentationRef
/// Pointer to a `Merge_tree` that `merge_disk_regions()` and `segment_into_disks()` fill,
/// and that `parameterize_patches()` reads to choose charts top-down (`Merge_tree*`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(merge_tree_t, merge_tree)
/// \ingroup PkgDiskSegmentationRef
/// Patches with more faces than this are split before they are parameterized (`std::size_t`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_chart_faces_t, max_chart_faces)
/// \ingroup PkgDiskSegmentationRef
/// The most charts the atlas may have: charts chosen under the distortion bound are merged past it
/// until there are no more (`std::size_t`; see `parameterize_patches()`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(max_number_of_charts_t, max_number_of_charts)
/// \ingroup PkgDiskSegmentationRef
/// Faces with different values (materials, parts) never share a chart or a patch: the mesh is
/// cut along the edges between them (`ReadablePropertyMap` from faces to an equality-comparable value).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(face_material_map_t, face_material_map)
/// \ingroup PkgDiskSegmentationRef
/// Faces with the same value are one polygon of the caller's mesh (triangulated), kept whole in
/// one chart where both charts stay disks (`ReadablePropertyMap` from faces to an integral id; see `uv_atlas()`).
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(face_polygon_map_t, face_polygon_map)
/// \endcond

// Parameters for the package's tests and benchmarks, not part of its
// interface (they may change without notice): the face used as the first
// farthest-point seed of its component, and whether parameterize_patches()
// refuses patches that are not topological disks (`false` parameterizes
// them anyway, as a baseline that ignores topology).
namespace testing {
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(first_seed_t, first_seed)
CGAL_DISK_SEGMENTATION_ADD_PARAMETER(require_disk_patches_t, require_disk_patches)
} // namespace testing
#undef CGAL_DISK_SEGMENTATION_ADD_PARAMETER

} // namespace parameters

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_PARAMETERS_H
