// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Brings each connected component of the indexed mesh to a frame of unit
// size by exact scalings, so that huge and tiny meshes compute like others.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_MESH_COORDINATE_NORMALIZATION_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_MESH_COORDINATE_NORMALIZATION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh_type.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// A power of two 2^k such that `side` * 2^k lies in [1, 2), k bounded so
// that 2^k stays finite for a subnormal side; 1 for a zero or non-finite side.
inline double unit_scale(double side)
{
  if(!(side > 0) || !std::isfinite(side))
    return 1.;
  int exponent = 0;
  std::frexp(side, &exponent);  // side = f * 2^exponent, f in [0.5, 1)
  return std::ldexp(1., (std::min)(1 - exponent, std::numeric_limits<double>::max_exponent - 1));
}

// Centers each connected component of the used vertices and scales it by a
// power of two so that its bounding box side lies in [1, 2). Every
// algorithm of the package is invariant under similarities, and scaling by
// a power of two is exact, so results do not change, while huge (1e30) and
// tiny (1e-30) meshes meet the floating-point ranges of unit-size ones (no
// overflow of squared lengths, no underflow of areas). Each component gets
// its own frame because nothing relates positions across components, while
// one shared frame would lose a component much smaller than the mesh: a
// shared center rounds its shape away (a 1e-20 wide copy next to a 1e20
// wide one collapses to a point), a shared scale underflows its squared
// lengths and areas (a 1e-150 wide one next to a 1e150 wide one). Where
// sizes are compared across components (farthest-point seeds, atlas
// totals), `Indexed_triangle_mesh::common_unit` brings them to the frame of
// the largest component.
inline void normalize_coordinates(Indexed_triangle_mesh& m)
{
  constexpr double infinity = std::numeric_limits<double>::infinity();
  const std::size_t nv = m.number_of_vertices();
  m.face_component.clear();
  m.component_unit.clear();
  // Union-find over the corners: vertex -> component root.
  std::vector<Index> parent(nv);
  for(std::size_t v = 0; v < nv; ++v)
    parent[v] = static_cast<Index>(v);
  // Ends: a non-root's parent is a smaller index (unions link the larger root
  // to the smaller), so v strictly decreases.
  auto find = [&parent](Index v) {
    while(parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for(const auto& c : m.corners)
    for(int i = 1; i < 3; ++i)
    {
      const Index a = find(c[0]), b = find(c[i]);
      if(a != b)
        parent[(std::max)(a, b)] = (std::min)(a, b);
    }

  // Components numbered in order of first corner; bounding box of each.
  std::vector<std::array<double, 6> > box;  // lo, hi
  std::vector<Index> component_of_root(nv, no_index);
  for(const auto& c : m.corners)
    for(Index v : c)
    {
      Index& b = component_of_root[find(v)];
      if(b == no_index)
      {
        b = static_cast<Index>(box.size());
        box.push_back({{ infinity, infinity, infinity, -infinity, -infinity, -infinity }});
      }
      for(int k = 0; k < 3; ++k)
      {
        box[b][k] = (std::min)(box[b][k], m.points[v][k]);
        box[b][k + 3] = (std::max)(box[b][k + 3], m.points[v][k]);
      }
    }
  std::vector<double> side(box.size());
  double largest = 0;
  for(std::size_t b = 0; b < box.size(); ++b)
  {
    side[b] = (std::max)(box[b][3] - box[b][0], (std::max)(box[b][4] - box[b][1], box[b][5] - box[b][2]));
    largest = (std::max)(largest, side[b]);
  }
  if(!(largest > 0) || !std::isfinite(largest))
    return;
  m.normalization_scale = unit_scale(largest);
  std::vector<double> scale(box.size());
  for(std::size_t b = 0; b < box.size(); ++b)
    // A component whose vertices all coincide keeps the common frame.
    scale[b] = side[b] > 0 ? unit_scale(side[b]) : m.normalization_scale;
  if(box.size() > 1)  // one component: its frame is the common one
  {
    m.component_unit.resize(box.size());
    for(std::size_t b = 0; b < box.size(); ++b)
      m.component_unit[b] = m.normalization_scale / scale[b];  // exact, or 0 past the double range
    m.face_component.resize(m.number_of_faces());
    for(std::size_t f = 0; f < m.number_of_faces(); ++f)
      m.face_component[f] = component_of_root[find(m.corners[f][0])];
  }
  // Vertices without faces are never read: they are left as they are.
  for(std::size_t v = 0; v < nv; ++v)
  {
    const Index b = component_of_root[find(static_cast<Index>(v))];
    if(b != no_index)
      for(int k = 0; k < 3; ++k)
        m.points[v][k] = (m.points[v][k] - (box[b][k] / 2 + box[b][k + 3] / 2)) * scale[b];
  }
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_MESH_COORDINATE_NORMALIZATION_H
