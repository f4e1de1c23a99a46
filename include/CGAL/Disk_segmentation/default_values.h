// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The named parameters' defaults, in one place: the library's functions, the
// disk_uv tool and the Python module all read them from here.

#ifndef CGAL_DISK_SEGMENTATION_DEFAULT_VALUES_H
#define CGAL_DISK_SEGMENTATION_DEFAULT_VALUES_H

#include <CGAL/Disk_segmentation/Parameterization_method.h>

#include <cstddef>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// The `number_of_seeds` of the joint farthest-point sampling when none is
/// given: the paper's 10.
constexpr std::size_t default_number_of_seeds = 10;

/// \ingroup PkgDiskSegmentationRef
/// The `number_of_subsamples` a region that is not a disk is re-sampled
/// with when none is given: the paper's 5. Also the number of cells a patch
/// is split into when none of its maps is valid.
constexpr std::size_t default_number_of_subsamples = 5;

/// \ingroup PkgDiskSegmentationRef
/// The default `merge_threshold` is `regular_polygon_threshold()` of this
/// many sides (about 0.7624), the paper's best setting.
constexpr int default_merge_threshold_sides = 5;

/// \ingroup PkgDiskSegmentationRef
/// Whether region borders lose their saw teeth (`smooth_borders`) when the
/// parameter is not given, in every function that reads it: not in the
/// paper, whose segmentation `smooth_borders(false)` with `crease_penalty(0)`
/// gives.
constexpr bool default_smooth_borders = true;

/// \ingroup PkgDiskSegmentationRef
/// The `crease_penalty` when none is given: a dual arc across an edge whose
/// faces' normals are \f$ \theta \f$ apart counts
/// \f$ 1 + 10 (1 - \cos\theta) \f$ times its length, so that Voronoi cells
/// and region borders follow creases. Not in the paper, whose distance
/// `crease_penalty(0)` gives; see \ref DS_Creases in the user manual for the
/// measurements behind this choice.
constexpr double default_crease_penalty = 10.;

/// \ingroup PkgDiskSegmentationRef
/// The `texture_resolution` (texels on a side) of the packers and of the
/// quality measures when none is given.
constexpr unsigned int default_texture_resolution = 1024;

/// \ingroup PkgDiskSegmentationRef
/// The `padding_in_texels` around each chart when none is given.
constexpr double default_padding_in_texels = 2.;

/// \ingroup PkgDiskSegmentationRef
/// The `max_number_of_pages` a fixed `texels_per_unit` may fill when none
/// is given. Pages are packed one after the other, each trying every chart
/// left: the cap keeps that linear in the charts whatever density is given.
constexpr std::size_t default_max_number_of_pages = 64;

/// \ingroup PkgDiskSegmentationRef
/// The method `parameterize_patches()` uses when none is given: ARAP. It
/// starts from the free-border LSCM map (from the injective mean value map
/// when that fails) and keeps only iterates that stay valid, so it never
/// needs a fallback when mean value coordinates succeed, and it has the
/// lowest area distortion of all methods (see \ref DS_Parameterization in
/// the user manual for the measurements behind this choice).
constexpr Parameterization_method default_parameterization_method = Parameterization_method::ARAP;

/// \ingroup PkgDiskSegmentationRef
/// The `max_chart_faces` of `parameterize_patches()` when none is given:
/// patches of more than \f$ 2^{17} = 131072 \f$ faces are split before
/// they are parameterized. The time and memory of a chart's sparse
/// factorization grow faster than its number of faces: on a 2.2M-face mesh
/// this bound halves the parameterization time and keeps the peak memory of
/// the whole pipeline at 0.89 GB on one thread (1.06 GB on two), for 3 more
/// charts than \f$ 2^{18} \f$. With the default
/// 10 seeds, meshes below about 1M faces rarely have such patches.
constexpr std::size_t default_max_chart_faces = std::size_t(1) << 17;

} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_DEFAULT_VALUES_H
