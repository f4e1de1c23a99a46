// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_PARAMETERIZATION_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_PARAMETERIZATION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Chart_parameterizer.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_slots.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Free_border_lscm.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Local_global_arap.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Triangle_distortion.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_sparse_matrix.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// One chart cut out of the indexed mesh, with its own vertex numbering so that
// charts can be parameterized independently (and in parallel).
struct Chart
{
  std::vector<Index> faces;                     // faces of the indexed mesh
  std::vector<Index> vertices;                  // local vertex -> indexed-mesh vertex
  std::vector<std::array<Index, 3> > triangles; // local corners of each face
  std::vector<std::array<double, 2> > uv;       // local vertex -> UV
  // Its indexed-mesh vertices in the order the solvers eliminate them:
  // recorded when the chart is first solved, or inherited from the charts
  // it was built from (see Inherited_elimination_order.h); empty until then.
  std::vector<Index> elimination_order;
};

// Per-thread local numbering of the vertices of a chart being built or
// read, sized to the chart (a mesh-sized array per thread grew with mesh
// size times threads; std::unordered_map was 1 % of the time).
inline Region_slots& chart_vertex_slots()
{
  thread_local Region_slots slots;
  return slots;
}

// Local vertices are numbered as first met.
inline Chart make_chart(const Indexed_triangle_mesh& m, const std::vector<Index>& faces)
{
  Region_slots& slots = chart_vertex_slots();
  slots.clear_for_corners(m, faces);
  Chart c;
  c.faces = faces;
  c.triangles.reserve(faces.size());
  for(Index f : faces)
  {
    std::array<Index, 3> t;
    for(int i = 0; i < 3; ++i)
    {
      t[i] = slots.insert(m.corners[f][i]);
      if(t[i] == c.vertices.size())
        c.vertices.push_back(m.corners[f][i]);
    }
    c.triangles.push_back(t);
  }
  return c;
}

// The border of a chart that is a disk, as one cycle of local vertices in
// the orientation of its triangles; empty if the border edges do not form
// one cycle through distinct vertices.
inline std::vector<Index> chart_border_loop(const Chart& c)
{
  // Directed edges as the triangles give them, grouped by their source
  // (counting sort): an edge is on the border when its reverse is not
  // among the edges out of its target.
  const std::size_t nv = c.vertices.size();
  std::vector<std::size_t> first(nv + 1, 0);
  for(const auto& t : c.triangles)
    for(int i = 0; i < 3; ++i)
      ++first[t[i] + 1];
  for(std::size_t v = 0; v < nv; ++v)
    first[v + 1] += first[v];
  std::vector<Index> out(first[nv]);
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(const auto& t : c.triangles)
      for(int i = 0; i < 3; ++i)
        out[fill[t[i]]++] = t[(i + 1) % 3];
  }
  // The edges out of a vertex of high valence are sorted and searched in
  // halves (looking each up in turn was quadratic there); the few out of
  // any other vertex are scanned.
  const std::size_t few = 16;
  for(std::size_t v = 0; v < nv; ++v)
    if(first[v + 1] - first[v] > few)
      std::sort(out.begin() + first[v], out.begin() + first[v + 1]);
  auto has_edge = [&](Index a, Index b) {
    const auto begin = out.begin() + first[a], end = out.begin() + first[a + 1];
    return end - begin > std::ptrdiff_t(few) ? std::binary_search(begin, end, b) : std::find(begin, end, b) != end;
  };
  std::vector<Index> next(nv, no_index);
  std::size_t border_edges = 0;
  Index start = no_index;
  for(const auto& t : c.triangles)
    for(int i = 0; i < 3; ++i)
    {
      const std::pair<Index, Index> e(t[i], t[(i + 1) % 3]);
      if(has_edge(e.second, e.first))
        continue;
      if(next[e.first] != no_index)
        return std::vector<Index>();  // a vertex on the border twice
      next[e.first] = e.second;
      ++border_edges;
      start = e.first;
    }
  std::vector<Index> loop;
  if(start == no_index)
    return loop;
  // Ends: each step follows a distinct border edge, at most border_edges.
  Index v = start;
  do
  {
    loop.push_back(v);
    v = next[v];
  } while(v != no_index && v != start && loop.size() <= border_edges);
  if(v != start || loop.size() != border_edges)
    return std::vector<Index>();
  return loop;
}

