// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_REFINE_TO_TOPOLOGICAL_DISKS_H
#define CGAL_DISK_SEGMENTATION_REFINE_TO_TOPOLOGICAL_DISKS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Region_refinement.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Segmentation_settings.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Voronoi_fps.h>
#include <CGAL/Disk_segmentation/parameters.h>

#include <boost/graph/graph_traits.hpp>

#include <vector>

namespace CGAL {
namespace Disk_segmentation {
/// \ingroup PkgDiskSegmentationRef
///
/// Refines a face partition of `tm` until every region is a topological
/// disk (the paper's Algorithm 1). A region that is already a disk is kept
/// as it is. Any other region is re-sampled with `k` farthest-point seeds
/// restricted to its faces and split into their Voronoi cells, recursively;
/// a region of at most `k` faces is split into single faces.
///
/// A region is a topological disk when its faces are connected through
/// edges, no vertex has its region faces in more than one fan (no pinched
/// vertex), and its Euler characteristic `V - E + F` is 1.
///
/// The input regions are the sets of faces with equal values in
/// `face_patch_map` (any values). On return, the ids are `0` to the returned
/// value minus one, numbered in the order of each region's first face in
/// the package's face order (see \ref DS_FaceOrder).
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         whose faces are triangles
/// @tparam FacePatchMap a model of `ReadWritePropertyMap` with
///         `face_descriptor` as key type and an integral value type
/// @tparam NamedParameters a sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters"
///
/// @param tm a triangle mesh, manifold, without garbage
/// @param face_patch_map the partition to refine; receives the refined one
/// @param np an optional sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_subsamples}
///     \cgalParamDescription{the number `k` of seeds used to re-sample a region that is not a disk}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`5`}
///     \cgalParamExtra{must be at least 2}
///   \cgalParamNEnd
///   \cgalParamNBegin{crease_penalty}
///     \cgalParamDescription{a dual arc across an edge whose two faces' normals make an angle
///       \f$ \theta \f$ is \f$ 1 + k (1 - \cos\theta) \f$ times longer, so that Voronoi cells, and
///       the borders of the regions, follow creases (not in the paper; see \ref DS_Creases)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`default_crease_penalty` (10); `0` is the paper's geodesic distance on the dual mesh}
///     \cgalParamExtra{must be a finite number \f$ \geq 0 \f$}
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
/// @return the number of regions after refinement
///
/// @throws Input_error as `voronoi_fps_segmentation()` does, or if `k < 2`.
///
/// Complexity, for `F` faces and `V` vertices: \f$ O(F + V) \f$ expected time
/// to read the mesh and test every region (the input ids are hashed): all
/// the work when every region is already a disk. Re-sampling a region of `m`
/// faces costs expected \f$ O(m \log m \log k) \f$ time, plus \f$ O(m) \f$ to
/// test its cells. The regions re-sampled at one depth are disjoint, so each
/// level of re-sampling costs expected \f$ O(F \log F \log k) \f$; every
/// level makes the regions smaller, so there are at most `F` levels, and
/// typically few. Memory: \f$ O(F + V) \f$.
template <typename TriangleMesh, typename FacePatchMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t refine_to_topological_disks(const TriangleMesh& tm,
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
  const internal::Dual_arcs arcs = internal::dual_arcs(m);
  internal::Voronoi_fps fps(m, &arcs);
  std::vector<internal::Index> labels;
  const std::size_t count = internal::refine_regions(
    m, fps, internal::group_faces_by_label(internal::read_face_labels(face_handles, patch_map)),
    settings.number_of_subsamples, labels);
  internal::write_face_labels(face_handles, labels, patch_map);
  return count;
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_REFINE_TO_TOPOLOGICAL_DISKS_H
