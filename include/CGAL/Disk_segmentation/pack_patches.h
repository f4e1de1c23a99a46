// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_PACK_PATCHES_H
#define CGAL_DISK_SEGMENTATION_PACK_PATCHES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Packing_method.h>
#include <CGAL/Disk_segmentation/Packing_report.h>
#include <CGAL/Disk_segmentation/internal/Execution/Progress.h>
#include <CGAL/Disk_segmentation/internal/Packing/Packing_settings.h>
#include <CGAL/Disk_segmentation/internal/Packing/Patch_packing.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Canonical_parameters.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>
#include <CGAL/Disk_segmentation/parameters.h>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
///
/// Places the UV charts of the patches of `tm` in the unit square without
/// overlap: every chart is moved by one similarity of its own (uniform scale,
/// rotation and translation, never a reflection, so the winding of its faces
/// is kept), all charts end inside \f$ [0,1]^2 \f$, and any two charts, and
/// a chart and the sides of the square, are at least
/// `padding_in_texels / texture_resolution` apart.
///
/// With `Packing_method::TIGHT` (the default), every chart is first scaled by
/// \f$ \sqrt{A_{3D} / A_{UV}} \f$ so that all have the same texel density,
/// rotated so that its minimum-area bounding rectangle (rotating calipers on
/// the convex hull of its UVs) is axis-aligned with its longer side
/// horizontal, and the rectangles are packed by a best-fit skyline packer
/// (each step fills the lowest gap with the widest rectangle that fits it),
/// which may turn a rectangle by a quarter turn to fill a gap. A search
/// guided by each trial's packing density, then bisection, finds the largest
/// common scale (to 0.05 percent) at which the packing fits in the square;
/// the padding, fixed in texels, does not scale with the charts. Then the
/// chart shapes are packed (not ours in the paper, nor a rectangle packer):
/// on a grid of at most 512 cells across, each chart in each of its four
/// quarter turns is reduced to the lowest and highest cell it covers in
/// every column, and charts are dropped, largest first, onto the skyline of
/// those already placed where their top ends lowest (plus 5 % of the cells
/// they leave empty below), so that jagged charts nest into each other's
/// dents; bisection finds the largest scale at which that fits (only for
/// 64 charts or fewer: with more, the raster packer alone packs as much in
/// less time). Then the
/// shapes are packed again with their holes (the raster packer, ours): on
/// the same grid, each chart in each of its eight orientations (eighths of
/// a turn; four quarter turns for charts under 400 cells, two for those
/// under 100) becomes the set of cells it touches (its border triangles
/// rasterized, its inside filled by crossing parity), and charts are
/// placed, largest first, where their top ends lowest (then lowest, then
/// leftmost) among the positions where that set grown by the padding meets
/// no cell already taken, so that small charts fill the holes under and
/// inside large ones and long charts may lie along a diagonal; each trial
/// aims at the scale at which the rows used would just fill the square, to
/// 1 percent, in at most six trials, starting 20 % above the rectangles'
/// scale, or from the profile packer's scale if that ran. The best of the three
/// layouts (rectangles, profile, raster) is kept; on a tie, the earlier
/// one. Padding is rounded up to whole cells. With TBB and
/// `number_of_threads` other than 1, the orientations of a chart are
/// profiled or rasterized and searched side by side; the layout is the same
/// for any number of threads.
///
/// With `texels_per_unit` given (`TIGHT` only, not in the paper), the scale
/// is not searched: every chart gets that texel density, and pages are
/// filled one after the other by the raster packer, each with the charts
/// left that fit on it, largest first (the xatlas and UVAtlas "atlas
/// count"). A page does not try the charts that cannot fit it: those whose
/// cells are more than the page has free, and those with the same cells in
/// every turn as one that found no room on it (copies of a part), so that
/// the pages cost what they place plus, per page, the distinct charts that
/// fail. Each chart lies whole in the unit square of its page;
/// `Packing_report::page_of_chart` says which page that is. A chart that
/// does not fit an empty page, or more pages than `max_number_of_pages`,
/// throws `Input_error` naming the chart's size in texels.
///
/// With `Packing_method::GRID` (the paper's packer), chart `i` goes to cell
/// `i` of a `ceil(sqrt(P)) x ceil(sqrt(P))` grid of equal square cells, row by
/// row from the bottom left (the UV origin). Each chart is turned by the
/// rotation that lets it be scaled largest in a square (found exactly over
/// the convex hull: edge directions and the angles where width equals
/// height), scaled to fill its cell less the padding, and centered.
///
/// The result is deterministic: it depends only on the input, in the order of
/// `faces(tm)`. Time is \f$ O(N \log N) \f$ for the \f$ N = 3F \f$ UV corners
/// of the `F` faces plus, for
/// `TIGHT`, \f$ O(P \log P) \f$ per trial rectangle packing (typically under
/// ten) and, per trial profile packing (about ten), the cells the charts
/// cross plus 4 times 512 times the sum of the charts' widths in cells; per
/// raster trial (at most six), per chart and orientation, the rows of the
/// strip below the chart's position times the free runs it crosses there.
/// Memory is \f$ O(N + P) \f$: the corners are copied once, grouped by chart.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeGraph` whose
///         faces are triangles
/// @tparam FacePatchMap a model of `ReadablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and
///         an integral value type
/// @tparam UVMap a model of `ReadWritePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type
///         and a 2D point as value type (with `x()`, `y()` and a constructor
///         from two `double`s, e.g. `Kernel::Point_2`)
/// @tparam NamedParameters a sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters"
///
/// @param tm a triangle mesh
/// @param face_patch_map the patch id of every face, contiguous in
///        `[0, P)`, as written by `segment_into_disks()`
/// @param uv_map per-corner UVs: `uv_map[h]` is the UV of `target(h)` as seen
///        from `face(h)`; halfedges without a face are neither read nor
///        written. On entry, the charts may have any position, scale and
///        rotation, but every face must have a positive signed UV area
///        (counterclockwise); on return they are packed. Each halfedge must
///        hold its own value (a map that shares storage between halfedges,
///        e.g. one that reads per vertex, would be moved twice).
/// @param np an optional sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{packing_method}
///     \cgalParamDescription{how the charts are placed}
///     \cgalParamType{`Packing_method`}
///     \cgalParamDefault{`Packing_method::TIGHT`}
///   \cgalParamNEnd
///   \cgalParamNBegin{texture_resolution}
///     \cgalParamDescription{side, in texels, of the texture the atlas is made for}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`1024`}
///     \cgalParamExtra{must be at least 1}
///   \cgalParamNEnd
///   \cgalParamNBegin{texture_height}
///     \cgalParamDescription{`TIGHT` only: height, in texels, of a non-square texture; `texture_resolution` is
///       then its width. The UVs still span the unit square (each page's), so that a chart is a similar copy of
///       its parameterization in texels, stretched by `texture_height / texture_resolution` in \f$ v \f$ relative to
///       \f$ u \f$ in UV units}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`texture_resolution`}
///     \cgalParamExtra{must be at least 1}
///   \cgalParamNEnd
///   \cgalParamNBegin{padding_in_texels}
///     \cgalParamDescription{gap kept between the charts' bounding rectangles and along the sides of the square, in texels}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`2`}
///     \cgalParamExtra{must be finite, >= 0 and less than half of `texture_resolution`}
///   \cgalParamNEnd
///   \cgalParamNBegin{texels_per_unit}
///     \cgalParamDescription{`TIGHT` only: texels of the target texture per unit of 3D length, fixed. The charts
///       are then spread over as many pages (textures of `texture_resolution` texels, each the unit square of
///       its own UVs) as they need; 0: the largest density that fits all charts on one page}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0`}
///     \cgalParamExtra{must be finite and >= 0}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_number_of_pages}
///     \cgalParamDescription{most pages a fixed `texels_per_unit` may fill; more throws `Input_error`}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`64`}
///     \cgalParamExtra{must be at least 1}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{maximum number of threads of the `TIGHT` packing (0: TBB's choice; 1: sequential). Without TBB, sequential.}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{called as `("packing", trial, 16)` before each trial layout of the `TIGHT`
///       packing; a `false` result stops it with `Cancelled` before any UV is written}
///     \cgalParamType{a callable of `(const std::string&, std::size_t, std::size_t)` returning `bool` or `void`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm` (3D areas of `TIGHT`)}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key type and the traits' `Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class, used only to read coordinates: they are converted with `CGAL::to_double()` and all computation runs in `double` whatever the kernel}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{a \cgal Kernel deduced from the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// @return a `Packing_report`; a mesh without faces gives 0 charts and leaves
///         `uv_map` untouched
///
/// @throws Input_error if a parameter is out of range, a face is not a
///         triangle, a patch id is out of range or a patch has no face, a
///         patch has a zero, negative or non-finite UV area (or, for `TIGHT`,
///         a non-finite 3D area), or the padding leaves no room for all
///         charts, or (with `texels_per_unit`) a chart is larger than a page or
///         the charts need more than `max_number_of_pages` pages. `uv_map` is
///         not written then. A `TIGHT` chart whose 3D area
///         is zero (degenerate faces) or below a millionth of the mean chart
///         area is not an error: it is given the size of a chart of a
///         millionth of the mean chart area.
template <typename TriangleMesh, typename FacePatchMap, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
Packing_report pack_patches(const TriangleMesh& tm,
                            FacePatchMap face_patch_map,
                            UVMap uv_map,
                            const NamedParameters& np = parameters::default_values())
{
  static_assert(internal::Check_patch_map<FacePatchMap>::value, "");
  static_assert(internal::Check_named_parameters<NamedParameters>::value, "");
  internal::Progress progress = internal::Progress::from(np);
  internal::Packing_settings settings = internal::packing_settings(np);
  settings.progress = &progress;
  // The coordinates are read through a chain of the mesh's maps only: one
  // instantiation for any chain of values.
  return internal::pack_checked_patches(tm, internal::checked_patch_map<TriangleMesh>(face_patch_map),
                                        internal::checked_uv_map<TriangleMesh>(uv_map), settings,
                                        internal::forward_mesh_parameters(np, parameters::default_values()));
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_PACK_PATCHES_H
