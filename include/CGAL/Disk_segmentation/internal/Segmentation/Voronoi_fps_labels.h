// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Voronoi step on a whole indexed mesh: its seeds and every face's cell.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_VORONOI_FPS_LABELS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_VORONOI_FPS_LABELS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Segmentation_settings.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Voronoi_fps.h>

#include <CGAL/Random.h>

#include <cstddef>
#include <memory>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// The Voronoi step on an indexed mesh with `number_of_seeds` seeds (see
// Segmentation_settings): returns the seeds (face indices) and writes into
// `labels` the position of each face's seed. `np` gives the first seed and
// the random seed, if any.
template <typename NamedParameters, typename FaceHandles>
std::vector<Index> voronoi_fps_labels(const Indexed_triangle_mesh& m,
                                      const FaceHandles& face_handles,
                                      Voronoi_fps& fps,
                                      std::size_t number_of_seeds,
                                      const NamedParameters& np,
                                      std::vector<Index>& labels)
{
  const Index first = first_seed_parameter(np, face_handles);
  const std::unique_ptr<CGAL::Random> rng = random_generator_parameter(np);
  std::vector<Index> all_faces(m.number_of_faces());
  std::iota(all_faces.begin(), all_faces.end(), Index(0));
  const std::vector<Index> seeds = fps.run(all_faces, number_of_seeds, first, rng.get());

  labels = fps.cells();
  return seeds;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_VORONOI_FPS_LABELS_H
