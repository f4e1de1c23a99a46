// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_FREE_BORDER_LSCM_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_FREE_BORDER_LSCM_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Local_global_arap.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Least squares conformal map (Levy et al. 2002) of a disk, free border,
// as the ARAP start. The same map as SMP::LSCM_parameterizer_3, assembled
// here from the cotangent Laplacian L and the border's signed area term:
// the conformal energy is E_D(u) + E_D(v) - A(u, v) = 1/2 x^T H x with
// H = [L, -M/2; M/2, L], M the antisymmetric border incidence (M_ij = 1 for
// a border edge i -> j, counterclockwise). SMP's version builds a
// Surface_mesh, sets of faces and a least squares system row by row for the
// same factorization; on the charts of the top-down choice (most of them
// small) that overhead cost more than the factorization.
//
// Two border vertices far apart are pinned (the one farthest from the
// first border vertex, then the one farthest from it, at their 3D
// distance apart on the u axis), which removes the similarities from the
// null space. `border` is the chart's border cycle in the orientation of
// its (counterclockwise) triangles `g.triangles`. Returns false when the factorization
// fails (degenerate triangles); `uv` is then unspecified.
inline bool free_border_lscm(const Chart_geometry& g, const std::vector<std::size_t>& border,
                             std::vector<std::array<double, 2> >& uv)
{
  const std::vector<std::array<double, 3> >& points = g.points;
  const std::size_t n = points.size();
  uv.assign(n, {{ 0., 0. }});
  if(n < 3 || border.size() < 3)
    return false;
  auto distance2 = [&](std::size_t a, std::size_t b) {
    double d = 0;
    for(int k = 0; k < 3; ++k)
      d += (points[a][k] - points[b][k]) * (points[a][k] - points[b][k]);
    return d;
  };
  auto farthest_on_border = [&](std::size_t from) {
    std::size_t best = border[0];
    for(std::size_t v : border)
      if(distance2(from, v) > distance2(from, best))
        best = v;
    return best;
  };
  const std::size_t pin0 = farthest_on_border(border[0]);
  const std::size_t pin1 = farthest_on_border(pin0);
  const double span = std::sqrt(distance2(pin0, pin1));
  if(pin0 == pin1 || !(span > 0))
    return false;
  uv[pin1] = {{ span, 0. }};

  // Free vertex k (in elimination order) has unknowns 2k (u) and 2k+1 (v).
  const Eigen::Index none = -1;
  const std::vector<Eigen::Index>& rank = g.elimination_rank;
  std::vector<Eigen::Index> unknown(n, none);
  const Eigen::Index free_vertices = static_cast<Eigen::Index>(n) - 2;
  for(std::size_t v = 0; v < n; ++v)
    if(v != pin0 && v != pin1)
      unknown[v] = rank[v] - (rank[v] > rank[pin0] ? 1 : 0) - (rank[v] > rank[pin1] ? 1 : 0);
  if(!g.has_frames)
    return false;
  const Chart_edges& edges = g.edges;
  const std::vector<double>& edge_weight = g.edge_weight;
  const std::vector<double>& vertex_weight = g.vertex_weight;
  // +1 (-1) where the border runs along an edge from its first (second)
  // end to the other, 0 off the border.
  std::vector<signed char> border_direction(edges.ends.size(), 0);
  for(std::size_t k = 0; k < border.size(); ++k)
  {
    const std::size_t i = border[k], j = border[(k + 1) % border.size()];
    const std::size_t e = edges.between(i, j);
    if(e == Chart_edges::none)
      return false;
    border_direction[e] = static_cast<signed char>(edges.ends[e][0] == i ? 1 : -1);
  }
  // H at (2 x + c, 2 y + 1 - c) for the edge e between x and y: the border
  // term -1/2 (u_i v_j - u_j v_i) of each border edge i -> j, symmetrized.
  auto cross = [&](std::size_t x, std::size_t e, int c) {
    const double along = edges.ends[e][0] == x ? border_direction[e] : -border_direction[e];
    return along * (c == 0 ? -0.5 : 0.5);
  };
  if(free_vertices == 0)
    return true;
  std::vector<std::size_t> vertex_of(static_cast<std::size_t>(free_vertices));
  for(std::size_t v = 0; v < n; ++v)
    if(unknown[v] != none)
      vertex_of[std::size_t(unknown[v])] = v;
  // Pinned neighbors move to the right-hand side.
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * free_vertices);
  for(std::size_t v = 0; v < n; ++v)
    if(unknown[v] != none)
      for(std::size_t k = edges.first[v]; k < edges.first[v + 1]; ++k)
      {
        const std::size_t p = edges.neighbor[k], e = edges.edge[k];
        if(unknown[p] == none)
          for(int c = 0; c < 2; ++c)
            rhs[2 * unknown[v] + c] += edge_weight[e] * uv[p][c] - cross(v, e, c) * uv[p][1 - c];
      }
  Eigen::SparseMatrix<double> h;
  assemble_upper_triangle(2 * free_vertices, 2 * std::size_t(free_vertices) + 4 * edges.ends.size(),
                          [&](Eigen::Index column, const auto& add) {
    const std::size_t v = vertex_of[std::size_t(column / 2)];
    const int c = int(column % 2);
    add(column, vertex_weight[v]);
    for(std::size_t k = edges.first[v]; k < edges.first[v + 1]; ++k)
    {
      const std::size_t w = edges.neighbor[k], e = edges.edge[k];
      if(unknown[w] == none || unknown[w] >= unknown[v])
        continue;
      add(2 * unknown[w] + c, -edge_weight[e]);
      if(border_direction[e] != 0)
        add(2 * unknown[w] + 1 - c, cross(w, e, 1 - c));
    }
  }, h);
  Ordered_sparse_ldlt solver(h);
  if(solver.info() != Eigen::Success)
    return false;
  const Eigen::VectorXd x = solver.solve(rhs);
  if(solver.info() != Eigen::Success)
    return false;
  for(std::size_t v = 0; v < n; ++v)
    if(unknown[v] != none)
      uv[v] = {{ x[2 * unknown[v]], x[2 * unknown[v] + 1] }};
  return true;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_FREE_BORDER_LSCM_H
