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
  const std::vector<std::array<std::size_t, 3> >& triangles = g.triangles;
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
  std::vector<Eigen::Triplet<double> > entries;
  entries.reserve(14 * triangles.size() + 2 * border.size());
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * free_vertices);
  // Adds h to H at (row, col) for coordinates cr, cc (0: u, 1: v) of
  // vertices r, c; a pinned column goes to the right-hand side.
  // Only the lower triangle goes to the matrix (the solver reads no more).
  auto add = [&](std::size_t r, int cr, std::size_t c, int cc, double h) {
    if(unknown[r] == none)
      return;
    const Eigen::Index row = 2 * unknown[r] + cr;
    if(unknown[c] == none)
      rhs[row] -= h * uv[c][cc];
    else if(row >= 2 * unknown[c] + cc)
      entries.emplace_back(row, 2 * unknown[c] + cc, h);
  };

  std::vector<std::array<std::array<double, 2>, 3> > frames;
  std::vector<std::array<double, 3> > cot;
  if(!isometric_frames(points, triangles, frames, cot))
    return false;
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(int i = 0; i < 3; ++i)
    {
      const double weight = 0.5 * cot[t][i];
      const std::size_t va = triangles[t][i], vb = triangles[t][(i + 1) % 3];
      for(int coordinate = 0; coordinate < 2; ++coordinate)
      {
        add(va, coordinate, va, coordinate, weight);
        add(vb, coordinate, vb, coordinate, weight);
        add(va, coordinate, vb, coordinate, -weight);
        add(vb, coordinate, va, coordinate, -weight);
      }
    }
  for(std::size_t k = 0; k < border.size(); ++k)
  {
    const std::size_t i = border[k], j = border[(k + 1) % border.size()];
    // -1/2 (u_i v_j - u_j v_i), symmetrized.
    add(i, 0, j, 1, -0.5);
    add(j, 1, i, 0, -0.5);
    add(j, 0, i, 1, 0.5);
    add(i, 1, j, 0, 0.5);
  }
  if(free_vertices == 0)
    return true;
  Eigen::SparseMatrix<double> h(2 * free_vertices, 2 * free_vertices);
  h.setFromTriplets(entries.begin(), entries.end());
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
