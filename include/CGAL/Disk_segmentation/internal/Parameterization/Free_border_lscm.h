// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Least squares conformal map of a disk with a free border, the start
// of ARAP, assembled and solved here with one factorization.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_FREE_BORDER_LSCM_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_FREE_BORDER_LSCM_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Parameterization/Hermitian_ldlt.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Local_global_arap.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
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

  // Free vertex k (in elimination order) has the unknown z_k = u_k + i v_k.
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
  const std::vector<double>& edge_weight = g.lscm_edge_weight();
  const std::vector<double>& vertex_weight = g.lscm_vertex_weight();
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
  // H's 2 x 2 blocks [a, -b; b, a] act on (u, v) as a + i b acts on z, so
  // H is the Hermitian matrix Hc of half its size: Hc(x, y) = -w_e + i b
  // for the edge e between x and y, with b = 1/2 (-1/2) if the border
  // runs along e from x to y (from y to x), 0 off the border. Its LDL^T
  // has the vertex graph's pattern, half the entries and about half the
  // work of the real system's (bunny00: 0.28 s of its 0.38 s of
  // factorizations went to the real LSCM systems); see Hermitian_ldlt.
  typedef std::complex<double> Complex;
  auto entry = [&](std::size_t x, std::size_t e) {
    const double along = edges.ends[e][0] == x ? border_direction[e] : -border_direction[e];
    return Complex(-edge_weight[e], 0.5 * along);
  };
  if(free_vertices == 0)
    return true;
  std::vector<std::size_t> vertex_of(static_cast<std::size_t>(free_vertices));
  for(std::size_t v = 0; v < n; ++v)
    if(unknown[v] != none)
      vertex_of[std::size_t(unknown[v])] = v;
  // Pinned neighbors move to the right-hand side.
  Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(free_vertices);
  for(std::size_t v = 0; v < n; ++v)
    if(unknown[v] != none)
      for(std::size_t k = edges.first[v]; k < edges.first[v + 1]; ++k)
      {
        const std::size_t p = edges.neighbor[k];
        if(unknown[p] == none)
          rhs[unknown[v]] -= entry(v, edges.edge[k]) * Complex(uv[p][0], uv[p][1]);
      }
  Eigen::SparseMatrix<Complex> h;
  assemble_upper_triangle(free_vertices, std::size_t(free_vertices) + edges.ends.size(),
                          [&](Eigen::Index column, const auto& add) {
    const std::size_t v = vertex_of[std::size_t(column)];
    add(column, Complex(vertex_weight[v], 0.));
    for(std::size_t k = edges.first[v]; k < edges.first[v + 1]; ++k)
    {
      const std::size_t w = edges.neighbor[k];
      if(unknown[w] != none && unknown[w] < unknown[v])
        add(unknown[w], entry(w, edges.edge[k]));
    }
  }, h);
  const Hermitian_ldlt solver(h);
  if(!solver.ok())
    return false;
  Eigen::VectorXcd z = rhs;
  solver.solve(z);
  for(std::size_t v = 0; v < n; ++v)
    if(unknown[v] != none)
      uv[v] = {{ z[unknown[v]].real(), z[unknown[v]].imag() }};
  return true;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_FREE_BORDER_LSCM_H
