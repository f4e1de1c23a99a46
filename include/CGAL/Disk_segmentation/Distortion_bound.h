// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_DISTORTION_BOUND_H
#define CGAL_DISK_SEGMENTATION_DISTORTION_BOUND_H

#include <CGAL/Disk_segmentation/Input_error.h>

#include <limits>
#include <string>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// The distortion a chart may have to be kept as it is; `parameterize_patches()`
/// and `uv_atlas()` split or re-choose the charts that exceed any field.
///
/// With \f$ s_1 \ge s_2 \f$ the singular values of a triangle's Jacobian, the
/// chart scaled so that its UV area equals its 3D area ("chart-normalized",
/// as in `Atlas_quality`), and means weighted by 3D area over the chart:
/// - `max_angle_distortion` bounds the mean of \f$ |\log(s_1/s_2)| \f$;
/// - `max_area_distortion` bounds the mean of \f$ |\log(s_1 s_2)| \f$;
/// - `max_stretch` bounds \f$ s_1/s_2 \f$ of every triangle;
/// - `max_stretch_p95` bounds the 95th percentile of \f$ s_1/s_2 \f$ over
///   the chart's triangles (unweighted): at most 5% of the triangles of a
///   chart, hence of the atlas, are stretched more;
/// - `max_area_scale` bounds \f$ s_1 s_2 \f$ of every triangle to
///   \f$ [1/x, x] \f$.
///
/// The first two keep the texture's average look, the last two its worst
/// spots (a nearly collapsed triangle samples the texture at one point).
///
/// One field bounds a chart's shape rather than its distortion (ours, not
/// in the paper): `min_convexity` bounds from below the ratio of a chart's
/// UV area to the area of the convex hull of its UV layout, for every chart
/// holding at least `convexity_area_fraction` of the mesh's 3D area, and
/// `small_chart_convexity_ratio` times it for the smaller charts. A bent or
/// branching chart leaves room inside its hull that no other chart fills,
/// which is what keeps the atlas from packing tightly (see \ref DS_Bound in
/// the user manual).
///
/// A single triangle is laid out isometrically and is convex, so it meets
/// every bound: splitting always ends. The defaults were chosen by comparing bounds on
/// 10 meshes of \cgal's data set (charts, distortion, cut length and time;
/// see \ref DS_Bound in the user manual); `unbounded()` keeps the paper's charts.
struct Distortion_bound
{
  /// Largest area-weighted mean of \f$ |\log(s_1/s_2)| \f$ of a chart.
  double max_angle_distortion = 0.06;
  /// Largest area-weighted mean of \f$ |\log(s_1 s_2)| \f$ of a chart.
  double max_area_distortion = 0.12;
  /// Largest \f$ s_1/s_2 \f$ of any triangle.
  double max_stretch = 6.;
  /// Largest \f$ \max(s_1 s_2, 1/(s_1 s_2)) \f$ of any triangle.
  double max_area_scale = 6.;
  /// Largest 95th percentile of \f$ s_1/s_2 \f$ over a chart's triangles.
  double max_stretch_p95 = 1.15;
  /// Smallest UV area / UV convex hull area of a chart holding at least
  /// `convexity_area_fraction` of the mesh's 3D area; smaller charts are
  /// held to `small_chart_convexity_ratio` times it (0: no bound).
  double min_convexity = 0.8;

  /// Charts below this fraction of the mesh's 3D area are held to a lower
  /// convexity: they fill the holes between larger ones.
  static constexpr double convexity_area_fraction = 0.03;
  /// The convexity a chart below `convexity_area_fraction` of the area
  /// must reach, as a fraction of `min_convexity`. Small charts free of any
  /// convexity bound merged into branching shapes (thin strips unfolded
  /// from the faces of a CAD part), which cost seams and packing.
  static constexpr double small_chart_convexity_ratio = 0.8;

  /// No bound: every valid chart is kept (the paper's behaviour).
  static Distortion_bound unbounded()
  {
    const double inf = std::numeric_limits<double>::infinity();
    Distortion_bound b;
    b.max_angle_distortion = b.max_area_distortion = b.max_stretch = b.max_area_scale = b.max_stretch_p95 = inf;
    b.min_convexity = 0.;
    return b;
  }

  /// Whether every field bounds nothing (infinite, `min_convexity` 0).
  bool is_unbounded() const
  {
    const double inf = std::numeric_limits<double>::infinity();
    return max_angle_distortion == inf && max_area_distortion == inf && max_stretch == inf && max_area_scale == inf &&
           max_stretch_p95 == inf && min_convexity == 0.;
  }

  /// Throws `Input_error` naming the first field out of range (NaN, a mean
  /// bound \f$ \le 0 \f$, a per-triangle bound \f$ \le 1 \f$, a
  /// `min_convexity` outside \f$ [0, 1) \f$).
  void check() const
  {
    if(!(max_angle_distortion > 0))
      throw Input_error("max_angle_distortion must be > 0 (infinity disables it)");
    if(!(max_area_distortion > 0))
      throw Input_error("max_area_distortion must be > 0 (infinity disables it)");
    if(!(max_stretch > 1))
      throw Input_error("max_stretch must be > 1 (infinity disables it)");
    if(!(max_area_scale > 1))
      throw Input_error("max_area_scale must be > 1 (infinity disables it)");
    if(!(max_stretch_p95 > 1))
      throw Input_error("max_stretch_p95 must be > 1 (infinity disables it)");
    if(!(min_convexity >= 0 && min_convexity < 1))
      throw Input_error("min_convexity must be in [0, 1) (0 disables it)");
  }
};

} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_DISTORTION_BOUND_H
