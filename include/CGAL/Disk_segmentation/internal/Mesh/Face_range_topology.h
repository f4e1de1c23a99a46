// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Counts the topology of a range of faces of a FaceGraph, indexing only
// those faces.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_MESH_FACE_RANGE_TOPOLOGY_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_MESH_FACE_RANGE_TOPOLOGY_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_topology.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Counts the topology of the faces of `face_range`, indexing only them.
template <typename FaceRange, typename TriangleMesh>
Region_counts count_face_range(const FaceRange& face_range, const TriangleMesh& tm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  std::unordered_map<face_descriptor, Index> face_index;
  for(face_descriptor f : face_range)
    face_index.emplace(f, static_cast<Index>(face_index.size()));

  struct Vertex_index_of
  {
    std::unordered_map<vertex_descriptor, Index> index;
    Index operator()(vertex_descriptor v) const
    {
      const auto it = index.find(v);
      return it == index.end() ? no_index : it->second;
    }
    void assign(vertex_descriptor v, Index i) { index.emplace(v, i); }
  } vertex_index_of;

  Indexed_triangle_mesh m;
  std::vector<vertex_descriptor> vertex_handles;
  // Coordinates play no role in topology.
  auto no_coordinates = [](vertex_descriptor) { return std::array<double, 3>{{ 0., 0., 0. }}; };
  auto face_index_of = [&](face_descriptor f)
  {
    const auto it = face_index.find(f);
    return it == face_index.end() ? no_index : it->second;
  };
  build_indexed_triangle_mesh(tm, face_range, no_coordinates, face_index_of, vertex_index_of, vertex_handles, m);

  std::vector<Index> region(m.number_of_faces());
  std::iota(region.begin(), region.end(), Index(0));
  Region_topology topology(m);
  return topology.count(region);
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_MESH_FACE_RANGE_TOPOLOGY_H
