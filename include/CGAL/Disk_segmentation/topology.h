// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_TOPOLOGY_H
#define CGAL_DISK_SEGMENTATION_TOPOLOGY_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Face_range_topology.h>

namespace CGAL {
namespace Disk_segmentation {
/// \ingroup PkgDiskSegmentationRef
///
/// Returns the Euler characteristic `V - E + F` of the faces of `face_range`,
/// where `V` and `E` count the distinct vertices and edges of those faces.
///
/// Complexity: expected \f$ O(k) \f$ time and memory for the `k` faces of
/// the range (their descriptors are hashed).
///
/// @tparam FaceRange a range of `boost::graph_traits<TriangleMesh>::%face_descriptor`
///         without repetition
/// @tparam TriangleMesh a model of `FaceGraph` whose faces are triangles
///
/// @throws Input_error if a face of the range is not a triangle
template <typename FaceRange, typename TriangleMesh>
long euler_characteristic(const FaceRange& face_range, const TriangleMesh& tm)
{
  return internal::count_face_range(face_range, tm).euler_characteristic();
}

/// \ingroup PkgDiskSegmentationRef
///
/// Tells whether the faces of `face_range` form a topological disk: they are
/// connected through edges, around no vertex do they form more than one fan
/// (no pinched vertex), and their Euler characteristic is 1. The Euler
/// characteristic alone is not enough: two triangles sharing only a vertex
/// have `V - E + F = 5 - 6 + 2 = 1`.
///
/// `tm` must be manifold (every vertex has a single fan of faces), which the
/// segmentation functions check.
///
/// Complexity: expected \f$ O(k) \f$ time and memory for the `k` faces of
/// the range (their descriptors are hashed).
///
/// @tparam FaceRange a range of `boost::graph_traits<TriangleMesh>::%face_descriptor`
///         without repetition
/// @tparam TriangleMesh a model of `FaceGraph` whose faces are triangles
///
/// @throws Input_error if a face of the range is not a triangle
template <typename FaceRange, typename TriangleMesh>
bool is_topological_disk(const FaceRange& face_range, const TriangleMesh& tm)
{
  return internal::count_face_range(face_range, tm).is_disk();
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_TOPOLOGY_H
