// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// ARAP maps of a chart from its starts: the free-border LSCM map first, then
// SMP's LSCM and injective maps on a circle; one triangle laid out as is.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_PARAMETERIZATION_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_PARAMETERIZATION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Chart_parameterizer.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_slots.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Arap_early_look.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_uv_validity.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Free_border_lscm.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Local_global_arap.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/SMP_parameterizers.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Triangle_distortion.h>

#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>

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

// Local/global ARAP iterations: the energy drops little after ten.
constexpr int arap_iterations = 10;

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
