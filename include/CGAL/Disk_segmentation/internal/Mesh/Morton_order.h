// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Renumbers the faces and vertices of the indexed mesh along a Morton
// (Z-order) curve, so that faces close on the surface get close indices.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_MESH_MORTON_ORDER_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_MESH_MORTON_ORDER_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh_type.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Spreads the low 21 bits of x three bits apart (bit i to bit 3i).
inline std::uint64_t spread_bits_by_three(std::uint64_t x)
{
  x &= 0x1fffffull;
  x = (x | (x << 32)) & 0x1f00000000ffffull;
  x = (x | (x << 16)) & 0x1f0000ff0000ffull;
  x = (x | (x << 8)) & 0x100f00f00f00f00full;
  x = (x | (x << 4)) & 0x10c30c30c30c30c3ull;
  x = (x | (x << 2)) & 0x1249249249249249ull;
  return x;
}

// Renumbers faces along a Morton (Z-order) curve of their centroids, and
// vertices in order of first use by the renumbered faces: faces close on
// the surface get close indices. Every pass of the package goes over
// regions in index order and reads their vertices; in a file's own order a
// compact region can be spread over the whole index range (CGAL's Loop
// step keeps one child of face i at i and appends the other three, so
// after L levels a patch lies in 2^L distant ranges). The order depends on
// the geometry and on the input order only among faces of one cell of the
// curve (2^-21 of the bounding box), so atlases barely depend on how the
// file lists its faces. `face_handles` and `vertex_handles` are permuted
// alike. Needs finite coordinates (see check_and_split_vertices).
template <typename FaceHandles, typename VertexHandles>
void renumber_for_locality(Indexed_triangle_mesh& m, FaceHandles& face_handles, VertexHandles& vertex_handles)
{
  constexpr double infinity = std::numeric_limits<double>::infinity();
  const std::size_t nf = m.number_of_faces(), nv = m.number_of_vertices();
  std::array<double, 3> lo{{ infinity, infinity, infinity }}, hi{{ -infinity, -infinity, -infinity }};
  for(const auto& c : m.corners)
    for(Index v : c)
      for(int k = 0; k < 3; ++k)
      {
        lo[k] = (std::min)(lo[k], m.points[v][k]);
        hi[k] = (std::max)(hi[k], m.points[v][k]);
      }
  // Halves first: the box of coordinates near the double range's ends
  // would overflow its side.
  std::array<double, 3> cells_per_half_unit;
  for(int k = 0; k < 3; ++k)
  {
    const double half_side = hi[k] / 2 - lo[k] / 2;
    cells_per_half_unit[k] = half_side > 0 ? double(1u << 21) / half_side : 0.;
  }
  std::vector<std::pair<std::uint64_t, Index> > key(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    std::uint64_t code = 0;
    for(int k = 0; k < 3; ++k)
    {
      const double sum = m.point(Index(f), 0)[k] / 6 + m.point(Index(f), 1)[k] / 6 + m.point(Index(f), 2)[k] / 6;
      // A subnormal box side makes the scale infinite: clamp before converting.
      const double cell = (sum - lo[k] / 2) * cells_per_half_unit[k];
      const double clamped = cell >= 0 ? (std::min)(cell, double((1u << 21) - 1)) : 0.;
      code |= spread_bits_by_three(std::uint64_t(clamped)) << k;
    }
    key[f] = std::make_pair(code, Index(f));
  }
  std::sort(key.begin(), key.end());

  std::vector<Index> new_face(nf);
  for(std::size_t i = 0; i < nf; ++i)
    new_face[key[i].second] = Index(i);
  std::vector<Index> new_vertex(nv, no_index);
  std::vector<Index> old_vertex;
  old_vertex.reserve(nv);
  for(std::size_t i = 0; i < nf; ++i)
    for(Index v : m.corners[key[i].second])
      if(new_vertex[v] == no_index)
      {
        new_vertex[v] = Index(old_vertex.size());
        old_vertex.push_back(v);
      }
  for(std::size_t v = 0; v < nv; ++v)  // vertices of no face, last
    if(new_vertex[v] == no_index)
    {
      new_vertex[v] = Index(old_vertex.size());
      old_vertex.push_back(Index(v));
    }

  std::vector<std::array<Index, 3> > corners(nf), neighbors(nf);
  FaceHandles faces_in_order;
  faces_in_order.reserve(nf);
  for(std::size_t i = 0; i < nf; ++i)
  {
    const Index f = key[i].second;
    for(int j = 0; j < 3; ++j)
    {
      corners[i][j] = new_vertex[m.corners[f][j]];
      neighbors[i][j] = m.neighbors[f][j] == no_index ? no_index : new_face[m.neighbors[f][j]];
    }
    put_smallest_vertex_first(corners[i], neighbors[i]);
    faces_in_order.push_back(face_handles[f]);
  }
  m.corners.swap(corners);
  m.neighbors.swap(neighbors);
  face_handles.swap(faces_in_order);
  m.input_face.resize(nf);
  for(std::size_t i = 0; i < nf; ++i)
    m.input_face[i] = key[i].second;

  std::vector<std::array<double, 3> > points(nv);
  VertexHandles vertices_in_order;
  vertices_in_order.reserve(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    points[i] = m.points[old_vertex[i]];
    vertices_in_order.push_back(vertex_handles[old_vertex[i]]);
  }
  m.points.swap(points);
  vertex_handles.swap(vertices_in_order);
  if(!m.split_from.empty())
  {
    // The copies of an input vertex all stand for the first of them.
    std::vector<Index> split_from(nv, no_index);
    std::vector<Index> stands_for(nv, no_index);  // old representative -> new one
    for(std::size_t i = 0; i < nv; ++i)
    {
      Index& first = stands_for[m.split_from[old_vertex[i]]];
      if(first == no_index)
        first = Index(i);
      split_from[i] = first;
    }
    m.split_from.swap(split_from);
  }
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_MESH_MORTON_ORDER_H
