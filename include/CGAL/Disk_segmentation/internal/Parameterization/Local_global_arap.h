// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Local/global ARAP iterations on a chart with one factorization of the
// cotangent Laplacian, and the chart's edge graph the solvers share.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_LOCAL_GLOBAL_ARAP_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_LOCAL_GLOBAL_ARAP_H

#include <CGAL/disable_warnings.h>

#include <CGAL/assertions.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// The edges of a chart's triangles, each once, and the edges around each
// vertex. The LSCM and ARAP matrices and the elimination order are all
// built on this graph, column by column: assembling them from triplets
// (sorted, summed and transposed by Eigen), with the triangles' frames,
// took 0.26 s of bunny00's 1.4 s.
struct Chart_edges
{
  std::vector<std::array<std::size_t, 2> > ends;         // by increasing (first, second), first < second
  std::vector<std::array<std::size_t, 3> > of_triangle;  // the edge from corner i to corner i+1
  std::vector<std::size_t> first;                        // per vertex, into `neighbor` and `edge`; and the end
  std::vector<std::size_t> neighbor, edge;               // around each vertex, by increasing neighbor

  static constexpr std::size_t none = std::size_t(-1);

  // The edge between a and b, or none.
  std::size_t between(std::size_t a, std::size_t b) const
  {
    for(std::size_t k = first[a]; k < first[a + 1]; ++k)
      if(neighbor[k] == b)
        return edge[k];
    return none;
  }
};

inline void build_chart_edges(std::size_t n, const std::vector<std::array<std::size_t, 3> >& triangles,
                              Chart_edges& edges)
{
  const std::size_t nt = triangles.size();
  // Triangle edges bucketed by their smaller end (counting sort), then
  // numbered by (smaller end, larger end).
  std::vector<std::size_t> start(n + 1, 0);
  for(const auto& t : triangles)
    for(int i = 0; i < 3; ++i)
      ++start[(std::min)(t[i], t[(i + 1) % 3]) + 1];
  for(std::size_t v = 0; v < n; ++v)
    start[v + 1] += start[v];
  std::vector<std::pair<std::size_t, std::size_t> > bucket(3 * nt);  // larger end, 3 t + i
  {
    std::vector<std::size_t> cursor(start.begin(), start.end() - 1);
    for(std::size_t t = 0; t < nt; ++t)
      for(int i = 0; i < 3; ++i)
      {
        const std::size_t a = triangles[t][i], b = triangles[t][(i + 1) % 3];
        bucket[cursor[(std::min)(a, b)]++] = std::make_pair((std::max)(a, b), 3 * t + std::size_t(i));
      }
  }
  edges.ends.clear();
  edges.of_triangle.resize(nt);
  for(std::size_t v = 0; v < n; ++v)
  {
    std::sort(bucket.begin() + std::ptrdiff_t(start[v]), bucket.begin() + std::ptrdiff_t(start[v + 1]));
    for(std::size_t k = start[v]; k < start[v + 1]; ++k)
    {
      if(k == start[v] || bucket[k].first != bucket[k - 1].first)
        edges.ends.push_back({{ v, bucket[k].first }});
      edges.of_triangle[bucket[k].second / 3][bucket[k].second % 3] = edges.ends.size() - 1;
    }
  }
  // Edges come by increasing smaller end, so every vertex meets its
  // smaller neighbors (as larger end) before its larger ones, each group
  // in increasing order.
  edges.first.assign(n + 1, 0);
  for(const auto& e : edges.ends)
  {
    ++edges.first[e[0] + 1];
    ++edges.first[e[1] + 1];
  }
  for(std::size_t v = 0; v < n; ++v)
    edges.first[v + 1] += edges.first[v];
  edges.neighbor.resize(2 * edges.ends.size());
  edges.edge.resize(2 * edges.ends.size());
  std::vector<std::size_t> cursor(edges.first.begin(), edges.first.end() - 1);
  for(std::size_t e = 0; e < edges.ends.size(); ++e)
    for(int side = 0; side < 2; ++side)
    {
      const std::size_t k = cursor[edges.ends[e][side]]++;
      edges.neighbor[k] = edges.ends[e][1 - side];
      edges.edge[k] = e;
    }
}

