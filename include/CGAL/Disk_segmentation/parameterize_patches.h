// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_PARAMETERIZE_PATCHES_H
#define CGAL_DISK_SEGMENTATION_PARAMETERIZE_PATCHES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Distortion_bound.h>
#include <CGAL/Disk_segmentation/Merge_tree.h>
#include <CGAL/Disk_segmentation/Chart_parameterizer.h>
#include <CGAL/Disk_segmentation/Parameterization_method.h>
#include <CGAL/Disk_segmentation/Parameterization_report.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Patch_parameterization.h>
#include <CGAL/Disk_segmentation/internal/Execution/Progress.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Canonical_parameters.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Parameterization_settings.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Region_merging.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Segmentation_settings.h>
#include <CGAL/Disk_segmentation/parameters.h>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
///
/// Parameterizes every patch of `tm` on its own with CGAL's
/// Surface_mesh_parameterization, in parallel, and writes per-corner UVs.
///
/// Each chart is validated: finite UVs, every triangle keeps the 3D winding
/// with a non-negligible area (charts that come out mirrored are mirrored
/// back), and the UV border is a simple polygon; together these make the
/// chart injective. With `use_fallback` (the default), an invalid chart is
/// redone with mean value coordinates, then Tutte's barycentric map, both on
/// a circle and injective by construction; if even those fail numerically,
/// the patch is split in two and each piece redone, and the pieces get new
/// ids in `face_patch_map` (the first chart of a patch keeps the patch's id
/// where it can; ids stay contiguous, `0` to the number of charts minus
/// one). Valid
/// charts that exceed the distortion bound (`Distortion_bound`; the paper
/// has none) are replaced the same way: with a `merge_tree`, a patch is
/// first replaced by the two disks it was merged from, recursively down to
/// the tree's leaves, which are then split; candidates are parameterized
/// in parallel, each as soon as its parent is rejected. Under a finite bound, a chart of more
/// than one triangle whose map is invalid is replaced the same way at once,
/// without the other methods (a map redone on a circle rarely meets the
/// bound, and it was a third of the time on meshes with such charts).
/// Patches with more than
/// `max_chart_faces` faces are split the same way before they are
/// parameterized, with or without the fallback.
///
/// A chart budget (`max_number_of_charts`, UVAtlas's maxChartNumber; not in
/// the paper) is applied last: when the charts chosen above are more than
/// the budget, adjacent charts whose union is a disk are merged, and a
/// union is kept when its map is valid, whatever its distortion, until the
/// budget is met. Pairs are solved in the order of the growth of the
/// area-weighted sum of excesses over the bound that their own excesses
/// predict; of each round's solved unions, those whose measured growth is
/// least are kept. So validity and `max_chart_faces`
/// win over the budget, and the budget wins over the distortion bound; the
/// report says when the budget could not be met (`chart_budget_met`) and
/// how many charts the bound alone gave. Without a budget, or when the
/// bound gives no more charts than the budget, nothing changes.
///
/// UVs are per corner: `uv_map[h]` is the UV of `target(h)` as seen from
/// `face(h)`, so charts are cut along patch borders. Charts are not placed
/// relative to each other: see `pack_patches()`.
///
/// Charts do not depend on each other, and each is computed the same way on
/// any thread, so results do not depend on the number of threads.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` whose faces are triangles
/// @tparam FacePatchMap a model of `ReadWritePropertyMap` with `face_descriptor` as key type and an
///         integral value type; patch ids must be contiguous, `0` to `P - 1`
/// @tparam UVMap a model of `WritablePropertyMap` with `halfedge_descriptor` as key type and a 2D
///         point type (constructible from two `double`) as value type
/// @tparam NamedParameters a sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters"
///
/// @param tm a triangle mesh, manifold, without garbage
/// @param face_patch_map the patches, each a topological disk (see `segment_into_disks()`)
/// @param uv_map receives the UVs
/// @param np an optional sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{parameterization_method}
///     \cgalParamDescription{the method of every chart}
///     \cgalParamType{`Parameterization_method`}
///     \cgalParamDefault{`default_parameterization_method` (ARAP)}
///   \cgalParamNEnd
///   \cgalParamNBegin{parameterizer}
///     \cgalParamDescription{the user's parameterizer of every chart, instead of a built-in method
///       (not together with `parameterization_method`); it runs on a copy of each chart, and an
///       invalid result gets the fallbacks like a built-in method's; reports name it `CUSTOM`}
///     \cgalParamType{a model of SMP's `Parameterizer_3` over `Chart_mesh`, or a callable with no
///       argument returning one (see `Chart_mesh`)}
///     \cgalParamDefault{none: `parameterization_method` decides}
///   \cgalParamNEnd
///   \cgalParamNBegin{use_fallback}
///     \cgalParamDescription{whether invalid charts are redone (see above); when `false`, they are
///       kept as the method produced them and reported invalid. Only validity: the distortion
///       bound, `merge_charts` and `straighten_borders` work the same either way (a chart over the
///       bound is split, its pieces kept even if invalid)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{distortion_bound}
///     \cgalParamDescription{the distortion every chart of two faces or more must meet, and the
///       convexity of the large ones; a single triangle is laid out
///       isometrically}
///     \cgalParamType{`Distortion_bound`}
///     \cgalParamDefault{`Distortion_bound()`; `Distortion_bound::unbounded()` keeps the paper's charts}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_angle_distortion, max_area_distortion, max_stretch, max_area_scale, max_stretch_p95, min_convexity}
///     \cgalParamDescription{override one field of `distortion_bound`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{the field of `distortion_bound`}
///   \cgalParamNEnd
///   \cgalParamNBegin{smooth_borders}
///     \cgalParamDescription{whether the borders between the pieces of a split patch lose their saw
///       teeth (see `segment_into_disks()`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`default_smooth_borders` (`true`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{crease_penalty}
///     \cgalParamDescription{the distance of the Voronoi cells that split a patch over the bound (see
///       `voronoi_fps_segmentation()`); give the value the patches were segmented with}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`default_crease_penalty` (10); `0` is the paper's geodesic distance on the dual mesh}
///   \cgalParamNEnd
///   \cgalParamNBegin{merge_charts}
///     \cgalParamDescription{whether adjacent charts are merged, once chosen, when their union is a disk
///       that meets the bound (only under a bound); merged charts may join pieces of
///       different patches}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{straighten_borders}
///     \cgalParamDescription{whether, once the charts are chosen and merged, each border arc between
///       two of them (from one junction to the next) is replaced by a shorter edge path near it that
///       prefers creases, the faces in between changing sides; the changed charts are parameterized
///       again, and an arc is given back wherever a chart stops being a disk or meeting the bound
///       (only under a bound). Not in the paper.}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{merge_tree}
///     \cgalParamDescription{the merges that made the patches (filled by `segment_into_disks()`); charts
///       over the bound are replaced by their children in it before they are split by Voronoi cells}
///     \cgalParamType{`Merge_tree*`}
///     \cgalParamDefault{`nullptr`: over-bound patches are split by Voronoi cells at once}
///     \cgalParamExtra{its roots must be the patches of `face_patch_map`, else `Input_error`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_chart_faces}
///     \cgalParamDescription{patches with more faces are split (recursively, in two) before they are
///       parameterized, which bounds the memory of each chart's linear systems}
///     \cgalParamType{`std::size_t`, at least 1}
///     \cgalParamDefault{`default_max_chart_faces` (\f$ 2^{17} = 131072 \f$)}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_number_of_charts}
///     \cgalParamDescription{the chart budget: charts over it are merged past the distortion bound
///       (see above)}
///     \cgalParamType{`std::size_t`, at least 1}
///     \cgalParamDefault{no budget}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{maximum number of threads (0: TBB's choice; 1: sequential). Without TBB, sequential.}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{called with `("parameterization", charts done, charts)` after each chart;
///       a `false` result stops the work with `Cancelled`, the maps untouched (see \ref DS_Errors)}
///     \cgalParamType{a callable of `(const std::string&, std::size_t, std::size_t)` returning `bool` or `void`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key type and the traits' `Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class, used only to read coordinates: they are converted with `CGAL::to_double()` and all computation runs in `double` whatever the kernel}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{a \cgal Kernel deduced from the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map, vertex_index_map}
///     \cgalParamDescription{as in `voronoi_fps_segmentation()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// @return one report per chart and the counts of fallbacks, splits and invalid charts
///
/// @throws Input_error on a bad mesh (as `voronoi_fps_segmentation()`), on patch ids that are not
///         contiguous, or on a patch that is not a topological disk.
///
/// Complexity, for `F` faces and `V` vertices, with `M` the smaller of `F`
/// and `max_chart_faces`: expected \f$ O(F + V) \f$ time to read the mesh and
/// test the patches. A chart of `m` faces is parameterized in expected
/// \f$ O(m^{3/2}) \f$ time and \f$ O(m \log m) \f$ memory, the usual bounds of
/// the sparse factorization of its Laplacian with a fill-reducing ordering
/// (ARAP's ten iterations reuse one factorization; each fallback method adds
/// one), and validated in \f$ O(m \log m) \f$ time. The candidates of one
/// level of the merge tree, or of the Voronoi splits below it, are disjoint,
/// so a level costs expected \f$ O(F (\sqrt{M} + \log F)) \f$ time; there are
/// as many levels as the tree is high plus the depth of the splits (one
/// level when every patch meets the bound), and each round of chart merging
/// costs at most as much as a level. Memory: \f$ O(F + V) \f$ per thread,
/// plus the UVs of the parameterized ancestors that candidates reuse
/// (\f$ O(F) \f$ per level) and one factorization per thread (expected
/// \f$ O(M \log M) \f$).
template <typename TriangleMesh, typename FacePatchMap, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
Parameterization_report parameterize_patches(const TriangleMesh& tm,
                                             FacePatchMap face_patch_map,
                                             UVMap uv_map,
                                             const NamedParameters& np = parameters::default_values())
{
  static_assert(internal::Check_patch_map<FacePatchMap>::value, "");
  static_assert(internal::Check_named_parameters<NamedParameters>::value, "");
  // The mesh is read through a chain of its maps and the distance of the
  // Voronoi splits only: one instantiation for any chain of values.
  const internal::Indexed_input<TriangleMesh> input(
    tm, internal::forward_mesh_parameters(np, parameters::crease_penalty(internal::crease_penalty_parameter(np))));
  const Merge_tree* given = internal::merge_tree_parameter(np);
  Merge_tree tree;
  if(given != nullptr)
    tree = internal::face_leaves_to_mesh_order(input.mesh, *given);
  internal::Progress progress = internal::Progress::from(np);
  return internal::parameterize_indexed_patches(tm, input, internal::checked_patch_map<TriangleMesh>(face_patch_map),
                                                internal::checked_uv_map<TriangleMesh>(uv_map),
                                                internal::parameterization_settings(np), progress,
                                                given != nullptr ? &tree : nullptr);
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_PARAMETERIZE_PATCHES_H
