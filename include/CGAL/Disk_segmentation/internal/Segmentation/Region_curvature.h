// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Gaussian curvature a region holds inside it, which predicts charts
// too curved to meet the distortion bound.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_REGION_CURVATURE_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_REGION_CURVATURE_H

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_slots.h>

#include <CGAL/number_type_config.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// The Gaussian curvature a region holds inside it: the sum of the angle
// defects (2 pi minus the angles around the vertex) of the vertices whose
// faces all belong to the region, vertices on the mesh's border excluded.
// By Gauss-Bonnet it is what the region's border must turn away from 2 pi
// to lie flat, so a large value says that no flattening of the region is
// close to an isometry. Signed: the noise of scanned surfaces cancels out.
class Interior_curvature
{
public:
  explicit Interior_curvature(const Indexed_triangle_mesh& m)
    : defect_(m.number_of_vertices(), 2. * CGAL_PI), degree_(m.number_of_vertices(), 0)
  {
    for(Index f = 0; f < m.number_of_faces(); ++f)
      for(int j = 0; j < 3; ++j)
      {
        const Index v = m.corners[f][j];
        ++degree_[v];
        defect_[v] -= corner_angle(m.points[v], m.points[m.corners[f][(j + 1) % 3]], m.points[m.corners[f][(j + 2) % 3]]);
      }
    for(Index f = 0; f < m.number_of_faces(); ++f)
      for(int j = 0; j < 3; ++j)
        if(m.neighbors[f][j] == no_index)
        {
          degree_[m.corners[f][j]] = border_vertex;
          degree_[m.corners[f][(j + 1) % 3]] = border_vertex;
        }
    number_cells(m);
  }

  // What a region holds: its signed total (see above) and its spread, the
  // curvature it holds cell by cell, in absolute value, summed over the
  // cells of a grid whose side is `cells_across` times less than the square
  // root of the mesh's area: curvature of both signs in different places
  // (a bumpy flank, a leg beside a belly) cancels in the signed total but
  // adds up in the spread, while noise finer than a cell still cancels. The
  // spread is at least the absolute value of the signed total.
  struct Totals
  {
    double signed_total = 0.;
    double spread = 0.;
  };

  // Both totals in one walk over the region. Thread-safe: the scratch is
  // per thread.
  Totals totals(const Indexed_triangle_mesh& m, const std::vector<Index>& faces) const
  {
    // Zero between calls; one per thread, since queries run in parallel.
    thread_local std::vector<double> in_cell;
    thread_local std::vector<char> met;
    thread_local std::vector<Index> touched;
    if(in_cell.size() < number_of_cells_)
    {
      in_cell.resize(number_of_cells_, 0.);
      met.resize(number_of_cells_, 0);
    }
    touched.clear();
    Totals t;
    for_each_interior_vertex(m, faces, [&](Index v) {
      t.signed_total += defect_[v];
      const Index c = cell_[v];
      if(!met[c])
      {
        met[c] = 1;
        touched.push_back(c);
      }
      in_cell[c] += defect_[v];
    });
    // Cells in the order first met: the sum does not depend on the thread.
    for(Index c : touched)
    {
      t.spread += std::abs(in_cell[c]);
      in_cell[c] = 0.;
      met[c] = 0;
    }
    return t;
  }

  static constexpr double cells_across = 8.;

  // The interior vertex of the region with the largest |angle defect| (the
  // smallest index among equals), and that defect; no_index if none.
  Index sharpest_interior_vertex(const Indexed_triangle_mesh& m, const std::vector<Index>& faces,
                                 double& defect) const
  {
    Index sharpest = no_index;
    defect = 0.;
    for_each_interior_vertex(m, faces, [&](Index v) {
      const double d = std::abs(defect_[v]);
      if(d > std::abs(defect) || (d == std::abs(defect) && sharpest != no_index && v < sharpest))
      {
        sharpest = v;
        defect = defect_[v];
      }
    });
    return sharpest;
  }

private:
  // Calls `visit(v)` once for every interior vertex of the region: when
  // the last of its faces is met. Counting per vertex rather than sorting
  // the corners: the sort was 3 to 6 % of the whole atlas's time.
  template <typename Visit>
  void for_each_interior_vertex(const Indexed_triangle_mesh& m, const std::vector<Index>& faces,
                                const Visit& visit) const
  {
    // One per thread, since queries run in parallel; sized to the region.
    thread_local Region_slots vertex_position;
    thread_local std::vector<Index> faces_met;
    vertex_position.clear_for_corners(m, faces);
    release_if_far_larger(faces_met, 3 * faces.size());
    faces_met.assign(3 * faces.size(), 0);  // room for every corner's own vertex
    for(Index f : faces)
      for(Index v : m.corners[f])
        if(++faces_met[vertex_position.insert(v)] == degree_[v])
          visit(v);
  }

  static constexpr Index border_vertex = no_index;

  // Numbers the grid cells that hold a vertex, in the order of the
  // vertices. Components are normalized each in its own frame: each has
  // its own grid, of the same side in common units.
  void number_cells(const Indexed_triangle_mesh& m)
  {
    const std::size_t nv = m.number_of_vertices();
    cell_.assign(nv, 0);
    std::vector<double> unit(nv, 1.);
    std::vector<Index> component(nv, 0);
    for(Index f = 0; f < m.number_of_faces(); ++f)
      for(Index v : m.corners[f])
      {
        unit[v] = m.common_unit(f);
        component[v] = m.face_component.empty() ? 0 : m.face_component[f];
      }
    const double side = std::sqrt(m.total_common_area()) / cells_across;
    struct Hash
    {
      std::size_t operator()(const std::array<std::int64_t, 4>& k) const
      {
        std::uint64_t h = 0;
        for(std::int64_t x : k)
          h = (h ^ std::uint64_t(x)) * 0x9E3779B97F4A7C15ull;
        return std::size_t(h ^ (h >> 29));
      }
    };
    // Numbered in the order of the vertices: the hash order does not matter.
    std::unordered_map<std::array<std::int64_t, 4>, Index, Hash> number;
    for(std::size_t v = 0; v < nv; ++v)
    {
      std::array<std::int64_t, 4> key = {{ std::int64_t(component[v]), 0, 0, 0 }};
      // Unit 0: the component is below the double range next to the largest.
      const double local_side = unit[v] > 0. ? side / unit[v] : 0.;
      for(int k = 0; k < 3; ++k)
        key[k + 1] = local_side > 0. && std::isfinite(local_side)
                       ? static_cast<std::int64_t>(std::floor(m.points[v][k] / local_side))
                       : 0;
      const auto inserted = number.emplace(key, static_cast<Index>(number.size()));
      cell_[v] = inserted.first->second;
    }
    number_of_cells_ = number.size();
  }

  static double corner_angle(const std::array<double, 3>& a, const std::array<double, 3>& b,
                             const std::array<double, 3>& c)
  {
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
    return std::atan2(std::sqrt(x * x + y * y + z * z), u[0] * v[0] + u[1] * v[1] + u[2] * v[2]);
  }

  std::vector<double> defect_;
  std::vector<Index> degree_;  // faces around each vertex; border_vertex on the mesh's border
  std::vector<Index> cell_;    // per vertex, see totals()
  std::size_t number_of_cells_ = 0;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_REGION_CURVATURE_H
