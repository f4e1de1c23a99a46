// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one reader of a Distortion_bound: whether a chart's measures meet it,
// and how far they are from it. The splitting, merging and rerouting of
// charts ask here rather than read the bound's fields themselves.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_BOUND_TEST_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_BOUND_TEST_H

#include <CGAL/Disk_segmentation/Distortion_bound.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_distortion.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// A bound seen from the charts it judges. Holds a reference: it lives no
// longer than the bound it reads.
class Bound_test
{
public:
  explicit Bound_test(const Distortion_bound& bound) : bound_(bound) {}

  // Whether no chart can break the bound (every valid chart is kept).
  bool bounds_nothing() const { return bound_.is_unbounded(); }

  // Whether distortion `d` is within every distortion field. Written so
  // that a NaN fails.
  bool meets_distortion(const Chart_distortion& d) const
  {
    return d.angle <= bound_.max_angle_distortion && d.area <= bound_.max_area_distortion &&
           d.max_stretch <= bound_.max_stretch && d.max_area_scale <= bound_.max_area_scale &&
           d.min_area_scale * bound_.max_area_scale >= 1 && d.stretch_p95 <= bound_.max_stretch_p95;
  }

  // Whether the shape of a chart is bounded at all.
  bool bounds_convexity() const { return bound_.min_convexity > 0.; }

  // The convexity a chart holding `area_fraction` of the mesh's 3D area
  // must reach: the small ones fill the holes between the large ones and
  // are held to less.
  double least_convexity(double area_fraction) const
  {
    return area_fraction >= Distortion_bound::convexity_area_fraction
             ? bound_.min_convexity
             : Distortion_bound::small_chart_convexity_ratio * bound_.min_convexity;
  }

  // Whether a chart of convexity `convexity` and holding `area_fraction` of
  // the mesh's 3D area is under `margin` times the convexity it must reach.
  bool too_concave(double convexity, double area_fraction, double margin = 1.) const
  {
    if(!bounds_convexity())
      return false;
    return convexity < margin * least_convexity(area_fraction);
  }

  // The larger of the chart's two mean distortions over their bounds (0 for
  // an infinite bound; above 1: over the bound).
  double mean_excess(const Chart_distortion& d) const
  {
    const double e =
      (std::max)(std::isfinite(bound_.max_angle_distortion) ? d.angle / bound_.max_angle_distortion : 0.,
                 std::isfinite(bound_.max_area_distortion) ? d.area / bound_.max_area_distortion : 0.);
    return std::isfinite(e) ? e : std::numeric_limits<double>::infinity();
  }

  // How close a chart is to the bound: the largest of its mean distortions
  // over their bounds and of its p95 s1/s2 over its bound (both less one);
  // 1 at the bound.
  double load(const Chart_distortion& d) const
  {
    double load = 0.;
    if(std::isfinite(bound_.max_angle_distortion))
      load = (std::max)(load, d.angle / bound_.max_angle_distortion);
    if(std::isfinite(bound_.max_area_distortion))
      load = (std::max)(load, d.area / bound_.max_area_distortion);
    if(std::isfinite(bound_.max_stretch_p95))
      load = (std::max)(load, (d.stretch_p95 - 1.) / (bound_.max_stretch_p95 - 1.));
    return load;
  }

  // Whether the p95 s1/s2 of `d`, less one, is more than 1 / `margin` times
  // its bound's.
  bool p95_far_over(const Chart_distortion& d, double margin) const
  {
    return (d.stretch_p95 - 1.) * margin > bound_.max_stretch_p95 - 1.;
  }

  // How much looser the bounds on the means are than the defaults (the
  // looser of the two; 0 when both are infinite).
  double looseness_of_means() const
  {
    const Distortion_bound defaults;
    double looser = 0.;
    if(std::isfinite(bound_.max_angle_distortion))
      looser = (std::max)(looser, bound_.max_angle_distortion / defaults.max_angle_distortion);
    if(std::isfinite(bound_.max_area_distortion))
      looser = (std::max)(looser, bound_.max_area_distortion / defaults.max_area_distortion);
    return looser;
  }

private:
  const Distortion_bound& bound_;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_BOUND_TEST_H
