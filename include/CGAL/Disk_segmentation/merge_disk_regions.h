// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_MERGE_DISK_REGIONS_H
#define CGAL_DISK_SEGMENTATION_MERGE_DISK_REGIONS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Merge_tree.h>
#include <CGAL/Disk_segmentation/parameters.h>
#include <CGAL/Disk_segmentation/internal/Disk_region_merger.h>
#include <CGAL/Disk_segmentation/internal/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Parameter_checks.h>
#include <CGAL/Disk_segmentation/internal/Region_topology.h>

#include <CGAL/assertions.h>
#include <CGAL/number_type_config.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// The paper's threshold \f$ \epsilon_N = 2 / \sqrt{N \cot(\pi / N)} \f$
/// (its Equation 5): one side of a regular `N`-gon over the square root of its
/// area, i.e.\ the merge score of a regular `N`-gon and a smaller neighbor
/// sharing one full side. `regular_polygon_threshold(5)` (about 0.7624) is
/// the default of `merge_disk_regions()`. Constant time and memory.
///
/// @throws Input_error if `N < 3`, in release builds too.
template <typename Integer>
double regular_polygon_threshold(Integer N)
{
  static_assert(std::is_integral<Integer>::value && !std::is_same<Integer, bool>::value,
                "CGAL::Disk_segmentation::regular_polygon_threshold() takes an integer number of sides");
  if(!(N >= 3))
    throw Input_error("regular_polygon_threshold: a polygon has at least 3 sides (got " + std::to_string(N) + ")");
  const double n = static_cast<double>(N);
  return 2. / std::sqrt(n / std::tan(CGAL_PI / n));
}

namespace internal {

inline double checked_merge_threshold(double eps)
{
  if(!(eps >= 0.) || !std::isfinite(eps))
    throw Input_error("merge_threshold must be a finite number >= 0");
  return eps;
}

template <typename NamedParameters>
double merge_threshold_parameter(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return checked_merge_threshold(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::merge_threshold),
                     regular_polygon_threshold(default_merge_threshold_sides)));
}

// `labels` numbers disk regions canonically; merges them and renumbers.
// `tree`, if not null, receives the merges and the leaf of every face.
inline std::size_t merge_regions(const Indexed_triangle_mesh& m, std::vector<Index>& labels,
                                 std::size_t number_of_regions, double threshold, Merge_tree* tree = nullptr)
{
  if(tree != nullptr)
  {
    tree->number_of_leaves = number_of_regions;
    tree->face_leaves.assign(labels.begin(), labels.end());
  }
  Disk_region_merger merger(m, labels, number_of_regions);
  merger.run(threshold);
  if(tree != nullptr)
    tree->merges = merger.merges();
  return make_canonical(labels);
}

// The `merge_tree` named parameter: a Merge_tree* or null.
template <typename NamedParameters>
Merge_tree* merge_tree_parameter(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return choose_parameter(get_parameter(np, Disk_segmentation::internal_np::merge_tree),
                          static_cast<Merge_tree*>(nullptr));
}

// A Merge_tree lists the leaves of the faces in the order of faces(tm),
// the indexed mesh in its own (Indexed_triangle_mesh::input_face): from
// the mesh's order to the input's, in place.
inline void face_leaves_to_input_order(const Indexed_triangle_mesh& m, Merge_tree& tree)
{
  if(m.input_face.empty() || tree.face_leaves.size() != m.number_of_faces())
    return;
  std::vector<std::size_t> leaves(tree.face_leaves.size());
  for(std::size_t f = 0; f < leaves.size(); ++f)
    leaves[m.input_face[f]] = tree.face_leaves[f];
  tree.face_leaves.swap(leaves);
}

// A copy of `tree` with its faces in the indexed mesh's order. A tree of
// another size is copied as it is, for the checks to name it.
inline Merge_tree face_leaves_to_mesh_order(const Indexed_triangle_mesh& m, const Merge_tree& tree)
{
  Merge_tree out = tree;
  if(!m.input_face.empty() && tree.face_leaves.size() == m.number_of_faces())
    for(std::size_t f = 0; f < out.face_leaves.size(); ++f)
      out.face_leaves[f] = tree.face_leaves[m.input_face[f]];
  return out;
}

} // namespace internal

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
  const double threshold = internal::merge_threshold_parameter(np);

  internal::Indexed_triangle_mesh m;
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> face_handles;
  internal::build_indexed_triangle_mesh(tm, np, m, face_handles);

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
  const std::size_t count = internal::merge_regions(m, labels, regions.size(), threshold, tree);
  if(tree != nullptr)
    internal::face_leaves_to_input_order(m, *tree);
  internal::write_face_labels(face_handles, labels, patch_map);
  return count;
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_MERGE_DISK_REGIONS_H
