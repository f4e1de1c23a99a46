// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_VORONOI_FPS_LABELS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_VORONOI_FPS_LABELS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/default_values.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Voronoi_fps.h>
#include <CGAL/Disk_segmentation/parameters.h>

#include <CGAL/Random.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/iterator.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

inline std::size_t checked_number_of_seeds(std::size_t n)
{
  if(n == 0)
    throw Input_error("number_of_seeds must be at least 1");
  return n;
}

// The Voronoi step on an indexed mesh: returns the seeds (face indices) and
// writes into `labels` the position of each face's seed.
template <typename NamedParameters, typename FaceHandles>
std::vector<Index> voronoi_fps_labels(const Indexed_triangle_mesh& m,
                                      const FaceHandles& face_handles,
                                      Voronoi_fps& fps,
                                      const NamedParameters& np,
                                      std::vector<Index>& labels)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;

  const std::size_t n = checked_number_of_seeds(count_parameter(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::number_of_seeds), default_number_of_seeds),
    "number_of_seeds"));

  Index first = no_index;
  if(!is_default_parameter<NamedParameters, Disk_segmentation::internal_np::first_seed_t>::value)
  {
    const auto f = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::first_seed),
                                    face_handles.front());
    const auto it = std::find(face_handles.begin(), face_handles.end(), f);
    if(it == face_handles.end())
      throw Input_error("first_seed is not a face of the mesh");
    first = static_cast<Index>(it - face_handles.begin());
  }

  std::unique_ptr<CGAL::Random> rng;
  if(!is_default_parameter<NamedParameters, CGAL::internal_np::random_seed_t>::value)
    rng.reset(new CGAL::Random(choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u)));

  std::vector<Index> all_faces(m.number_of_faces());
  std::iota(all_faces.begin(), all_faces.end(), Index(0));
  const std::vector<Index> seeds = fps.run(all_faces, n, first, rng.get());

  labels = fps.cells();
  return seeds;
}

template <typename NamedParameters, typename FaceHandles>
void write_seeds(const NamedParameters& np, const std::vector<Index>& seeds, const FaceHandles& face_handles)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto out = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::seeds_output_iterator),
                              CGAL::Emptyset_iterator());
  for(Index s : seeds)
    *out++ = face_handles[s];
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_VORONOI_FPS_LABELS_H
