// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_SEGMENT_INTO_DISKS_H
#define CGAL_DISK_SEGMENTATION_SEGMENT_INTO_DISKS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Merge_tree.h>
#include <CGAL/Disk_segmentation/internal/Execution/Progress.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Region_merging.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Segmentation_pipeline.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Segmentation_settings.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Voronoi_fps_labels.h>
#include <CGAL/Disk_segmentation/merge_disk_regions.h>
#include <CGAL/Disk_segmentation/parameters.h>
#include <CGAL/Disk_segmentation/refine_to_topological_disks.h>
#include <CGAL/Disk_segmentation/voronoi_fps_segmentation.h>

#include <boost/graph/graph_traits.hpp>

#include <vector>

namespace CGAL {
namespace Disk_segmentation {
/// \ingroup PkgDiskSegmentationRef
///
/// Segments `tm` into topological disks with the whole method of the paper:
/// `voronoi_fps_segmentation()`, then `refine_to_topological_disks()`, then
/// `merge_disk_regions()`. The mesh is read once, so this is faster than
/// calling the three functions in turn, with the same result.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         whose faces are triangles
/// @tparam FacePatchMap a model of `WritablePropertyMap` with
///         `face_descriptor` as key type and an integral value type
/// @tparam NamedParameters a sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters"
///
/// @param tm a triangle mesh, manifold, without garbage
/// @param face_patch_map receives the patch id of every face, in `[0, P)`
///        where `P` is the returned value, numbered in the order of each
///        patch's first face in the package's face order (see \ref DS_FaceOrder)
/// @param np an optional sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters":
///        all those of the three functions (`number_of_seeds`,
///        `random_seed`, `seeds_output_iterator`, `crease_penalty`, `number_of_subsamples`,
///        `merge_threshold`, `merge_tree`, `smooth_borders`, `vertex_point_map`, `geom_traits`,
///        `face_index_map`, `vertex_index_map`), and `progress_callback`, called with
///        `("segmentation", s, 3)` after each step `s` (and `s = 0` first); its `false`
///        stops the work with `Cancelled` (see \ref DS_Errors)
///
/// With `smooth_borders(true)` (not in the paper; the default,
/// `default_smooth_borders`, as in every function), the refined regions
/// lose the saw teeth of their borders before they are merged: a face of
/// one region with two edges on the border of another moves to it when both
/// stay disks, which shortens the border (see the manual).
/// `smooth_borders(false)` runs the three functions one after the other;
/// with `crease_penalty(0)` as well (the paper's distance, see
/// \ref DS_Creases), that is the paper's segmentation.
///
/// @return the number `P` of patches; every patch is a topological disk
///
/// @throws Input_error as the three functions do, and Cancelled; `face_patch_map`,
///         `merge_tree` and `seeds_output_iterator` are not written then.
///
/// Complexity, for `F` faces and `V` vertices: the sum of the three steps'
/// (see each function), the mesh being read once in \f$ O(F + V) \f$ time;
/// the first step takes expected \f$ O(F \log F \log n) \f$ time.
/// `smooth_borders(true)` adds \f$ O(F) \f$ expected time on a mesh of
/// bounded vertex degree (at most \f$ 4F \f$ face moves). Memory:
/// \f$ O(F + V) \f$, plus the candidates of the merge step (see
/// `merge_disk_regions()`).
template <typename TriangleMesh, typename FacePatchMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t segment_into_disks(const TriangleMesh& tm,
                               FacePatchMap face_patch_map,
                               const NamedParameters& np = parameters::default_values())
{
  static_assert(internal::Check_patch_map<FacePatchMap>::value, "");
  static_assert(internal::Check_named_parameters<NamedParameters>::value, "");
  const internal::Segmentation_settings settings = internal::segmentation_settings(np);
  // One instantiation of the stages for any chain of values (see stage_parameters()).
  const auto stage_parameters = internal::stage_parameters(np, settings);
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  internal::Indexed_triangle_mesh m;
  std::vector<face_descriptor> face_handles;
  internal::build_indexed_triangle_mesh(tm, stage_parameters, m, face_handles);

  std::vector<internal::Index> labels;
  // The caller's tree is replaced only once nothing can throw.
  Merge_tree* tree = internal::merge_tree_parameter(np);
  Merge_tree staged_tree;
  internal::Progress progress = internal::Progress::from(np);
  const internal::Segmentation_steps steps = internal::segment_indexed(
    m, face_handles, settings, stage_parameters, labels, tree != nullptr ? &staged_tree : nullptr, progress);
  if(tree != nullptr)
  {
    internal::face_leaves_to_input_order(m, staged_tree);
    *tree = std::move(staged_tree);
  }
  std::vector<face_descriptor> seeds;
  for(internal::Index s : steps.seeds)
    seeds.push_back(face_handles[s]);
  internal::write_seeds(np, seeds);
  auto patch_map = internal::checked_patch_map<TriangleMesh>(face_patch_map);
  internal::write_face_labels(face_handles, labels, patch_map);
  return steps.patches;
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_SEGMENT_INTO_DISKS_H