typedef std::vector<std::array<double, 2> > Chart_uv;

constexpr const char* non_finite_uv = "non-finite UV";

// Whether a vertex of the closed polygon `border` lies within `tolerance` of
// a border segment it is not an end of. Packing moves every UV by a
// similarity rounded to doubles: such a border could touch itself once
// packed (two copies of a vertex split in 3D, laid out 1e-17 apart, met).
// Each segment is tested against the vertices in its x-range, sorted.
template <typename Point_2>
bool border_nearly_touches_itself(const std::vector<Point_2>& border, double tolerance)
{
  const std::size_t n = border.size();
  if(n < 4)
    return false;
  std::vector<std::pair<double, std::size_t> > by_x(n);
  for(std::size_t i = 0; i < n; ++i)
    by_x[i] = std::make_pair(border[i].x(), i);
  std::sort(by_x.begin(), by_x.end());
  for(std::size_t k = 0; k < n; ++k)
  {
    const Point_2& a = border[k];
    const Point_2& b = border[(k + 1) % n];
    const double dx = b.x() - a.x(), dy = b.y() - a.y(), length2 = dx * dx + dy * dy;
    const double lo = (std::min)(a.x(), b.x()) - tolerance, hi = (std::max)(a.x(), b.x()) + tolerance;
    for(auto it = std::lower_bound(by_x.begin(), by_x.end(), std::make_pair(lo, std::size_t(0)));
        it != by_x.end() && it->first <= hi; ++it)
    {
      const std::size_t i = it->second;
      if(i == k || i == (k + 1) % n)
        continue;
      const Point_2& p = border[i];
      // The closest point of the segment, clamped to its ends.
      const double t = length2 > 0 ? (std::max)(0., (std::min)(1., ((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / length2)) : 0.;
      const double ex = p.x() - (a.x() + t * dx), ey = p.y() - (a.y() + t * dy);
      if(ex * ex + ey * ey <= tolerance * tolerance)
        return true;
    }
  }
  return false;
}

// What is wrong with a chart's UVs, or an empty string. A chart is valid when
// its UVs are finite, every triangle keeps the 3D winding with a non-negligible
// area, and its border is a simple polygon; a locally injective map of a disk
// whose border is simple is globally injective.
inline std::string chart_uv_problem(const Chart& c, const std::vector<std::array<double, 2> >& uv,
                                    const std::vector<Index>& border_loop)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Point_2;
  for(const auto& u : uv)
    if(!std::isfinite(u[0]) || !std::isfinite(u[1]))
      return non_finite_uv;

  double total = 0;
  std::vector<double> areas(c.triangles.size());
  for(std::size_t t = 0; t < c.triangles.size(); ++t)
  {
    const auto& a = uv[c.triangles[t][0]];
    const auto& b = uv[c.triangles[t][1]];
    const auto& d = uv[c.triangles[t][2]];
    if(CGAL::orientation(Point_2(a[0], a[1]), Point_2(b[0], b[1]), Point_2(d[0], d[1])) != CGAL::LEFT_TURN)
      return "flipped or degenerate UV triangle";
    areas[t] = 0.5 * ((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]));
    total += areas[t];
  }
  // Triangles too thin to rasterize or to invert in a texture lookup; and
  // needles whose height is under 1e-10 of the chart's size, which packing
  // (a similarity rounded to doubles in [0, 1]) would flatten to a line.
  const double mean = total / static_cast<double>(c.triangles.size());
  double xmin = uv[0][0], xmax = uv[0][0], ymin = uv[0][1], ymax = uv[0][1];
  for(const auto& u : uv)
  {
    xmin = (std::min)(xmin, u[0]); xmax = (std::max)(xmax, u[0]);
    ymin = (std::min)(ymin, u[1]); ymax = (std::max)(ymax, u[1]);
  }
  // Squared: 2 area > 1e-10 size longest, without a square root per edge.
  const double chart_size2 = (xmax - xmin) * (xmax - xmin) + (ymax - ymin) * (ymax - ymin);
  for(std::size_t t = 0; t < c.triangles.size(); ++t)
  {
    if(!(areas[t] > 1e-12 * mean))
      return "degenerate UV triangle";
    double longest2 = 0;
    for(int i = 0; i < 3; ++i)
    {
      const auto& a = uv[c.triangles[t][i]];
      const auto& b = uv[c.triangles[t][(i + 1) % 3]];
      longest2 = (std::max)(longest2, (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]));
    }
    if(!(4 * areas[t] * areas[t] > 1e-20 * chart_size2 * longest2))
      return "degenerate UV triangle";
  }
  const double chart_size = std::sqrt(chart_size2);

  std::vector<Point_2> polygon;
  polygon.reserve(border_loop.size());
  for(Index v : border_loop)
    polygon.push_back(Point_2(uv[v][0], uv[v][1]));
  if(polygon.size() >= 4 && !CGAL::is_simple_2(polygon.begin(), polygon.end()))
    return "self-intersecting UV border";
  if(border_nearly_touches_itself(polygon, 1e-10 * chart_size))
    return "UV border nearly touches itself";
  return std::string();
}

