// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The JSON report of an atlas (nlohmann-json), as disk_uv --report and the
// Python module's Atlas.report write it, for one mesh or several in one
// atlas. Only what the library computed:
// a measure of the process (its peak memory) is the caller's to add.

#ifndef CGAL_DISK_SEGMENTATION_IO_ATLAS_REPORT_JSON_H
#define CGAL_DISK_SEGMENTATION_IO_ATLAS_REPORT_JSON_H

#include <CGAL/Disk_segmentation/Atlas_report.h>
#include <CGAL/Disk_segmentation/IO/Read_options.h>
#include <CGAL/Disk_segmentation/Multi_mesh_atlas_report.h>
#include <CGAL/Disk_segmentation/Packing_report.h>
#include <CGAL/Disk_segmentation/Parameterization_method.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {

/// \ingroup PkgDiskSegmentationIO
/// The packing and its pages as JSON: `efficiency`, `texels_per_unit`,
/// `pages`, `charts_below_a_texel`, `page_efficiency`, `page_of_chart`.
inline nlohmann::json packing_report_json(const CGAL::Disk_segmentation::Packing_report& p)
{
  return { { "efficiency", p.efficiency },
           { "texels_per_unit", p.texels_per_unit },
           { "pages", p.number_of_pages },
           { "charts_below_a_texel", p.number_of_charts_below_a_texel },
           { "page_efficiency", p.page_efficiency },
           { "page_of_chart", p.page_of_chart } };
}

/// \ingroup PkgDiskSegmentationIO
/// The packing of one mesh of several packed together (`uv_atlas_of_meshes()`),
/// whose charts are `first_chart` to `end_chart - 1` of the common packing
/// `p`: `efficiency`, `texels_per_unit` and `pages` of the common packing,
/// and `page_of_chart` for this mesh's charts only, from `first_chart` on.
/// The common `page_efficiency` and the other meshes' charts are left to the
/// common packing's report: repeated for every mesh, they made the reports
/// of many meshes quadratic in size.
inline nlohmann::json packing_report_json(const CGAL::Disk_segmentation::Packing_report& p, std::size_t first_chart,
                                          std::size_t end_chart)
{
  const std::size_t end = (std::min)(end_chart, p.page_of_chart.size());
  const std::size_t first = (std::min)(first_chart, end);
  return { { "efficiency", p.efficiency },
           { "texels_per_unit", p.texels_per_unit },
           { "pages", p.number_of_pages },
           { "page_of_chart", std::vector<std::size_t>(p.page_of_chart.begin() + first,
                                                       p.page_of_chart.begin() + end) } };
}

/// \ingroup PkgDiskSegmentationIO
/// Everything an atlas report holds, as JSON: sizes, what reading changed,
/// the stages' times and one entry per chart. The process's peak memory,
/// which the front ends report as `peak_rss_mb`, is theirs to measure and add.
/// `input` names the mesh's source, `method` and `packer` the names the
/// user gave, `read_seconds` the time reading took.
inline nlohmann::json atlas_report_json(const std::string& input, std::size_t vertices,
                                        const CGAL::Disk_segmentation::Atlas_report& r, const std::string& method,
                                        const std::string& packer, double read_seconds, const Read_changes& changes)
{
  nlohmann::json charts = nlohmann::json::array();
  for(const Chart_report& c : r.parameterization.charts)
    charts.push_back({ { "patch", c.patch }, { "faces", c.faces }, { "requested", to_string(c.requested) },
                       { "used", to_string(c.used) }, { "fallback", c.fallback }, { "split", c.split },
                       { "valid", c.valid }, { "problem", c.problem },
                       { "angle_distortion", c.angle_distortion }, { "area_distortion", c.area_distortion },
                       { "max_stretch", c.max_stretch }, { "min_area_scale", c.min_area_scale },
                       { "max_area_scale", c.max_area_scale }, { "stretch_p95", c.stretch_p95 } });
  return {
    { "input", input },
    { "faces", r.number_of_faces },
    { "vertices", vertices },
    { "method", method },
    { "packer", packer },
    { "input_changes", { { "polygons_triangulated", changes.polygons_triangulated },
                         { "fan_triangulations", changes.fan_triangulations },
                         { "faces_added", changes.faces_added },
                         { "faces_removed", changes.faces_removed },
                         { "vertices_added", changes.vertices_added },
                         { "vertices_removed", changes.vertices_removed },
                         { "pinched_vertices_split", changes.pinched_vertices_split } } },
    { "segmentation", { { "voronoi_cells", r.number_of_voronoi_cells },
                        { "refined_regions", r.number_of_refined_regions },
                        { "charts", r.number_of_charts } } },
    { "parameterization", { { "fallbacks", r.parameterization.number_of_fallbacks },
                            { "split_patches", r.parameterization.number_of_split_patches },
                            { "invalid_charts", r.parameterization.number_of_invalid_charts },
                            { "charts_before_budget", r.parameterization.charts_before_budget },
                            { "chart_budget_met", r.parameterization.chart_budget_met },
                            { "solves", r.parameterization.number_of_solves },
                            { "solved_faces", r.parameterization.solved_faces },
                            { "solved_faces_in_merges", r.parameterization.solved_faces_in_merges },
                            { "solved_faces_in_reroutes", r.parameterization.solved_faces_in_reroutes },
                            { "solves_per_face", r.solves_per_face() } } },
    { "polygons", { { "moved_whole_into_one_chart", r.polygons_moved_whole },
                    { "left_across_charts", r.polygons_left_across_charts } } },
    { "packing", packing_report_json(r.packing) },
    { "seconds", { { "read", read_seconds }, { "voronoi", r.voronoi_seconds }, { "refine", r.refine_seconds },
                   { "merge", r.merge_seconds }, { "parameterization", r.parameterization_seconds },
                   { "packing", r.packing_seconds }, { "total", r.total_seconds } } },
    { "charts", charts } };
}

