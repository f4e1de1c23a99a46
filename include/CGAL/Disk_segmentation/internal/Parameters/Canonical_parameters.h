// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The named parameters the heavy stages read, rebuilt in one fixed form.
// A chain's type names every parameter given and its value type, so that
// each distinct chain a user writes (seeds as int or as size_t, a bound or
// not) would instantiate the whole pipeline again. The public functions read
// the values into settings structures and hand the stages a chain whose type
// depends only on the property maps and the seeds' kinds that were given
// (forward_mesh_parameters(); the segmentation adds its crease penalty, see
// stage_parameters()): every chain of plain values compiles the
// pipeline once.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERS_CANONICAL_PARAMETERS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERS_CANONICAL_PARAMETERS_H

#include <CGAL/Disk_segmentation/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <type_traits>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// `base` with the parameter `Tag` of `np` added if `np` has it.
template <typename Tag, typename NamedParameters, typename Base>
auto forward_parameter(const NamedParameters& np, const Base& base)
{
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, Tag>::value)
    return base;
  else
  {
    typedef std::decay_t<decltype(CGAL::parameters::get_parameter(np, Tag()))> Value;
    return Disk_segmentation::Named_function_parameters<Value, Tag, Base>(CGAL::parameters::get_parameter(np, Tag()),
                                                                          base);
  }
}

// The parameters that are maps or that matter by being given at all: how
// to read the mesh (points, kernel, indices), which faces may not share a
// chart or should stay in one, and the first seed.
template <typename NamedParameters, typename Base>
auto forward_mesh_parameters(const NamedParameters& np, const Base& base)
{
  const auto a = forward_parameter<CGAL::internal_np::vertex_point_t>(np, base);
  const auto b = forward_parameter<CGAL::internal_np::geom_traits_t>(np, a);
  const auto c = forward_parameter<CGAL::internal_np::face_index_t>(np, b);
  const auto d = forward_parameter<CGAL::internal_np::vertex_index_t>(np, c);
  const auto e = forward_parameter<Disk_segmentation::internal_np::face_material_map_t>(np, d);
  const auto f = forward_parameter<Disk_segmentation::internal_np::face_polygon_map_t>(np, e);
  const auto g = forward_parameter<Disk_segmentation::internal_np::first_seed_t>(np, f);
  return forward_parameter<CGAL::internal_np::random_seed_t>(np, g);
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERS_CANONICAL_PARAMETERS_H
