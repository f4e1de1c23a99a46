// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The faces around every vertex of the indexed mesh, in one array.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_MESH_VERTEX_FACES_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_MESH_VERTEX_FACES_H

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>

#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// The faces around every vertex of an indexed mesh, in one array: the faces
// of vertex v are faces[begin[v]] to faces[begin[v + 1] - 1], by increasing
// face index. With `by_input_vertex`, the faces of all the copies of a
// pinched input vertex are listed under the one that stands for them
// (Indexed_triangle_mesh::input_vertex()), the other copies having none.
struct Vertex_faces
{
  std::vector<Index> begin, faces;

  explicit Vertex_faces(const Indexed_triangle_mesh& m, bool by_input_vertex = false)
  {
    auto vertex = [&](Index v) { return by_input_vertex ? m.input_vertex(v) : v; };
    begin.assign(m.number_of_vertices() + 1, 0);
    for(const auto& c : m.corners)
      for(Index v : c) ++begin[vertex(v) + 1];
    for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
      begin[v + 1] += begin[v];
    faces.resize(3 * m.number_of_faces());
    std::vector<Index> fill(begin.begin(), begin.end() - 1);
    for(Index f = 0; f < m.number_of_faces(); ++f)
      for(Index v : m.corners[f]) faces[fill[vertex(v)]++] = f;
  }
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_MESH_VERTEX_FACES_H