/// \ingroup PkgDiskSegmentationIO
/// The report of mesh `i` of several packed together (`uv_atlas_of_meshes()`)
/// as JSON: `atlas_report_json()` of its own report, whose `packing` holds the
/// pages of its charts only (`packing_report_json()` with its charts), and
/// `first_chart`, the id of its first chart. `input` names the mesh's source.
///
/// \pre `i < r.meshes.size()` and `r.first_chart` has `r.meshes.size() + 1` entries.
inline nlohmann::json mesh_in_atlas_report_json(const std::string& input, std::size_t vertices,
                                                const CGAL::Disk_segmentation::Multi_mesh_atlas_report& r,
                                                std::size_t i, const std::string& method, const std::string& packer,
                                                const Read_changes& changes)
{
  // Read time is the caller's for all meshes together, not per mesh.
  nlohmann::json mesh = atlas_report_json(input, vertices, r.meshes[i], method, packer, 0., changes);
  // The common packing is reported once, beside the meshes: repeated in
  // every mesh's report it made the reports of many meshes quadratic.
  mesh["packing"] = packing_report_json(r.packing, r.first_chart[i], r.first_chart[i + 1]);
  mesh["first_chart"] = r.first_chart[i];
  return mesh;
}

/// \ingroup PkgDiskSegmentationIO
/// The report of several meshes in one atlas (`uv_atlas_of_meshes()`) as
/// JSON: `inputs`, the report of each mesh (`mesh_in_atlas_report_json()`),
/// `charts`, the number of charts of all meshes, `packing`, the common
/// packing, and `seconds` (`read`, `packing`, `total`). `inputs`,
/// `vertices` and `changes` give each mesh's source, number of vertices
/// and what reading changed; `read_seconds` is the time reading all took.
///
/// \pre `inputs`, `vertices` and `changes` have one entry per mesh of `r`.
inline nlohmann::json atlas_of_meshes_report_json(const std::vector<std::string>& inputs,
                                                  const std::vector<std::size_t>& vertices,
                                                  const CGAL::Disk_segmentation::Multi_mesh_atlas_report& r,
                                                  const std::string& method, const std::string& packer,
                                                  double read_seconds, const std::vector<Read_changes>& changes)
{
  nlohmann::json meshes = nlohmann::json::array();
  for(std::size_t i = 0; i < r.meshes.size(); ++i)
    meshes.push_back(mesh_in_atlas_report_json(inputs[i], vertices[i], r, i, method, packer, changes[i]));
  return { { "inputs", meshes },
           { "charts", r.first_chart.back() },
           { "packing", packing_report_json(r.packing) },
           { "seconds", { { "read", read_seconds }, { "packing", r.packing_seconds },
                          { "total", r.total_seconds } } } };
}

} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_ATLAS_REPORT_JSON_H
