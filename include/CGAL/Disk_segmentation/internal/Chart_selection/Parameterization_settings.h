// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The named parameters of parameterize_patches() (the method, the bound,
// the chart budget, the border passes), read and checked once.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_PARAMETERIZATION_SETTINGS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_PARAMETERIZATION_SETTINGS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Distortion_bound.h>
#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Parameterization_method.h>
#include <CGAL/Disk_segmentation/default_values.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_methods.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>
#include <CGAL/Disk_segmentation/parameters.h>

#include <cstddef>
#include <memory>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// No chart budget: merge_kept_charts() merges only unions that meet the bound.
constexpr std::size_t no_chart_budget = std::size_t(-1);

struct Parameterization_settings
{
  // Shared: the settings are copied (uv_atlas() retries without the bound).
  std::shared_ptr<const Chart_method> method;
  bool use_fallback, require_disks;
  unsigned int threads;
  Distortion_bound bound;
  std::size_t max_chart_faces;
  std::size_t max_charts;  // no_chart_budget without a budget
  bool smooth_borders, merge_charts, straighten_borders;
};

// The distortion bound from its named parameters.
template <typename NamedParameters>
Distortion_bound distortion_bound_parameters(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Distortion_bound b =
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::distortion_bound), Distortion_bound());
  b.max_angle_distortion =
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::max_angle_distortion), b.max_angle_distortion);
  b.max_area_distortion =
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::max_area_distortion), b.max_area_distortion);
  b.max_stretch = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::max_stretch), b.max_stretch);
  b.max_area_scale =
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::max_area_scale), b.max_area_scale);
  b.max_stretch_p95 =
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::max_stretch_p95), b.max_stretch_p95);
  b.min_convexity = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::min_convexity), b.min_convexity);
  b.check();
  return b;
}

// The method of every chart: `parameterizer` or `parameterization_method`.
template <typename NamedParameters>
std::shared_ptr<const Chart_method> chart_method_parameter(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  constexpr bool object = !is_default_parameter<NamedParameters, Disk_segmentation::internal_np::parameterizer_t>::value;
  constexpr bool by_value =
    !is_default_parameter<NamedParameters, Disk_segmentation::internal_np::parameterization_method_t>::value;
  static_assert(!(object && by_value), "CGAL::Disk_segmentation: give parameterization_method or parameterizer, "
                                       "not both (parameterization_method names the built-in parameterizers)");
  if constexpr(object)
    return user_chart_method(get_parameter(np, Disk_segmentation::internal_np::parameterizer));
  else
  {
    const Chart_method& built_in = built_in_chart_method(choose_parameter(
      get_parameter(np, Disk_segmentation::internal_np::parameterization_method), default_parameterization_method));
    return std::shared_ptr<const Chart_method>(&built_in, [](const Chart_method*) {});  // a static object
  }
}

// The named parameters of parameterize_patches(), checked.
template <typename NamedParameters>
Parameterization_settings parameterization_settings(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Parameterization_settings s;
  s.method = chart_method_parameter(np);
  s.use_fallback = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::use_fallback), true);
  s.require_disks = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::require_disk_patches), true);
  s.threads = number_of_threads_parameter(np);
  s.bound = distortion_bound_parameters(np);
  s.smooth_borders = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::smooth_borders), default_smooth_borders);
  s.merge_charts = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::merge_charts), true);
  s.straighten_borders =
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::straighten_borders), true);
  s.max_chart_faces = count_parameter(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::max_chart_faces), default_max_chart_faces),
    "max_chart_faces");
  if(s.max_chart_faces < 1)
    throw Input_error("max_chart_faces must be >= 1");
  s.max_charts = count_parameter(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::max_number_of_charts), no_chart_budget),
    "max_number_of_charts");
  if(s.max_charts < 1)
    throw Input_error("max_number_of_charts must be >= 1");
  return s;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_PARAMETERIZATION_SETTINGS_H
