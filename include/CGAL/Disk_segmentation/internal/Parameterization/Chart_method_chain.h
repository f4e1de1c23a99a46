// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Runs a chart's method, then its fallbacks, until the map is valid, and
// counts what the solves cost.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_METHOD_CHAIN_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_METHOD_CHAIN_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Chart_parameterizer.h>
#include <CGAL/Disk_segmentation/Parameterization_method.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_methods.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_parameterization.h>

#include <atomic>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Runs `method` on the chart; returns an empty string on success, else
// what went wrong. The UVs are left in `c.uv` in either case; `validated`
// says whether they were found valid (ARAP checks its result).
inline std::string parameterize_chart_with(const Indexed_triangle_mesh& m, Chart& c, const Chart_method& method,
                                           std::vector<Index>& border_loop, bool& validated,
                                           On_invalid_map on_invalid = On_invalid_map::redo,
                                           Early_look* look = nullptr)
{
  validated = false;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point_3;

  c.uv.assign(c.vertices.size(), {{ 0., 0. }});
  if(const std::optional<std::string> done = method.parameterize_indexed(m, c, border_loop, validated, on_invalid, look))
    return *done;

  Chart_mesh mesh;
  mesh.reserve(static_cast<Chart_mesh::size_type>(c.vertices.size()),
               static_cast<Chart_mesh::size_type>(3 * c.triangles.size()),
               static_cast<Chart_mesh::size_type>(c.triangles.size()));
  for(Index v : c.vertices)
    mesh.add_vertex(Point_3(m.points[v][0], m.points[v][1], m.points[v][2]));
  for(const auto& t : c.triangles)
    if(mesh.add_face(Chart_mesh::Vertex_index(t[0]), Chart_mesh::Vertex_index(t[1]), Chart_mesh::Vertex_index(t[2])) ==
       Chart_mesh::null_face())
      return "chart is not a manifold disk";

  Chart_mesh::Halfedge_index border;
  for(Chart_mesh::Halfedge_index h : mesh.halfedges())
    if(mesh.is_border(h)) { border = h; break; }
  if(border == Chart_mesh::null_halfedge())
    return "chart has no border";
  border_loop.clear();
  // Ends: add_face keeps the mesh valid, so the border cycle returns to
  // `border` (at most 3 F halfedges).
  for(Chart_mesh::Halfedge_index h : CGAL::halfedges_around_face(border, mesh))
    border_loop.push_back(static_cast<Index>(std::size_t(mesh.target(h))));

  if(c.triangles.size() == 1)
  {
    lay_out_single_triangle(m, c);
    return std::string();
  }

  // A chart whose vertices all coincide has no flattening; worse, SMP's
  // LSCM divides by the length of the bounding box to pick its two fixed
  // vertices, picks none (NaN comparisons) and then writes the UV of a null
  // vertex, out of bounds.
  if(m.at_one_point(c.faces))
    return "degenerate chart (all vertices at one point)";

  return method.parameterize_copy(m, c, mesh, border, border_loop, validated, look);
}

// What solving cost in one call: each time a method runs on a chart
// (a fallback, a union a merge tries, a chart a reroute changes: every
// try), the chart's faces. Divided by the mesh's faces, how many times a
// face was solved.
struct Solve_tally
{
  std::atomic<std::size_t> charts{ 0 }, faces{ 0 };

  void add(const Chart& c)
  {
    charts.fetch_add(1, std::memory_order_relaxed);
    faces.fetch_add(c.triangles.size(), std::memory_order_relaxed);
  }
};

struct Chart_outcome
{
  Parameterization_method used = Parameterization_method::TUTTE;
  bool fallback = false;  // another method than the requested one was used
  bool valid = false;
  // The requested method itself failed (solver error, no border, not a
  // manifold chart, non-finite UVs), as opposed to returning a map with
  // flipped triangles or a self-intersecting border.
  bool method_error = false;
  std::string problem;    // why the requested method was rejected (empty if it was not)
};

// The requested method, then, if its chart is invalid and `use_fallback`,
// mean value coordinates and Tutte's barycentric map on a circle: both are
// injective by construction for a disk mapped to a convex border (positive
// weights), so they only fail on numerically degenerate input. With
// `On_invalid_map::report`, a chart of more than one triangle gets the
// requested method from its first start only.
inline Chart_outcome parameterize_chart(const Indexed_triangle_mesh& m, Chart& c, const Chart_method& requested,
                                        bool use_fallback, On_invalid_map on_invalid, Early_look* look,
                                        Solve_tally& tally)
{
  Chart_outcome outcome;
  std::vector<Index> border_loop;
  std::vector<const Chart_method*> chain(1, &requested);
  if(c.triangles.size() < 2)
    on_invalid = On_invalid_map::redo;
  if(use_fallback && on_invalid == On_invalid_map::redo)
    for(Parameterization_method fallback : { Parameterization_method::MEAN_VALUE, Parameterization_method::TUTTE })
      if(fallback != requested.id())
        chain.push_back(&built_in_chart_method(fallback));

  // The fallback chain: at most three methods (requested, mean value, Tutte).
  for(std::size_t i = 0; i < chain.size(); ++i)
  {
    tally.add(c);
    bool validated = false;
    std::string problem = parameterize_chart_with(m, c, *chain[i], border_loop, validated, on_invalid, look);
    bool error = !problem.empty();
    if(problem.empty() && !validated)
    {
      keep_winding(c);
      problem = chart_uv_problem(c, c.uv, border_loop);
      error = (problem == non_finite_uv);
    }
    if(i == 0)
    {
      outcome.problem = problem;
      outcome.method_error = error;
    }
    if(problem.empty())
    {
      outcome.used = chain[i]->id();
      outcome.fallback = (i > 0);
      outcome.valid = true;
      return outcome;
    }
  }
  outcome.used = chain.back()->id();
  outcome.fallback = chain.size() > 1;
  return outcome;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_METHOD_CHAIN_H