// Free-border methods may return the mirror image of the surface; mirroring
// it back keeps the 3D winding that normal-map baking relies on.
inline void keep_winding(const Chart& c, Chart_uv& uv)
{
  double signed_area = 0;
  for(const auto& t : c.triangles)
  {
    const auto& a = uv[t[0]]; const auto& b = uv[t[1]]; const auto& d = uv[t[2]];
    signed_area += (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
  }
  if(signed_area < 0)
    for(auto& u : uv)
      u[0] = -u[0];
}

inline void keep_winding(Chart& c) { keep_winding(c, c.uv); }

// The border of the fixed-border methods: a circle, by arc length.
typedef CGAL::Surface_mesh_parameterization::Circular_border_arc_length_parameterizer_3<Chart_mesh> Circle_border;

// Solver traits for SMP's fixed-border methods: a direct sparse LU instead
// of the default BiCGSTAB with incomplete LU (measured 20% faster on a
// 75k-face chart, and it cannot fail to converge), factored once for the
// two systems (u and v) that share one matrix, where Eigen_solver_traits
// would factor it twice.
class Factor_once_sparse_lu
  : public CGAL::Eigen_solver_traits<
      Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::COLAMDOrdering<int> > >
{
  typedef CGAL::Eigen_solver_traits<
    Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::COLAMDOrdering<int> > > Base;

public:
  using Base::linear_solver;

  bool linear_solver(const Matrix& A, const Vector& B, Vector& X, NT& D)
  {
    D = 1;
    const auto& a = A.eigen_object();
    const double checksum = a.coeffs().sum();
    if(&a != factored_ || a.nonZeros() != factored_non_zeros_ || checksum != factored_checksum_)
    {
      solver().compute(a);
      if(solver().info() != Eigen::Success)
      {
        factored_ = nullptr;
        return false;
      }
      factored_ = &a;
      factored_non_zeros_ = a.nonZeros();
      factored_checksum_ = checksum;
    }
    X = solver().solve(B);
    return solver().info() == Eigen::Success;
  }

private:
  const void* factored_ = nullptr;
  Eigen::Index factored_non_zeros_ = 0;
  double factored_checksum_ = 0;
};

// Local/global ARAP iterations: the energy drops little after ten.
constexpr int arap_iterations = 10;

template <typename Parameterizer>
std::string run_parameterizer(Chart_mesh& mesh, Parameterizer parameterizer,
                              Chart_mesh::Halfedge_index border, Chart& c)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Point_2;
  auto uv = mesh.add_property_map<Chart_mesh::Vertex_index, Point_2>("v:uv", Point_2(0, 0)).first;
  SMP::Error_code status;
  try
  {
    status = SMP::parameterize(mesh, parameterizer, border, uv);
  }
  catch(const std::exception& e)
  {
    mesh.remove_property_map(uv);
    return std::string("parameterizer threw: ") + e.what();
  }
  // A user's parameterizer gets the mesh by reference: one that added or
  // removed vertices would have its UVs read out of place.
  if(mesh.number_of_vertices() != c.uv.size() || mesh.has_garbage())
  {
    mesh.remove_property_map(uv);
    return "the parameterizer changed the chart's mesh";
  }
  for(Chart_mesh::Vertex_index v : mesh.vertices())
    c.uv[std::size_t(v)] = {{ uv[v].x(), uv[v].y() }};
  mesh.remove_property_map(uv);
  if(status != SMP::OK)
    return SMP::get_error_message(status);
  return std::string();
}

