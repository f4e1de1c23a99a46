// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// uv_atlas() up to the packing, shared with uv_atlas_of_meshes():
// segmentation, merge tree and chart parameterization in one call.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_ATLAS_ATLAS_PIPELINE_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_ATLAS_ATLAS_PIPELINE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Atlas_report.h>
#include <CGAL/Disk_segmentation/Distortion_bound.h>
#include <CGAL/Disk_segmentation/Merge_tree.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Face_group_moves.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Patch_parameterization.h>
#include <CGAL/Disk_segmentation/internal/Execution/Progress.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Packing/Packing_settings.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Parameterization_settings.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Region_merging.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Segmentation_pipeline.h>
#include <CGAL/Disk_segmentation/parameters.h>

#include <CGAL/Real_timer.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// uv_atlas() up to the packing: the patches of `tm` in `face_patch_map`,
// their charts' UVs in `uv_map` (not yet packed), the merge tree and the
// seeds. Shared with uv_atlas_of_meshes(). `np` is a chain of
// stage_parameters(); the values come checked in `segmentation`,
// `settings` and `packing`.
template <typename TriangleMesh, typename FacePatchMap, typename UVMap, typename NamedParameters>
Atlas_report segment_and_parameterize(const TriangleMesh& tm, FacePatchMap face_patch_map, UVMap uv_map,
                                      const NamedParameters& np, const Segmentation_settings& segmentation,
                                      const Parameterization_settings& settings,
                                      const Packing_settings& packing, Progress& progress, Merge_tree& tree,
                                      std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& seeds)
{
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  Atlas_report report;
  CGAL::Real_timer timer;
  {
    // One indexed mesh for the segmentation and the parameterization.
    const Indexed_input<TriangleMesh> input(tm, np);
    {
      std::vector<Index> labels;
      const Segmentation_steps steps =
        segment_indexed(input.mesh, input.face_handles, segmentation, np, labels, &tree, progress);
      // Charts only split from here: too many patches for the padding can
      // be told before the parameterization.
      check_packing_capacity(packing, steps.patches);
      write_face_labels(input.face_handles, labels, face_patch_map);
      for(Index s : steps.seeds)
        seeds.push_back(input.face_handles[s]);
      report.number_of_faces = input.mesh.number_of_faces();
      report.number_of_voronoi_cells = steps.voronoi_cells;
      report.number_of_refined_regions = steps.refined_regions;
      report.voronoi_seconds = steps.voronoi_seconds;
      report.refine_seconds = steps.refine_seconds;
      report.merge_seconds = steps.merge_seconds;
    }

    timer.start();
    report.parameterization =
      parameterize_indexed_patches(tm, input, face_patch_map, uv_map, settings, progress, &tree);
    if constexpr(!is_default_parameter<NamedParameters, Disk_segmentation::internal_np::face_polygon_map_t>::value)
    {
      const auto polygon_map = checked_face_group_map<TriangleMesh>(
        get_parameter(np, Disk_segmentation::internal_np::face_polygon_map));
      typedef typename boost::property_traits<std::decay_t<decltype(polygon_map)> >::value_type Polygon_id;
      std::vector<Polygon_id> polygon_of;
      polygon_of.reserve(input.face_handles.size());
      for(face_descriptor f : input.face_handles)
        polygon_of.push_back(get(polygon_map, f));
      const std::vector<std::size_t> ids = read_face_labels(input.face_handles, face_patch_map);
      std::vector<Index> labels(ids.begin(), ids.end());
      const Face_group_moves moves = keep_polygons_whole(input.mesh, polygon_of, labels);
      report.polygons_moved_whole = moves.moved;
      report.polygons_left_across_charts = moves.left;
      if(moves.moved > 0)
      {
        // The charts are parameterized again, each whole, without the bound:
        // a split would cut polygons again.
        write_face_labels(input.face_handles, labels, face_patch_map);
        Parameterization_settings unbounded = settings;
        unbounded.bound = Distortion_bound::unbounded();
        const Parameterization_report first = std::move(report.parameterization);
        report.parameterization =
          parameterize_indexed_patches(tm, input, face_patch_map, uv_map, unbounded, progress, nullptr);
        // Both calls' solves count.
        report.parameterization.solved_faces += first.solved_faces;
        report.parameterization.solved_faces_in_merges += first.solved_faces_in_merges;
        report.parameterization.solved_faces_in_reroutes += first.solved_faces_in_reroutes;
        report.parameterization.number_of_solves += first.number_of_solves;
      }
    }
    face_leaves_to_input_order(input.mesh, tree);
    report.number_of_charts = report.parameterization.charts.size();
    report.parameterization_seconds = timer.time();
  }
  return report;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_ATLAS_ATLAS_PIPELINE_H
