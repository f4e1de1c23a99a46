// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The segmentation's named parameters, read and checked once by the public
// functions; the stages take the settings, not the parameters.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_SEGMENTATION_SETTINGS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_SEGMENTATION_SETTINGS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Merge_tree.h>
#include <CGAL/Disk_segmentation/default_values.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Canonical_parameters.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>
#include <CGAL/Disk_segmentation/parameters.h>
#include <CGAL/Disk_segmentation/regular_polygon_threshold.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Random.h>
#include <CGAL/iterator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

struct Segmentation_settings
{
  std::size_t number_of_seeds;       // n of the Voronoi step
  std::size_t number_of_subsamples;  // k of the refinement
  double merge_threshold;            // eps of the merging
  double crease_penalty;             // of the dual distance (Indexed_triangle_mesh)
  bool smooth_borders;               // of the refined regions
};

inline std::size_t checked_number_of_seeds(std::size_t n)
{
  if(n == 0)
    throw Input_error("number_of_seeds must be at least 1");
  return n;
}

inline std::size_t checked_number_of_subsamples(std::size_t k)
{
  if(k < 2)
    throw Input_error("number_of_subsamples must be at least 2");
  return k;
}

inline double checked_merge_threshold(double eps)
{
  if(!(eps >= 0.) || !std::isfinite(eps))
    throw Input_error("merge_threshold must be a finite number >= 0");
  return eps;
}

// The named parameters of the three steps, checked in this order.
template <typename NamedParameters>
Segmentation_settings segmentation_settings(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Segmentation_settings s;
  s.number_of_seeds = checked_number_of_seeds(count_parameter(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::number_of_seeds), default_number_of_seeds),
    "number_of_seeds"));
  s.number_of_subsamples = checked_number_of_subsamples(count_parameter(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::number_of_subsamples),
                     default_number_of_subsamples),
    "number_of_subsamples"));
  s.merge_threshold = checked_merge_threshold(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::merge_threshold),
                     regular_polygon_threshold(default_merge_threshold_sides)));
  s.crease_penalty = crease_penalty_parameter(np);
  s.smooth_borders = static_cast<bool>(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::smooth_borders), default_smooth_borders));
  return s;
}

// What the stages read from a chain besides the settings: the mesh's maps
// and the seeds' kinds (forward_mesh_parameters()), and the crease penalty
// that build_indexed_triangle_mesh() gives the mesh. Its type depends only
// on the maps given, so that every chain of plain values compiles the
// stages once.
template <typename NamedParameters>
auto stage_parameters(const NamedParameters& np, const Segmentation_settings& s)
{
  return forward_mesh_parameters(np, parameters::crease_penalty(s.crease_penalty));
}

// The `merge_tree` named parameter: a Merge_tree* or null.
template <typename NamedParameters>
Merge_tree* merge_tree_parameter(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return choose_parameter(get_parameter(np, Disk_segmentation::internal_np::merge_tree),
                          static_cast<Merge_tree*>(nullptr));
}

// The `first_seed` named parameter as a face index (no_index when not
// given), among `face_handles`.
template <typename NamedParameters, typename FaceHandles>
Index first_seed_parameter(const NamedParameters& np, const FaceHandles& face_handles)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters,
                                                      Disk_segmentation::internal_np::first_seed_t>::value)
    return no_index;
  else
  {
    const auto f = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::first_seed),
                                    face_handles.front());
    const auto it = std::find(face_handles.begin(), face_handles.end(), f);
    if(it == face_handles.end())
      throw Input_error("first_seed is not a face of the mesh");
    return static_cast<Index>(it - face_handles.begin());
  }
}

// CGAL's `random_seed` named parameter as a generator; null when not given.
template <typename NamedParameters>
std::unique_ptr<CGAL::Random> random_generator_parameter(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::random_seed_t>::value)
    return nullptr;
  else
    return std::make_unique<CGAL::Random>(choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u));
}

// The seeds, as face descriptors, into the `seeds_output_iterator` parameter.
template <typename NamedParameters, typename Seeds>
void write_seeds(const NamedParameters& np, const Seeds& seeds)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto out = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::seeds_output_iterator),
                              CGAL::Emptyset_iterator());
  for(const auto& s : seeds)
    *out++ = s;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_SEGMENTATION_SETTINGS_H