// The solvers' view of `c`, eliminating its vertices in
// `c.elimination_order` when it has one, else in a fill-reducing order
// computed now and recorded there, for the charts built from `c`.
inline Chart_geometry chart_geometry(const Indexed_triangle_mesh& m, Chart& c)
{
  std::vector<std::array<double, 3> > points;
  points.reserve(c.vertices.size());
  for(Index v : c.vertices)
    points.push_back(m.points[v]);
  std::vector<std::array<std::size_t, 3> > triangles;
  triangles.reserve(c.triangles.size());
  for(const auto& t : c.triangles)
    triangles.push_back({{ t[0], t[1], t[2] }});
  const std::size_t n = c.vertices.size();
  std::vector<Eigen::Index> rank;
  if(c.elimination_order.size() == n)
  {
    // The chart's vertices are distinct: each gets its own local index.
    Region_slots& slots = chart_vertex_slots();
    slots.clear_for_keys(c.vertices);
    for(Index v : c.vertices)
      slots.insert(v);
    rank.resize(n);
    for(std::size_t k = 0; k < n; ++k)
    {
      const Index local = slots.find(c.elimination_order[k]);
      CGAL_assertion(local != no_index);
      rank[local] = Eigen::Index(k);
    }
  }
  Chart_geometry g(std::move(points), std::move(triangles), std::move(rank));
  if(c.elimination_order.size() != n)
  {
    c.elimination_order.resize(n);
    for(std::size_t v = 0; v < n; ++v)
      c.elimination_order[std::size_t(g.elimination_rank[v])] = c.vertices[v];
  }
  return g;
}

// What a look at an early ARAP iterate of a chart says of the iterations
// left.
enum class Early_verdict
{
  iterate_on,   // they are needed
  good_enough,  // the iterate already meets what the chart must meet: stop there if it is valid
  hopeless      // it is so far from it that they would not bring it there: stop
};

// A verdict, with the measure it was drawn from (Split_rule: the chart's
// excess), so that the chart need not be measured again.
struct Early_judgement
{
  Early_verdict verdict = Early_verdict::iterate_on;
  double measure = 0.;
};

// Judges chart `c` under the ARAP iterate `uv` after
// arap_early_look_iterations iterations (see Split_rule::early_verdict()).
// Most charts that meet the bound after all iterations already meet it
// there, and most that miss it by far already miss it by far.
typedef std::function<Early_judgement(const Chart&, const Chart_uv&)> Arap_early_look;
constexpr int arap_early_look_iterations = 2;

// The early look of one chart's parameterization: the judge (none: all
// iterations), and its judgement of the map the chart ends with when the
// look ended the iterations on it (else `iterate_on`).
struct Early_look
{
  const Arap_early_look* judge = nullptr;
  Early_judgement ended;
};

