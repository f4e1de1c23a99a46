// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Splits a pinched vertex of the indexed mesh, one whose faces form several
// fans, into one vertex per fan; checks the coordinates on the way.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_MESH_PINCHED_VERTEX_SPLITTING_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_MESH_PINCHED_VERTEX_SPLITTING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh_type.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Gives each fan of faces around a pinched vertex `v` but the first (in face
// order) a copy of `v`: same position, same descriptor in `vertex_handles`.
// `around` lists the corners (face, position) at `v` in increasing face
// order. Fans are found across the edges at `v`, through `m.neighbors`.
template <typename VertexHandles>
void split_pinched_vertex(Index v,
                          const std::vector<std::pair<Index, int> >& around,
                          VertexHandles& vertex_handles,
                          Indexed_triangle_mesh& m)
{
  std::vector<bool> reached(around.size(), false);
  auto position_of = [&around](Index f) {
    return std::size_t(std::lower_bound(around.begin(), around.end(), std::make_pair(f, 0)) - around.begin());
  };
  std::vector<std::size_t> stack;
  bool first_fan = true;
  for(std::size_t start = 0; start < around.size(); ++start)
  {
    if(reached[start])
      continue;
    Index copy = v;
    if(!first_fan)
    {
      copy = static_cast<Index>(m.points.size());
      const std::array<double, 3> p = m.points[v];
      if(m.split_from.empty())
      {
        m.split_from.resize(m.points.size());
        for(std::size_t i = 0; i < m.split_from.size(); ++i)
          m.split_from[i] = Index(i);
      }
      m.points.push_back(p);
      m.split_from.push_back(m.split_from[v]);
      vertex_handles.push_back(vertex_handles[v]);
    }
    first_fan = false;
    reached[start] = true;
    stack.assign(1, start);
    // Each corner is pushed once (`reached`): at most around.size() passes in all.
    while(!stack.empty())
    {
      const std::pair<Index, int> corner = around[stack.back()];
      stack.pop_back();
      m.corners[corner.first][corner.second] = copy;
      // The two edges of the face at v: (v, next) and (previous, v).
      for(int edge : { corner.second, (corner.second + 2) % 3 })
      {
        const Index g = m.neighbors[corner.first][edge];
        if(g == no_index)
          continue;
        const std::size_t q = position_of(g);
        if(q < around.size() && around[q].first == g && !reached[q])
        {
          reached[q] = true;
          stack.push_back(q);
        }
      }
    }
  }
}

// split_pinched_vertex() for each of `vertices` (`slot[v]` is v's position
// in it, `no_index` for the other vertices), with one pass over the faces.
template <typename VertexHandles>
void split_into_fans(const std::vector<Index>& vertices, const std::vector<Index>& slot,
                     VertexHandles& vertex_handles, Indexed_triangle_mesh& m)
{
  if(vertices.empty())
    return;
  std::vector<std::vector<std::pair<Index, int> > > around(vertices.size());
  for(Index f = 0; f < m.number_of_faces(); ++f)
    for(int i = 0; i < 3; ++i)
      if(slot[m.corners[f][i]] != no_index)
        around[slot[m.corners[f][i]]].emplace_back(f, i);
  for(std::size_t i = 0; i < vertices.size(); ++i)
    split_pinched_vertex(vertices[i], around[i], vertex_handles, m);
  // Faces keep their smallest vertex first (see Indexed_triangle_mesh).
  for(const auto& corners_at_vertex : around)
    for(const std::pair<Index, int>& corner : corners_at_vertex)
      put_smallest_vertex_first(m.corners[corner.first], m.neighbors[corner.first]);
}

// Checks what the algorithms rely on beyond triangles: finite coordinates.
// The faces around a vertex must form one fan (open or closed) for the
// algorithms; a pinched vertex, whose faces form several, is split in the
// indexed mesh (one vertex per fan, see split_pinched_vertex): the mesh is
// then cut there, as an atlas cuts it anyway, and `tm` is left as it is.
// The halfedge structure reaches only one fan from a vertex, so a vertex
// whose face count differs from the fan reached by circulation, or that
// meets the border twice, is pinched. Vertices without faces are ignored.
// Only meaningful when the indexed mesh covers all faces of `tm`. Returns the
// number of vertices added.
template <typename TriangleMesh, typename VertexHandles>
std::size_t check_and_split_vertices(const TriangleMesh& tm,
                                     VertexHandles& vertex_handles,
                                     Indexed_triangle_mesh& m)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  const std::size_t number_of_vertices = m.number_of_vertices();
  std::vector<Index> faces_per_vertex(number_of_vertices, 0);
  for(const auto& c : m.corners)
    for(Index v : c) ++faces_per_vertex[v];

  std::vector<Index> pinched_slot(number_of_vertices, no_index);
  std::vector<Index> pinched;
  for(std::size_t v = 0; v < number_of_vertices; ++v)
  {
    if(faces_per_vertex[v] == 0)
      continue;
    const auto& p = m.points[v];
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw Input_error("the mesh has a non-finite (NaN or infinite) coordinate at vertex #" +
                        std::to_string(v));
    std::size_t fan_faces = 0, border_halfedges = 0;
    // Ends: in a valid halfedge graph the circulation returns to its start
    // after the halfedges of one fan at v.
    for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(vertex_handles[v], tm), tm))
    {
      if(is_border(h, tm)) ++border_halfedges;
      else ++fan_faces;
    }
    if(border_halfedges > 1 || fan_faces != faces_per_vertex[v])
    {
      pinched_slot[v] = static_cast<Index>(pinched.size());
      pinched.push_back(static_cast<Index>(v));
    }
  }
  split_into_fans(pinched, pinched_slot, vertex_handles, m);
  return m.number_of_vertices() - number_of_vertices;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_MESH_PINCHED_VERTEX_SPLITTING_H
