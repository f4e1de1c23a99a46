// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// quality_table, the child's side: one case (mesh x segmentation x method)
// measured and streamed to the parent, one line per value.

#ifndef DISK_SEGMENTATION_BENCHMARK_QUALITY_TABLE_CASE_H
#define DISK_SEGMENTATION_BENCHMARK_QUALITY_TABLE_CASE_H

#include "quality_table_support.h"

namespace {

// ---------------------------------------------------------------------------
// The child: one case

// The child's side of the protocol: "\n@@\tkey\tvalue\n". The leading
// newline ends whatever the library may have written to stderr (which goes
// to the same pipe) without a newline; the parent skips empty lines. Each
// line is one write() shorter than PIPE_BUF, so it is never interleaved.
struct Reporter
{
  int fd;
  void operator()(const std::string& key, const std::string& value) const
  {
    std::string line = "\n@@\t" + key + "\t" + one_line(value);
    if(line.size() > 3500)
      line.resize(3500);
    write_all(fd, line + "\n");
  }
  void operator()(const std::string& key, double value) const { (*this)(key, format_double(value)); }
  void operator()(const std::string& key, std::size_t value) const { (*this)(key, std::to_string(value)); }
};

// Checks what the library assumes of its input; returns the problem, or an empty string.
std::string input_problem(const Mesh& mesh)
{
  if(faces(mesh).empty())
    return "no face";
  if(!CGAL::is_triangle_mesh(mesh))
    return "not a triangle mesh";
  if(!CGAL::is_valid_polygon_mesh(mesh))
    return "not a valid polygon mesh";
  // A vertex is non-manifold when the halfedges that point to it form more
  // than one umbrella: the cycle around it then misses some of them. (This
  // is PMP::is_non_manifold_vertex(), in linear time for the whole mesh.)
  std::vector<std::size_t> incoming(num_vertices(mesh), 0);
  for(Mesh::Halfedge_index h : halfedges(mesh))
    ++incoming[std::size_t(target(h, mesh))];
  std::size_t non_manifold = 0;
  for(Mesh::Vertex_index v : vertices(mesh))
  {
    if(mesh.is_isolated(v))
      continue;
    std::size_t around = 0;
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_target(halfedge(v, mesh), mesh))
    {
      CGAL_USE(h);
      ++around;
    }
    if(around != incoming[std::size_t(v)])
      ++non_manifold;
  }
  if(non_manifold > 0)
    return std::to_string(non_manifold) + " non-manifold vertices";
  for(Mesh::Vertex_index v : vertices(mesh))
  {
    const Kernel::Point_3& p = mesh.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return "non-finite coordinate";
  }
  return std::string();
}

struct Case_settings
{
  std::string file;
  std::string segmentation;
  DS::Parameterization_method method;
  std::size_t seeds;
  unsigned int threads;
  unsigned int texture_resolution;
  double crease_penalty;  // of `ours` (see DS::parameters::crease_penalty())
};

template <typename NamedParameters>
DS::Parameterization_report parameterize(const Mesh& mesh, Patch_map patches, UV_map uv, const NamedParameters& np)
{
  return DS::parameterize_patches(mesh, patches, uv, np);
}