// ARAP iterations on `c` from `start`. A valid start keeps only valid
// iterates; an invalid one (LSCM folds some jagged charts, two glued maps
// may fold along their seam) is iterated freely, which often unfolds it,
// and kept only if the result is valid. With `look`, the iterations may
// end early (see Early_verdict). Returns whether `c.uv` is now a valid
// ARAP map; it is unchanged otherwise.
inline bool arap_from(Chart& c, const std::vector<Index>& border_loop, const Chart_geometry& g, Chart_uv start,
                      Early_look* look = nullptr)
{
  auto is_valid = [&](const Chart_uv& candidate) { return chart_uv_problem(c, candidate, border_loop).empty(); };
  auto any_map = [](const Chart_uv&) { return true; };
  Early_judgement judgement;
  if(look != nullptr)
    look->ended = Early_judgement();
  auto look_once = [&](int done, const Chart_uv& uv) {
    if(look == nullptr || look->judge == nullptr || !*look->judge || done != arap_early_look_iterations)
      return false;
    judgement = (*look->judge)(c, uv);
    if(judgement.verdict == Early_verdict::good_enough && !is_valid(uv))
      judgement.verdict = Early_verdict::iterate_on;
    return judgement.verdict != Early_verdict::iterate_on;
  };
  const Early_verdict& verdict = judgement.verdict;
  // Called when the chart ends with the last iterate, unchanged: the
  // judged one if the look ended the iterations.
  auto ended_on_judged = [&] {
    if(look != nullptr && judgement.verdict != Early_verdict::iterate_on)
      look->ended = judgement;
  };
  if(is_valid(start))
  {
    // From a valid start the iterates nearly always stay valid, so only the
    // last one is checked; if it is not valid, the iterations are done
    // again with every iterate checked (the last valid one is kept). The
    // result is a valid map either way. Measured on the 10 peers' meshes:
    // no chart needed the second run, the same charts, parameterization
    // -7.5 % (a check costs about what an iteration does).
    Chart_uv unchecked = start;
    if(local_global_arap(g, unchecked, arap_iterations, any_map, look_once) < 0)
      return false;
    if(verdict == Early_verdict::good_enough || is_valid(unchecked))
    {
      c.uv.swap(unchecked);
      ended_on_judged();
      return true;
    }
    if(local_global_arap(g, start, arap_iterations, is_valid) < 0)
      return false;
  }
  else
  {
    if(local_global_arap(g, start, arap_iterations, any_map, look_once) < 0)
      return false;
    if(verdict != Early_verdict::good_enough)
    {
      keep_winding(c, start);
      if(!is_valid(start))
        return false;
    }
    else
      ended_on_judged();
  }
  c.uv.swap(start);
  return true;
}

// ARAP from the free-border LSCM map: its border is free, so ARAP starts
// near its optimum and moves the border where a circle would have pinned
// it. `border_loop` gets the chart's border (empty if the chart is not a
// disk). Returns whether `c.uv` is a valid ARAP map.
inline bool arap_from_lscm(const Indexed_triangle_mesh& m, Chart& c, std::vector<Index>& border_loop,
                           Early_look* look = nullptr)
{
  border_loop = chart_border_loop(c);
  if(border_loop.empty() || m.at_one_point(c.faces))
    return false;
  const Chart_geometry g = chart_geometry(m, c);
  Chart_uv start;
  if(!free_border_lscm(g, std::vector<std::size_t>(border_loop.begin(), border_loop.end()), start))
    return false;
  keep_winding(c, start);
  return arap_from(c, border_loop, g, std::move(start), look);
}

// What parameterize_chart() does when the requested method gives a chart of
// more than one triangle an invalid map.
enum class On_invalid_map
{
  redo,    // other starts of the method, then the fallback methods
  report   // nothing: the caller replaces the chart by smaller ones
};