// Builds the upper triangle of a symmetric `size` x `size` matrix in place,
// column by column: `column(k, add)` calls `add(row, value)` once for each
// entry of column k at a row <= k, in any order.
template <typename Scalar, typename Column>
void assemble_upper_triangle(Eigen::Index size, std::size_t non_zeros, const Column& column,
                             Eigen::SparseMatrix<Scalar>& a)
{
  a.resize(size, size);
  a.resizeNonZeros(Eigen::Index(non_zeros));
  int* outer = a.outerIndexPtr();
  int* inner = a.innerIndexPtr();
  Scalar* value = a.valuePtr();
  std::vector<std::pair<int, Scalar> > long_column;
  int next = 0;
  for(Eigen::Index k = 0; k < size; ++k)
  {
    outer[k] = next;
    const int begin = next;
    column(k, [&](Eigen::Index row, Scalar v) {
      CGAL_assertion(row <= k && next < int(non_zeros));
      // Insertion in row order: a column holds a few entries. Past 32 (a
      // vertex of high valence, where insertion was quadratic) entries are
      // appended, and the column sorted once below.
      int j = next++;
      if(j - begin < 32)
        for(; j > begin && inner[j - 1] > row; --j)
        {
          inner[j] = inner[j - 1];
          value[j] = value[j - 1];
        }
      inner[j] = int(row);
      value[j] = v;
    });
    if(next - begin > 32)
    {
      long_column.clear();
      for(int i = begin; i < next; ++i)
        long_column.emplace_back(inner[i], value[i]);
      std::stable_sort(long_column.begin(), long_column.end(),
                       [](const auto& x, const auto& y) { return x.first < y.first; });
      for(int i = begin; i < next; ++i)
      {
        inner[i] = long_column[std::size_t(i - begin)].first;
        value[i] = long_column[std::size_t(i - begin)].second;
      }
    }
  }
  outer[size] = next;
  a.resizeNonZeros(next);
}

// Rank of each vertex in a fill-reducing elimination order (approximate
// minimum degree on the vertex graph). The LSCM and ARAP systems of a
// chart are both built on this graph (LSCM's with two unknowns per vertex,
// side by side), so one ordering of the vertex graph serves both: ordering
// the LSCM system itself, twice as large, cost more than its factorization
// on small charts.
constexpr std::size_t smallest_ordered_chart = 48;  // vertices

inline std::vector<Eigen::Index> vertex_elimination_rank(std::size_t n, const Chart_edges& edges)
{
  // Small charts keep their own order (faces in region order, vertices as
  // first met): their factors are tiny either way, and the ordering cost
  // more than it saved. 10 meshes of the peers' table, one thread: the same
  // charts, 2 % less time in all (ChineseDragon-10kv, 1,100 small solves:
  // 3.5 %); 48 or 128 vertices: the same.
  if(n < smallest_ordered_chart)
  {
    std::vector<Eigen::Index> rank(n);
    for(std::size_t k = 0; k < n; ++k)
      rank[k] = Eigen::Index(k);
    return rank;
  }
  // One triangle of the pattern is enough: the ordering symmetrizes it.
  // (The diagonal is needed: Eigen's AMD does not always end without it.)
  Eigen::SparseMatrix<double> graph;
  assemble_upper_triangle(Eigen::Index(n), n + edges.ends.size(), [&](Eigen::Index k, const auto& add) {
    const std::size_t v = std::size_t(k);
    for(std::size_t j = edges.first[v]; j < edges.first[v + 1] && edges.neighbor[j] < v; ++j)
      add(Eigen::Index(edges.neighbor[j]), 1.);
    add(k, 1.);
  }, graph);
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
  Eigen::AMDOrdering<int>()(graph, order);
  // Eigen's orderings give the inverse permutation (as SimplicialLDLT
  // uses them): indices()[k] is the k-th vertex to eliminate.
  std::vector<Eigen::Index> rank(n);
  for(std::size_t k = 0; k < n; ++k)
    rank[std::size_t(order.indices()[Eigen::Index(k)])] = Eigen::Index(k);
  return rank;
}

