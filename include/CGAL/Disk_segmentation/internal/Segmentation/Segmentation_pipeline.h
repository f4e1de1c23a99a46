// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's three steps in a row on an indexed mesh (Voronoi cells,
// refinement into disks, merging), with their sizes and times.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_SEGMENTATION_PIPELINE_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_SEGMENTATION_PIPELINE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Merge_tree.h>
#include <CGAL/Disk_segmentation/internal/Execution/Progress.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Border_smoother.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Region_merging.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Region_refinement.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Segmentation_settings.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Voronoi_fps.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Voronoi_fps_labels.h>

#include <CGAL/Real_timer.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Sizes and wall-clock times of the three steps of one segmentation.
struct Segmentation_steps
{
  std::size_t voronoi_cells = 0, refined_regions = 0, patches = 0;
  double voronoi_seconds = 0, refine_seconds = 0, merge_seconds = 0;
  // For `seeds_output_iterator`, written by the caller once nothing can throw.
  std::vector<Index> seeds;
};

// The whole method on an indexed mesh with the settings `s`; `labels`
// receives the patch ids and `tree` (if not null) the merges; `np` gives
// the first seed and the random seed, if any. Reports the end of each step
// to `progress` (which may cancel). With `s.smooth_borders`, the borders of
// the refined regions lose their saw teeth (Border_smoother) before they
// are merged.
template <typename NamedParameters, typename FaceHandles>
Segmentation_steps segment_indexed(const Indexed_triangle_mesh& m, const FaceHandles& face_handles,
                                   const Segmentation_settings& s, const NamedParameters& np,
                                   std::vector<Index>& labels, Merge_tree* tree, Progress& progress)
{
  Segmentation_steps steps;
  CGAL::Real_timer timer;
  timer.start();
  // The refinement samples many regions: their arcs are measured once.
  const Dual_arcs arcs = dual_arcs(m);
  Voronoi_fps fps(m, &arcs);
  progress("segmentation", 0, 3);
  steps.seeds = voronoi_fps_labels(m, face_handles, fps, s.number_of_seeds, np, labels);
  steps.voronoi_cells = steps.seeds.size();
  steps.voronoi_seconds = timer.time();
  progress("segmentation", 1, 3);
  timer.reset();
  steps.refined_regions = refine_regions(m, fps, group_faces_by_label(labels), s.number_of_subsamples, labels);
  if(s.smooth_borders)
  {
    std::vector<Index> all(m.number_of_faces());
    for(Index f = 0; f < all.size(); ++f)
      all[f] = f;
    Border_smoother(m).smooth(labels, all);
  }
  steps.refine_seconds = timer.time();
  progress("segmentation", 2, 3);
  timer.reset();
  steps.patches = merge_regions(m, labels, steps.refined_regions, s.merge_threshold, tree);
  steps.merge_seconds = timer.time();
  progress("segmentation", 3, 3);
  return steps;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_SEGMENTATION_PIPELINE_H
