// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A checked triangle soup (manifold edges, consistently oriented: what the
// disk_uv tool's readers check) turned into a halfedge mesh in O(F log F),
// whatever the valences. CGAL's
// polygon_soup_to_polygon_mesh() adds the faces one by one through
// Euler::add_face(), which walks around each corner's vertex: a vertex of
// valence 200k cost 48 s there.
//
// The mesh is the one CGAL's function builds: vertex i and face i of the
// soup, the edges in the order the faces first use them, each edge's first
// halfedge running as in the face that first uses it, each face's halfedge
// the one that ends at its first corner, and each border vertex's halfedge
// its incoming border halfedge. Only an inner vertex's halfedge may be
// another one of its incoming halfedges.
//
// A pinched vertex (its faces in several fans), which CGAL's function
// refuses, is kept: the border halfedge into it is followed by the one
// that leaves it along the same fan, so that circulating around it stays
// in one fan (the package's indexed mesh finds the vertex pinched from
// there and cuts it, see check_and_split_vertices()).

#ifndef CGAL_DISK_SEGMENTATION_IO_INTERNAL_TRIANGLE_SOUP_TO_MESH_H
#define CGAL_DISK_SEGMENTATION_IO_INTERNAL_TRIANGLE_SOUP_TO_MESH_H

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {
namespace internal {

// Builds `mesh` (cleared first) from `points` and `triangles`, which must
// form a consistently oriented triangle mesh with manifold edges, pinched
// vertices allowed (throws std::logic_error where it sees otherwise). `Mesh`
// is a model of MutableFaceGraph.
template <typename Point, typename Mesh>
void checked_triangle_soup_to_mesh(const std::vector<Point>& points,
                                   const std::vector<std::vector<std::size_t> >& triangles, Mesh& mesh)
{
  typedef boost::graph_traits<Mesh> Traits;
  typedef typename Traits::vertex_descriptor vertex_descriptor;
  typedef typename Traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Traits::face_descriptor face_descriptor;

  clear(mesh);
  const std::size_t corners = 3 * triangles.size();
  if(points.size() >= (std::size_t(1) << 32) || corners >= (std::size_t(1) << 32))
    throw std::logic_error("checked_triangle_soup_to_mesh: more than 2^32 vertices or corners");
  reserve(mesh, static_cast<typename Traits::vertices_size_type>(points.size()),
          static_cast<typename Traits::edges_size_type>(corners / 2 + 1),
          static_cast<typename Traits::faces_size_type>(triangles.size()));

  auto point_map = get(CGAL::vertex_point, mesh);
  std::vector<vertex_descriptor> vertices;
  vertices.reserve(points.size());
  for(const Point& p : points)
  {
    vertices.push_back(add_vertex(mesh));
    put(point_map, vertices.back(), p);
  }

  // Corner c = 3f + i stands for the directed edge from triangles[f][i] to
  // triangles[f][(i + 1) % 3]; sorting by undirected edge puts the two
  // corners of an inner edge side by side.
  auto from = [&](std::uint32_t c) { return triangles[c / 3][c % 3]; };
  auto to = [&](std::uint32_t c) { return triangles[c / 3][(c % 3 + 1) % 3]; };
  auto key = [&](std::uint32_t c) {
    const std::uint64_t a = from(c), b = to(c);
    return (std::min)(a, b) << 32 | (std::max)(a, b);
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t> > by_edge(corners);
  for(std::uint32_t c = 0; c < corners; ++c)
    by_edge[c] = std::make_pair(key(c), c);
  std::sort(by_edge.begin(), by_edge.end());
  const std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
  std::vector<std::uint32_t> partner(corners, none);
  for(std::size_t i = 0; i + 1 < corners; ++i)
    if(by_edge[i].first == by_edge[i + 1].first)
    {
      if(i + 2 < corners && by_edge[i + 2].first == by_edge[i].first)
        throw std::logic_error("checked_triangle_soup_to_mesh: an edge of three faces");
      partner[by_edge[i].second] = by_edge[i + 1].second;
      partner[by_edge[i + 1].second] = by_edge[i].second;
      ++i;
    }
  std::vector<std::pair<std::uint64_t, std::uint32_t> >().swap(by_edge);

  // Edges in order of first use, each halfedge running as in that face.
  std::vector<halfedge_descriptor> corner_halfedge(corners);
  std::vector<halfedge_descriptor> incoming_border(points.size(), Traits::null_halfedge());
  std::vector<halfedge_descriptor> outgoing_border(points.size(), Traits::null_halfedge());
  std::vector<bool> several_borders(points.size(), false);  // a pinched vertex with open fans
  for(std::uint32_t c = 0; c < corners; ++c)
  {
    if(partner[c] != none && partner[c] < c)
      continue;
    const halfedge_descriptor h = halfedge(add_edge(mesh), mesh);
    const halfedge_descriptor o = opposite(h, mesh);
    set_target(h, vertices[to(c)], mesh);
    set_target(o, vertices[from(c)], mesh);
    corner_halfedge[c] = h;
    if(partner[c] != none)
    {
      if(from(partner[c]) != to(c))
        throw std::logic_error("checked_triangle_soup_to_mesh: faces oriented inconsistently");
      corner_halfedge[partner[c]] = o;
    }
    else
    {
      set_face(o, Traits::null_face(), mesh);
      if(incoming_border[from(c)] == Traits::null_halfedge())
        incoming_border[from(c)] = o;
      else
        several_borders[from(c)] = true;
      if(outgoing_border[to(c)] == Traits::null_halfedge())
        outgoing_border[to(c)] = o;
      else
        several_borders[to(c)] = true;
    }
  }

  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    const face_descriptor face = add_face(mesh);
    for(std::size_t i = 0; i < 3; ++i)
    {
      const halfedge_descriptor h = corner_halfedge[3 * f + i];
      set_face(h, face, mesh);
      set_next(h, corner_halfedge[3 * f + (i + 1) % 3], mesh);
      set_halfedge(vertices[triangles[f][(i + 1) % 3]], h, mesh);
    }
    set_halfedge(face, corner_halfedge[3 * f + 2], mesh);
  }
  // Around a border vertex, the border halfedge in comes before the one out.
  for(std::size_t v = 0; v < points.size(); ++v)
    if(incoming_border[v] != Traits::null_halfedge())
    {
      if(!several_borders[v])
        set_next(incoming_border[v], outgoing_border[v], mesh);
      set_halfedge(vertices[v], incoming_border[v], mesh);
    }
  // At such a vertex v, the border corner c leaving v (its border halfedge
  // comes into v) starts an open fan: across the fan's inner edges it
  // reaches the border corner coming into v, whose border halfedge leaves v.
  for(std::uint32_t c = 0; c < corners; ++c)
    if(partner[c] == none && several_borders[from(c)])
    {
      std::uint32_t into_v = 3 * (c / 3) + (c % 3 + 2) % 3;
      // Ends: each step crosses an inner edge at v to the next face of an
      // open fan, in one turning direction (the faces are oriented alike).
      while(partner[into_v] != none)
      {
        const std::uint32_t out_of_v = partner[into_v];
        into_v = 3 * (out_of_v / 3) + (out_of_v % 3 + 2) % 3;
      }
      set_next(opposite(corner_halfedge[c], mesh), opposite(corner_halfedge[into_v], mesh), mesh);
    }
}

} // namespace internal
} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_INTERNAL_TRIANGLE_SOUP_TO_MESH_H