// Charts with one triangle are laid out isometrically: fixed-border
// solvers have no unknown to solve for and free-border ones are overkill.
inline void lay_out_single_triangle(const Indexed_triangle_mesh& m, Chart& c)
{
  const auto& p0 = m.points[c.vertices[0]];
  const auto& p1 = m.points[c.vertices[1]];
  const auto& p2 = m.points[c.vertices[2]];
  const double l1 = Indexed_triangle_mesh::distance(p0, p1);
  const double e[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
  const double f[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
  const double x = l1 > 0 ? (e[0] * f[0] + e[1] * f[1] + e[2] * f[2]) / l1 : 0.;
  const double cx = e[1] * f[2] - e[2] * f[1], cy = e[2] * f[0] - e[0] * f[2], cz = e[0] * f[1] - e[1] * f[0];
  const double y = l1 > 0 ? std::sqrt(cx * cx + cy * cy + cz * cz) / l1 : 0.;
  c.uv[0] = {{ 0., 0. }};
  c.uv[1] = {{ l1, 0. }};
  c.uv[2] = {{ x, y }};
  // A degenerate face (collinear or coincident corners), or a needle whose
  // smallest height is under 1e-6 of its longest side, has no isometric
  // layout that survives packing (its corners would round to a line); an
  // equilateral triangle keeps the chart valid.
  const double longest = (std::max)(l1, (std::max)(Indexed_triangle_mesh::distance(p1, p2),
                                                   Indexed_triangle_mesh::distance(p2, p0)));
  const double smallest_height = longest > 0 ? l1 * y / longest : 0.;
  if(!(smallest_height > 1e-6 * longest))
  {
    const double side = longest > 0 ? longest : 1.;
    c.uv[1] = {{ side, 0. }};
    c.uv[2] = {{ side / 2, side * std::sqrt(3.) / 2 }};
  }
}

// ARAP once arap_from_lscm() failed: from SMP's LSCM, then from an
// injective map on a circle, keeping only valid iterates.
inline std::string arap_from_other_starts(const Indexed_triangle_mesh& m, Chart& c, Chart_mesh& mesh,
                                          Chart_mesh::Halfedge_index border, const std::vector<Index>& border_loop,
                                          bool& validated, Early_look* look)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  // Local/global iterations with one factorization (see
  // Local_global_arap.h for why not SMP::ARAP_parameterizer_3).
  // arap_from_lscm() failed: a chart with several borders (a patch
  // that is not a disk, with require_disk_patches(false)), which SMP's
  // LSCM takes, or a fold that free iterations did not undo, which
  // SMP's other choice of pinned vertices may avoid.
  if(run_parameterizer(mesh, SMP::LSCM_parameterizer_3<Chart_mesh>(), border, c).empty())
  {
    keep_winding(c);
    if(arap_from(c, border_loop, chart_geometry(m, c), c.uv, look))
    {
      validated = true;
      return std::string();
    }
  }
  // Then from an injective map on a circle, keeping only valid
  // iterates. Mean value coordinates start closer to ARAP; Tutte's map,
  // which ignores the geometry, is the start when near-degenerate 3D
  // triangles make the mean value map invalid.
  auto valid_start = [&](auto parameterizer) {
    std::string problem = run_parameterizer(mesh, parameterizer, border, c);
    if(problem.empty())
    {
      keep_winding(c);
      problem = chart_uv_problem(c, c.uv, border_loop);
    }
    return problem;
  };
  if(!valid_start(SMP::Mean_value_coordinates_parameterizer_3<Chart_mesh, Circle_border, Factor_once_sparse_lu>()).empty())
  {
    const std::string problem =
      valid_start(SMP::Barycentric_mapping_parameterizer_3<Chart_mesh, Circle_border, Factor_once_sparse_lu>());
    if(!problem.empty())
      return "ARAP: no valid initialization (" + problem + ")";
  }
  if(!arap_from(c, border_loop, chart_geometry(m, c), c.uv, look))
    return "ARAP: cannot factor the cotangent Laplacian (degenerate triangles)";
  validated = true;
  return std::string();
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_PARAMETERIZATION_H