// Sparse LDL^T on a matrix already in elimination order; only its upper
// triangle is read, so only that is assembled (the upper one: the solver
// would copy a lower one into it).
template <typename Scalar>
using Ordered_sparse_ldlt =
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<Scalar>, Eigen::Upper, Eigen::NaturalOrdering<int> >;

// Solves L D L^T x = b for two right-hand sides at once, in place (b as
// pairs): Eigen's triangular solves go over the factor once per column,
// twice as often; the solves were 7 % of bunny00's time (perf, one thread).
inline void solve_pairs(const Ordered_sparse_ldlt<double>& solver, std::vector<std::array<double, 2> >& x)
{
  const Eigen::SparseMatrix<double>& l = solver.matrixL().nestedExpression();
  CGAL_precondition(solver.permutationP().size() == 0 && l.isCompressed() && std::size_t(l.cols()) == x.size());
  const int* outer = l.outerIndexPtr();
  const int* inner = l.innerIndexPtr();
  const double* value = l.valuePtr();
  const Eigen::VectorXd& d = solver.vectorD();
  const int n = int(x.size());
  // L is unit lower triangular, its diagonal not stored.
  for(int j = 0; j < n; ++j)
  {
    const double a = x[j][0], b = x[j][1];
    for(int p = outer[j]; p < outer[j + 1]; ++p)
    {
      x[inner[p]][0] -= value[p] * a;
      x[inner[p]][1] -= value[p] * b;
    }
  }
  for(int j = 0; j < n; ++j)
  {
    // As Eigen does it (by the inverse), so that the charts stay the same.
    const double inverse = 1. / d[j];
    x[j][0] *= inverse;
    x[j][1] *= inverse;
  }
  for(int j = n - 1; j >= 0; --j)
  {
    double a = x[j][0], b = x[j][1];
    for(int p = outer[j]; p < outer[j + 1]; ++p)
    {
      a -= value[p] * x[inner[p]][0];
      b -= value[p] * x[inner[p]][1];
    }
    x[j] = {{ a, b }};
  }
}

// The cotangent weight of each edge (half the sum of the cotangents of the
// angles opposite to it) and their sum around each vertex: the cotangent
// Laplacian's off-diagonal (negated) and diagonal entries.
inline void cotangent_weights(const Chart_edges& edges, const std::vector<std::array<double, 3> >& cot,
                              std::vector<double>& edge_weight, std::vector<double>& vertex_weight)
{
  edge_weight.assign(edges.ends.size(), 0.);
  vertex_weight.assign(edges.first.size() - 1, 0.);
  for(std::size_t t = 0; t < cot.size(); ++t)
    for(int i = 0; i < 3; ++i)
      edge_weight[edges.of_triangle[t][i]] += 0.5 * cot[t][i];
  for(std::size_t e = 0; e < edges.ends.size(); ++e)
  {
    vertex_weight[edges.ends[e][0]] += edge_weight[e];
    vertex_weight[edges.ends[e][1]] += edge_weight[e];
  }
}

