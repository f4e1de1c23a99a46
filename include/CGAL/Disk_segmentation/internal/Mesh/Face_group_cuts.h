// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cuts the indexed mesh along the edges between faces of different groups
// (materials), so that no chart holds two groups.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_MESH_FACE_GROUP_CUTS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_MESH_FACE_GROUP_CUTS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh_type.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Pinched_vertex_splitting.h>

#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Faces of different groups (`group[f]`, e.g. materials) never share a
// chart: the indexed mesh is cut along the edges between them (no neighbor
// across), as if they were borders, and a vertex on such an edge gets one
// copy per fan left around it (see split_pinched_vertex()), so that every
// pass of the package sees the groups as separate surfaces. Returns the
// number of vertices added.
template <typename Group, typename VertexHandles>
std::size_t cut_between_face_groups(const std::vector<Group>& group, VertexHandles& vertex_handles,
                                    Indexed_triangle_mesh& m)
{
  const std::size_t number_of_vertices = m.number_of_vertices();
  std::vector<Index> cut_slot(number_of_vertices, no_index);
  std::vector<Index> cut_vertices;
  for(Index f = 0; f < m.number_of_faces(); ++f)
    for(int i = 0; i < 3; ++i)
    {
      const Index g = m.neighbors[f][i];
      if(g == no_index || group[f] == group[g])
        continue;
      m.neighbors[f][i] = no_index;
      for(Index v : { m.corners[f][i], m.corners[f][(i + 1) % 3] })
        if(cut_slot[v] == no_index)
        {
          cut_slot[v] = static_cast<Index>(cut_vertices.size());
          cut_vertices.push_back(v);
        }
    }
  split_into_fans(cut_vertices, cut_slot, vertex_handles, m);
  return m.number_of_vertices() - number_of_vertices;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_MESH_FACE_GROUP_CUTS_H