// Runs one case and reports it; the first failure reason wins.
void run_case(const Case_settings& s, const Reporter& report)
{
  Mesh mesh;
  bool read = false;
  try
  {
    read = CGAL::IO::read_polygon_mesh(s.file, mesh);
  }
  catch(const std::exception& e)
  {
    report("input_error", std::string("cannot read: ") + e.what());
    return;
  }
  if(!read)
  {
    report("input_error", "cannot read the file as a polygon mesh");
    return;
  }
  report("faces", static_cast<std::size_t>(num_faces(mesh)));
  const std::string problem = input_problem(mesh);
  if(!problem.empty())
  {
    report("input_error", problem);
    return;
  }

  Patch_map patches = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  UV_map uv = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv", Kernel::Point_2(0, 0)).first;
  bool failed = false;
  auto fail = [&](const std::string& kind, const std::string& reason) {
    if(failed)
      return;
    failed = true;
    report("failure_kind", kind);
    report("reason", reason);
  };

  // Segmentation.
  Clock::time_point start = Clock::now();
  std::size_t count = 0;
  DS::Merge_tree tree;
  try
  {
    if(s.segmentation == "components")
      count = PMP::connected_components(mesh, patches);
    else if(s.segmentation == "voronoi")
      // The paper's baseline, by the paper's distance.
      count = DS::voronoi_fps_segmentation(mesh, patches,
                                           DS::parameters::number_of_seeds(s.seeds).crease_penalty(0.));
    else if(s.segmentation == "ours")
      // What uv_atlas() does: smoothed borders, merge tree for the bound.
      count = DS::segment_into_disks(mesh, patches,
                                     DS::parameters::number_of_seeds(s.seeds).merge_tree(&tree).smooth_borders(true)
                                       .crease_penalty(s.crease_penalty));
    else
      count = DS::segment_into_disks(mesh, patches,
                                     DS::parameters::number_of_seeds(s.seeds).crease_penalty(s.crease_penalty));
  }
  catch(const std::exception& e)
  {
    report("seconds_segmentation", seconds_since(start));
    fail("exception", std::string("segmentation: ") + e.what());
    return;
  }
  report("seconds_segmentation", seconds_since(start));
  report("segments", count);

  // Parameterization: baselines without fallback and with non-disk charts
  // allowed; ours with the defaults (fallback, and splitting of charts of
  // high area distortion); ours-nosplit with the fallback only (the paper's
  // charts, invalid ones repaired); ours-nofallback with neither.
  start = Clock::now();
  DS::Parameterization_report p;
  try
  {
    // The splits of a patch over the bound use the segmentation's distance.
    const auto np = DS::parameters::parameterization_method(s.method).number_of_threads(s.threads)
                      .crease_penalty(s.crease_penalty);
    const double inf = std::numeric_limits<double>::infinity();
    if(s.segmentation == "ours")
      p = parameterize(mesh, patches, uv, np.merge_tree(&tree));
    else if(s.segmentation == "ours-nosplit")
      p = parameterize(mesh, patches, uv,
                       np.distortion_bound(DS::Distortion_bound::unbounded())
                         .smooth_borders(false));
    else if(s.segmentation == "ours-nofallback")
      p = parameterize(mesh, patches, uv,
                       np.use_fallback(false)
                         .distortion_bound(DS::Distortion_bound::unbounded())
                         .smooth_borders(false));
    else
      // The paper's baselines: no bound (use_fallback(false) alone keeps it).
      p = parameterize(mesh, patches, uv,
                       np.use_fallback(false).require_disk_patches(false)
                         .distortion_bound(DS::Distortion_bound::unbounded()));
  }
  catch(const std::exception& e)
  {
    report("seconds_parameterization", seconds_since(start));
    fail("exception", std::string("parameterize_patches: ") + e.what());
    return;
  }
  report("seconds_parameterization", seconds_since(start));
  report("fallbacks", p.number_of_fallbacks);
  report("split_patches", p.number_of_split_patches);
  report("invalid_charts", p.number_of_invalid_charts);
  report("method_errors", p.number_of_method_errors);
  report("solves_per_face", static_cast<double>(p.solved_faces) / static_cast<double>(num_faces(mesh)));
  const bool fallback_on = (s.segmentation == "ours" || s.segmentation == "ours-nosplit");
  if(!fallback_on && p.number_of_method_errors > 0)
  {
    for(const DS::Chart_report& c : p.charts)
      if(c.method_error)
      {
        report("reason_problem", c.problem);
        fail("method error", c.problem + " (chart " + std::to_string(c.patch) + " of " +
                                std::to_string(p.charts.size()) + ", " + std::to_string(c.faces) + " faces; " +
                                std::to_string(p.number_of_method_errors) + " charts failed)");
        break;
      }
  }

  // The paper's GRID packing of the same charts, measured apart: TIGHT
  // packing gives every chart the same texel density, so its
  // atlas-normalized distortion equals the chart-normalized one, while GRID
  // scales every chart to its cell. Not timed, not a failure if it throws.
  if(!failed)
  {
    UV_map grid_uv = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:grid_uv", Kernel::Point_2(0, 0)).first;
    for(Mesh::Halfedge_index h : halfedges(mesh))
      grid_uv[h] = uv[h];
    try
    {
      DS::pack_patches(mesh, patches, grid_uv,
                       DS::parameters::packing_method(DS::Packing_method::GRID).texture_resolution(s.texture_resolution));
      const DS::Atlas_quality g = DS::atlas_quality(mesh, patches, grid_uv, DS::parameters::texture_resolution(0u));
      if(!g.failed)
      {
        report("grid_benchmark_atlas_area_distortion", g.benchmark_atlas_area_distortion);
        report("grid_log_atlas_area_mean", g.atlas_area_distortion.mean);
        report("grid_packing_efficiency", g.packing_efficiency);
      }
    }
    catch(const std::exception& e)
    {
      report("grid_packing_error", e.what());
    }
    mesh.remove_property_map(grid_uv);
  }

  // Packing (needs charts of positive UV area, which a failed chart may not
  // have): on an exception the atlas is measured unpacked.
  start = Clock::now();
  bool packed = false;
  try
  {
    DS::pack_patches(mesh, patches, uv, DS::parameters::texture_resolution(s.texture_resolution));
    packed = true;
  }
  catch(const std::exception& e)
  {
    report("packing_error", e.what());
    fail("exception", std::string("pack_patches: ") + e.what());
  }
  report("seconds_packing", seconds_since(start));

  // Quality.
  start = Clock::now();
  DS::Atlas_quality q;
  try
  {
    q = DS::atlas_quality(mesh, patches, uv, DS::parameters::texture_resolution(packed ? s.texture_resolution : 0u));
  }
  catch(const std::exception& e)
  {
    report("seconds_quality", seconds_since(start));
    fail("exception", std::string("atlas_quality: ") + e.what());
    return;
  }
  report("seconds_quality", seconds_since(start));
  if(q.failed)
  {
    fail("non-finite UV", q.failure_reason);
    return;
  }
  report("charts", q.number_of_charts);
  report("smallest_chart_faces", q.smallest_chart_faces);
  report("single_face_charts", q.single_face_charts);
  report("flipped_faces", q.flipped_faces);
  report("flipped_percent", q.flipped_percent);
  report("degenerate_percent", q.degenerate_percent);
  report("benchmark_area_distortion", q.benchmark_area_distortion);
  report("benchmark_angle_distortion", q.benchmark_angle_distortion);
  report("benchmark_atlas_area_distortion", q.benchmark_atlas_area_distortion);
  report("benchmark_symmetric_dirichlet", q.benchmark_symmetric_dirichlet);
  report("log_area_mean", q.area_distortion.mean);
  report("log_area_p95", q.area_distortion.percentile_95);
  report("log_area_max", q.area_distortion.max);
  report("log_angle_mean", q.angle_distortion.mean);
  report("log_angle_p95", q.angle_distortion.percentile_95);
  report("log_angle_max", q.angle_distortion.max);
  report("log_atlas_area_mean", q.atlas_area_distortion.mean);
  report("conformal_ratio_p95", q.conformal_ratio_p95);
  report("max_conformal_ratio", q.max_conformal_ratio);
  report("min_area_scale", q.min_area_scale);
  report("max_area_scale", q.max_area_scale);
  report("cut_length", q.cut_length);
  report("packing_efficiency", q.packing_efficiency);
  if(packed)
    report("texel_overlaps", q.texel_overlaps);
}

} // namespace

#endif // DISK_SEGMENTATION_BENCHMARK_QUALITY_TABLE_CASE_H