// Each triangle isometrically in its own plane (corner 0 at the origin,
// corner 1 on the x axis) and the cotangent of the angle opposite to each
// edge (edge i from corner i to corner i+1), clamped so that needle
// triangles do not dominate a system built on them. The cotangent
// Laplacian of both ARAP and LSCM (Free_border_lscm.h) comes from here.
// If any was clamped, `exact_cot` gets them all unclamped (else it is
// emptied). False if a triangle has a zero edge or no area.
inline bool isometric_frames(const std::vector<std::array<double, 3> >& points,
                             const std::vector<std::array<std::size_t, 3> >& triangles,
                             std::vector<std::array<std::array<double, 2>, 3> >& local,
                             std::vector<std::array<double, 3> >& cot,
                             std::vector<std::array<double, 3> >& exact_cot)
{
  const std::size_t nt = triangles.size();
  local.resize(nt);
  cot.resize(nt);
  exact_cot.clear();
  for(std::size_t t = 0; t < nt; ++t)
  {
    const auto& p0 = points[triangles[t][0]];
    const auto& p1 = points[triangles[t][1]];
    const auto& p2 = points[triangles[t][2]];
    const double e[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
    const double f[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
    const double l = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    const double cx = e[1] * f[2] - e[2] * f[1], cy = e[2] * f[0] - e[0] * f[2], cz = e[0] * f[1] - e[1] * f[0];
    const double twice_area = std::sqrt(cx * cx + cy * cy + cz * cz);
    if(!(l > 0) || !(twice_area > 0))
      return false;
    local[t] = {{ {{ 0., 0. }}, {{ l, 0. }}, {{ (e[0] * f[0] + e[1] * f[1] + e[2] * f[2]) / l, twice_area / l }} }};
    for(int i = 0; i < 3; ++i)
    {
      // Angle at corner i+2, between the edges to corners i and i+1.
      const auto& a = local[t][i];
      const auto& b = local[t][(i + 1) % 3];
      const auto& c = local[t][(i + 2) % 3];
      const double ux = a[0] - c[0], uy = a[1] - c[1], vx = b[0] - c[0], vy = b[1] - c[1];
      const double exact = (ux * vx + uy * vy) / (ux * vy - uy * vx);
      cot[t][i] = (std::max)(-1e4, (std::min)(1e4, exact));
      if(cot[t][i] != exact && exact_cot.empty())
        exact_cot.assign(cot.begin(), cot.begin() + std::ptrdiff_t(t + 1));
      if(!exact_cot.empty())
      {
        exact_cot.resize(t + 1);
        exact_cot[t][i] = exact;
      }
    }
  }
  return true;
}

// A chart's 3D positions, its triangles (counterclockwise), their edges
// and the elimination rank of its vertices (given, or computed by
// vertex_elimination_rank()), as the LSCM and ARAP solvers take them, with
// what both read of the geometry, computed once per chart:
// each triangle in its own plane with its cotangents (see
// isometric_frames(); `has_frames` is false if a triangle has a zero edge
// or no area), the edges' cotangent weights and their sums around the
// vertices (see cotangent_weights()).
struct Chart_geometry
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::array<std::size_t, 3> > triangles;
  Chart_edges edges;
  std::vector<Eigen::Index> elimination_rank;
  std::vector<std::array<std::array<double, 2>, 3> > frames;
  std::vector<std::array<double, 3> > cot;
  std::vector<double> edge_weight, vertex_weight;
  // LSCM's weights where a cotangent was clamped (else empty: the same as
  // above). Its energy E_D - A is positive semidefinite with the true
  // cotangents only: clamped needles made the system indefinite, and
  // LSCM folded the slivers at the rim of a closed cone of valence 200k.
  std::vector<double> conformal_edge_weight, conformal_vertex_weight;
  bool has_frames = false;

  Chart_geometry() = default;
  Chart_geometry(std::vector<std::array<double, 3> > p, std::vector<std::array<std::size_t, 3> > t,
                 std::vector<Eigen::Index> rank = std::vector<Eigen::Index>())
    : points(std::move(p)), triangles(std::move(t)), elimination_rank(std::move(rank))
  {
    build_chart_edges(points.size(), triangles, edges);
    if(elimination_rank.size() != points.size())
      elimination_rank = vertex_elimination_rank(points.size(), edges);
    std::vector<std::array<double, 3> > exact_cot;
    has_frames = isometric_frames(points, triangles, frames, cot, exact_cot);
    if(has_frames)
      cotangent_weights(edges, cot, edge_weight, vertex_weight);
    if(has_frames && !exact_cot.empty())
      cotangent_weights(edges, exact_cot, conformal_edge_weight, conformal_vertex_weight);
  }

  const std::vector<double>& lscm_edge_weight() const
  {
    return conformal_edge_weight.empty() ? edge_weight : conformal_edge_weight;
  }
  const std::vector<double>& lscm_vertex_weight() const
  {
    return conformal_edge_weight.empty() ? vertex_weight : conformal_vertex_weight;
  }
};

// As-rigid-as-possible parameterization (Liu et al. 2008) by local/global
// iterations, free border.
//
// CGAL's ARAP_parameterizer_3 rebuilds and refactors its linear system at
// every iteration and keeps per-element data in hash maps; measured on a
// 27.7k-face chart it took seconds. The global step's matrix is the
// cotangent Laplacian, constant across iterations, so here it is factored
// once (sparse LDL^T) and each iteration costs one local SVD per triangle and
// two back-substitutions.
//
// `g` is the chart's geometry, `uv` the initial map, improved in place.
// `is_acceptable(uv)` vets every iterate; a rejected one is replaced by a
// shorter step from the last valid iterate, and the iterations stop when no
// step is accepted. From a valid start (e.g. mean value coordinates) the
// result is therefore always valid. `stop_after(k, uv)`, called on the k-th
// accepted iterate, ends the iterations when it returns true. Returns the
// number of iterations done, or -1 if the factorization fails (degenerate
// triangles).
template <typename Acceptance, typename Stop>
int local_global_arap(const Chart_geometry& g, std::vector<std::array<double, 2> >& uv, int iterations,
                      const Acceptance& is_acceptable, const Stop& stop_after)
{
  const std::vector<std::array<double, 3> >& points = g.points;
  const std::vector<std::array<std::size_t, 3> >& triangles = g.triangles;
  const std::size_t n = points.size(), nt = triangles.size();
  if(n < 3 || nt == 0)
    return 0;

  if(!g.has_frames)
    return -1;
  const std::vector<std::array<std::array<double, 2>, 3> >& local = g.frames;
  const std::vector<std::array<double, 3> >& cot = g.cot;

  // Vertex 0 stays where the initial map put it: that removes the
  // translation from the Laplacian's null space and makes it definite.
  // The other vertices are numbered in elimination order.
  const std::vector<Eigen::Index>& rank = g.elimination_rank;
  auto unknown = [&rank](std::size_t v) { return rank[v] - (rank[v] > rank[0] ? 1 : 0); };
  const Chart_edges& edges = g.edges;
  std::vector<std::size_t> vertex_of(n - 1);
  for(std::size_t v = 1; v < n; ++v)
    vertex_of[std::size_t(unknown(v))] = v;
  const std::vector<double>& edge_weight = g.edge_weight;
  const std::vector<double>& vertex_weight = g.vertex_weight;
  Eigen::SparseMatrix<double> laplacian;
  assemble_upper_triangle(Eigen::Index(n - 1), n - 1 + edges.ends.size(), [&](Eigen::Index k, const auto& add) {
    const std::size_t v = vertex_of[std::size_t(k)];
    add(k, vertex_weight[v]);
    for(std::size_t j = edges.first[v]; j < edges.first[v + 1]; ++j)
    {
      const std::size_t w = edges.neighbor[j];
      if(w != 0 && unknown(w) < k)
        add(unknown(w), -edge_weight[edges.edge[j]]);
    }
  }, laplacian);
  Ordered_sparse_ldlt<double> solver(laplacian);
  if(solver.info() != Eigen::Success)
    return -1;

  std::vector<std::array<double, 4> > rotation(nt);
  std::vector<std::array<double, 2> > previous;
  // u and v solved together: one pass over the factor for both.
  std::vector<std::array<double, 2> > x(n - 1);
  for(int iteration = 0; iteration < iterations; ++iteration)
  {
    // Local step: the rotation closest to each triangle's current map.
    for(std::size_t t = 0; t < nt; ++t)
    {
      double s00 = 0, s01 = 0, s10 = 0, s11 = 0;  // sum of w (du)(dx)^T
      for(int i = 0; i < 3; ++i)
      {
        const std::size_t a = triangles[t][i], b = triangles[t][(i + 1) % 3];
        const double w = cot[t][i];
        const double dux = uv[a][0] - uv[b][0], duy = uv[a][1] - uv[b][1];
        const double dxx = local[t][i][0] - local[t][(i + 1) % 3][0], dxy = local[t][i][1] - local[t][(i + 1) % 3][1];
        s00 += w * dux * dxx; s01 += w * dux * dxy;
        s10 += w * duy * dxx; s11 += w * duy * dxy;
      }
      // argmax over rotations R of trace(R^T S): the angle of
      // (s00 + s11, s10 - s01), normalized rather than through atan2/sincos.
      const double c = s00 + s11, s = s10 - s01, r = std::sqrt(c * c + s * s);
      rotation[t] = r > 0 ? std::array<double, 4>{{ c / r, -s / r, s / r, c / r }}
                          : std::array<double, 4>{{ 1., 0., 0., 1. }};
    }

    // Global step: L u = sum of w R (x_a - x_b) over edges, vertex 0 fixed.
    std::fill(x.begin(), x.end(), std::array<double, 2>{{ 0., 0. }});
    for(std::size_t t = 0; t < nt; ++t)
    {
      const auto& r = rotation[t];
      for(int i = 0; i < 3; ++i)
      {
        const std::size_t a = triangles[t][i], b = triangles[t][(i + 1) % 3];
        const double w = 0.5 * cot[t][i];
        const double dxx = local[t][i][0] - local[t][(i + 1) % 3][0], dxy = local[t][i][1] - local[t][(i + 1) % 3][1];
        const double ru = r[0] * dxx + r[1] * dxy, rv = r[2] * dxx + r[3] * dxy;
        if(a != 0) { x[unknown(a)][0] += w * ru; x[unknown(a)][1] += w * rv; }
        if(b != 0) { x[unknown(b)][0] -= w * ru; x[unknown(b)][1] -= w * rv; }
        // Move the fixed vertex's known term to the right-hand side.
        if(a == 0 && b != 0) { x[unknown(b)][0] += w * uv[0][0]; x[unknown(b)][1] += w * uv[0][1]; }
        if(b == 0 && a != 0) { x[unknown(a)][0] += w * uv[0][0]; x[unknown(a)][1] += w * uv[0][1]; }
      }
    }
    solve_pairs(solver, x);
    previous = uv;
    for(std::size_t i = 1; i < n; ++i)
      uv[i] = x[unknown(i)];
    // A rejected iterate is pulled back toward the last valid one: a
    // shorter step along the same direction often stays valid and still
    // lowers the energy. At most 8 shorter steps (1/2 down to 1/256) per
    // iteration, whatever is_acceptable says (NaN UVs included), then the
    // last valid iterate stays.
    double step = 1.;
    while(!is_acceptable(uv))
    {
      step /= 2;
      if(step < 1. / 256)
      {
        uv.swap(previous);
        return iteration;
      }
      for(std::size_t i = 1; i < n; ++i)
        uv[i] = {{ previous[i][0] + step * (x[unknown(i)][0] - previous[i][0]),
                   previous[i][1] + step * (x[unknown(i)][1] - previous[i][1]) }};
    }
    if(stop_after(iteration + 1, static_cast<const std::vector<std::array<double, 2> >&>(uv)))
      return iteration + 1;
  }
  return iterations;
}

template <typename Acceptance>
int local_global_arap(const Chart_geometry& g, std::vector<std::array<double, 2> >& uv, int iterations,
                      const Acceptance& is_acceptable)
{
  return local_global_arap(g, uv, iterations, is_acceptable,
                           [](int, const std::vector<std::array<double, 2> >&) { return false; });
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_LOCAL_GLOBAL_ARAP_H
