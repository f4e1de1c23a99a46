// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_MERGE_DISK_REGIONS_H
#define CGAL_DISK_SEGMENTATION_MERGE_DISK_REGIONS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Merge_tree.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_topology.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Region_merging.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Segmentation_settings.h>
#include <CGAL/Disk_segmentation/parameters.h>

#include <boost/graph/graph_traits.hpp>

#include <string>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
///
/// Greedily merges adjacent regions of a partition of `tm` into topological
/// disks while every region stays a disk (the paper's Algorithm 2).
///
/// Two adjacent disks `Si`, `Sj` are a candidate when their union is a disk,
/// that is when their common part (shared vertices and edges) is one open
/// path, and when their score
/// \f$ J_{ij} = \ell_{ij} / \sqrt{\max(A_i, A_j)} \f$ (shared boundary length
/// over the square root of the larger area) is at least the threshold. The
/// candidate with the highest score merges first (ties: smaller ids first),
/// then the scores of the merged region are updated, until no candidate is
/// left. A higher threshold stops earlier along the same sequence of merges,
/// so it never yields fewer regions.
///
/// On return, the ids are `0` to the returned value minus one, numbered in
/// the order of each region's first face in the package's face order (see \ref DS_FaceOrder).
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         whose faces are triangles
/// @tparam FacePatchMap a model of `ReadWritePropertyMap` with
///         `face_descriptor` as key type and an integral value type
/// @tparam NamedParameters a sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters"
///
/// @param tm a triangle mesh, manifold, without garbage
/// @param face_patch_map a partition whose regions (faces with equal values)
///        are all topological disks; receives the merged partition
/// @param np an optional sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{merge_threshold}
///     \cgalParamDescription{the score threshold `eps`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`regular_polygon_threshold(5)`, about 0.7624, the paper's best setting}
///     \cgalParamExtra{must be finite and >= 0; 0 merges as long as the union stays a disk}
///   \cgalParamNEnd
///   \cgalParamNBegin{merge_tree}
///     \cgalParamDescription{receives the merges done (see `Merge_tree`); its leaves are the
///       regions of `face_patch_map` as given, numbered in the order of their first face in the package's face order (see \ref DS_FaceOrder)}
///     \cgalParamType{`Merge_tree*`}
///     \cgalParamDefault{`nullptr`}
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
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in `[0, num_faces(tm))`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `face_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in `[0, num_vertices(tm))`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// @return the number of regions after merging (never more than before)
///
/// @throws Input_error as `voronoi_fps_segmentation()` does, if the
///         threshold is negative or not finite, or if a region is not a
///         topological disk (run `refine_to_topological_disks()` first).
///
/// Complexity, for `F` faces, `V` vertices and `R` input regions: expected
/// \f$ O(F + V) \f$ time to read the mesh, test the regions and build their
/// adjacency. Merges relabel the faces of the smaller region, \f$ O(F \log F) \f$
/// time over all merges, and push one candidate per neighbor of the merged
/// region into a lazy heap. Each of the `C` candidates costs
/// \f$ O(\log C) \f$ time and, when its two regions have not changed since it
/// was pushed, a disk test in \f$ O(m \log m + s) \f$ time, for the `m` faces
/// of the smaller region and the `s` faces around their vertices. `C` is at most the
/// number of adjacent pairs plus the neighbors of every merged region:
/// \f$ O(R) \f$ when every region has a bounded number of neighbors.
/// Memory: \f$ O(F + V + C) \f$.
template <typename TriangleMesh, typename FacePatchMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t merge_disk_regions(const TriangleMesh& tm,
                               FacePatchMap face_patch_map,
                               const NamedParameters& np = parameters::default_values())
{
  static_assert(internal::Check_patch_map<FacePatchMap>::value, "");
  static_assert(internal::Check_named_parameters<NamedParameters>::value, "");
  const internal::Segmentation_settings settings = internal::segmentation_settings(np);

  internal::Indexed_triangle_mesh m;
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> face_handles;
  internal::build_indexed_triangle_mesh(tm, internal::stage_parameters(np, settings), m, face_handles);

  auto patch_map = internal::checked_patch_map<TriangleMesh>(face_patch_map);
  const std::vector<std::vector<internal::Index> > regions =
    internal::group_faces_by_label(internal::read_face_labels(face_handles, patch_map));
  internal::Region_topology topology(m);
  std::vector<internal::Index> labels(m.number_of_faces());
  for(internal::Index r = 0; r < regions.size(); ++r)
  {
    if(!topology.is_disk(regions[r]))
      throw Input_error("merge_disk_regions: the region of face #" +
                        std::to_string(m.input_position(regions[r].front())) +
                        " is not a topological disk; run refine_to_topological_disks first");
    for(internal::Index f : regions[r]) labels[f] = r;
  }

  Merge_tree* tree = internal::merge_tree_parameter(np);
  const std::size_t count = internal::merge_regions(m, labels, regions.size(), settings.merge_threshold, tree);
  if(tree != nullptr)
    internal::face_leaves_to_input_order(m, *tree);
  internal::write_face_labels(face_handles, labels, patch_map);
  return count;
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_MERGE_DISK_REGIONS_H
