// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_PARAMETERIZE_PATCHES_H
#define CGAL_DISK_SEGMENTATION_PARAMETERIZE_PATCHES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Parameterization_method.h>
#include <CGAL/Disk_segmentation/parameters.h>
#include <CGAL/Disk_segmentation/refine_to_topological_disks.h>
#include <CGAL/Disk_segmentation/internal/Chart_parameterization.h>
#include <CGAL/Disk_segmentation/internal/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Progress.h>
#include <CGAL/Disk_segmentation/internal/Region_topology.h>
#include <CGAL/Disk_segmentation/internal/Voronoi_fps.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// What happened to one chart in `parameterize_patches()`.
struct Chart_report
{
  /// Patch id of the chart (after splits, see `split`).
  std::size_t patch = 0;
  /// Number of faces of the chart.
  std::size_t faces = 0;
  /// Method asked for.
  Parameterization_method requested = Parameterization_method::LSCM;
  /// Method whose result was kept.
  Parameterization_method used = Parameterization_method::LSCM;
  /// `true` if `used` differs from `requested` because the requested result was invalid.
  bool fallback = false;
  /// `true` if the chart is a piece of a patch that was split (no method gave a valid chart,
  /// its area distortion exceeded `max_area_distortion`, or it had more than `max_chart_faces` faces).
  bool split = false;
  /// `true` if the chart's UVs are valid (finite, no flipped or degenerate triangle, simple border).
  bool valid = false;
  /// `true` if the requested method itself failed (solver error, no border, non-manifold chart,
  /// non-finite UVs) rather than returning a map with flipped triangles or an overlapping border.
  bool method_error = false;
  /// Why the requested method's result was rejected; empty if it was kept.
  std::string problem;
  /// Area-weighted mean of |log(s1/s2)| over the chart (0 for an isometry).
  double angle_distortion = 0;
  /// Area-weighted mean of |log(s1 s2)| with the chart scaled to its 3D area (0 for an isometry).
  double area_distortion = 0;
};

/// \ingroup PkgDiskSegmentationRef
/// Summary of `parameterize_patches()`.
struct Parameterization_report
{
  /// One entry per chart, by patch id.
  std::vector<Chart_report> charts;
  /// Charts that needed a fallback method.
  std::size_t number_of_fallbacks = 0;
  /// Patches split because no method gave a valid chart, or because of their area distortion or size.
  std::size_t number_of_split_patches = 0;
  /// Charts left invalid (only possible with `use_fallback(false)`).
  std::size_t number_of_invalid_charts = 0;
  /// Charts where the requested method itself failed (see `Chart_report::method_error`),
  /// whether or not a fallback then repaired them.
  std::size_t number_of_method_errors = 0;
};

/// \ingroup PkgDiskSegmentationRef
/// The method `parameterize_patches()` uses when none is given: ARAP. It
/// starts from the injective mean value map and keeps only iterates that
/// stay valid, so it never needs a fallback when mean value coordinates
/// succeed, and it has the lowest area distortion of all methods (see the
/// README for the measurements behind this choice).
constexpr Parameterization_method default_parameterization_method = Parameterization_method::ARAP;

/// \ingroup PkgDiskSegmentationRef
/// The `max_area_distortion` of `parameterize_patches()` when none is
/// given: a chart whose area-weighted mean \f$ |\log(s_1 s_2)| \f$ (chart
/// scaled to its 3D area) exceeds 1, i.e. whose triangles are on average
/// more than e = 2.7 times too large or too small, is split. That catches
/// the tube-like charts closed at one end that no flattening keeps near
/// isometric (on the 89k-face refined elephant the benchmark-variant area
/// distortion drops from 12.3 to 0.29, for 32 charts instead of 18 and about
/// 50% more time); `std::numeric_limits<double>::infinity()` keeps the
/// paper's charts unchanged.
constexpr double default_max_area_distortion = 1.0;

/// \ingroup PkgDiskSegmentationRef
/// The `max_chart_faces` of `parameterize_patches()` when none is given:
/// patches of more than \f$ 2^{17} \f$ = 131,072 faces are split before
/// they are parameterized. The time and memory of a chart's sparse
/// factorization grow faster than its number of faces: on a 2.2M-face mesh
/// this bound halves the parameterization time and keeps the peak memory of
/// the whole pipeline at 0.89 GB on one thread (1.06 GB on two), for 3 more
/// charts than \f$ 2^{18} \f$ (see the benchmark README). With the default
/// 10 seeds, meshes below about 1M faces rarely have such patches.
constexpr std::size_t default_max_chart_faces = std::size_t(1) << 17;

namespace internal {

struct Parameterization_settings
{
  Parameterization_method method;
  bool use_fallback, require_disks;
  unsigned int threads;
  double max_area_distortion;
  std::size_t max_chart_faces;
};

// The named parameters of parameterize_patches(), checked.
template <typename NamedParameters>
Parameterization_settings parameterization_settings(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Parameterization_settings s;
  s.method = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::parameterization_method),
                              default_parameterization_method);
  s.use_fallback = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::use_fallback), true);
  s.require_disks = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::require_disk_patches), true);
  s.threads = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::number_of_threads), 0u);
  s.max_area_distortion = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::max_area_distortion),
                                           default_max_area_distortion);
  if(!(s.max_area_distortion > 0))
    throw Input_error("max_area_distortion must be > 0 (infinity disables splitting)");
  s.max_chart_faces = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::max_chart_faces),
                                       default_max_chart_faces);
  if(s.max_chart_faces < 1)
    throw Input_error("max_chart_faces must be >= 1");
  return s;
}

// Runs `work(i)` for i in [0, n), on up to `threads` threads (0: TBB's
// choice). Each call must touch only its own data.
template <typename Work>
void for_each_index(std::size_t n, unsigned int threads, const Work& work)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(threads != 1)
  {
    tbb::task_arena arena(threads == 0 ? tbb::task_arena::automatic : static_cast<int>(threads));
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1), [&](const tbb::blocked_range<std::size_t>& r) {
        for(std::size_t i = r.begin(); i != r.end(); ++i)
          work(i);
      });
    });
    return;
  }
#else
  CGAL_USE(threads);
#endif
  for(std::size_t i = 0; i < n; ++i)
    work(i);
}

// What splitting a chart needs: farthest-point sampling and the disk test.
struct Splitter
{
  explicit Splitter(const Indexed_triangle_mesh& m) : fps(m), topology(m) {}
  Voronoi_fps fps;
  Region_topology topology;
};

// Splits a chart into the Voronoi cells of two seeds (one per component if
// it has more), refined to disks, and parameterizes each piece on its own; a
// piece too large to parameterize, or for which `needs_split` holds once
// parameterized, is split again.
//
// Bound: `faces` (at least 2) gets at least two seeds, each keeping its own
// face, so every piece is smaller than `faces`, and a single triangle is
// always kept: at most |faces| - 1 splits below a patch, nested as deep
// (far fewer in practice: cells halve the chart). A chart whose points all
// coincide, where zero arcs would let a split take only one face off, is
// cut into single faces at once.
template <typename NeedsSplit>
void split_and_parameterize(const Indexed_triangle_mesh& m, Splitter& splitter, const std::vector<Index>& faces,
                            Parameterization_method requested, bool use_fallback, std::vector<Chart>& pieces,
                            std::vector<Chart_outcome>& outcomes, const NeedsSplit& needs_split)
{
  if(faces.size() < 2)
    return;
  // Never valid as a whole, and Voronoi cells of zero arcs split it slowly:
  // single faces at once.
  if(m.at_one_point(faces))
  {
    for(Index f : faces)
    {
      Chart c = make_chart(m, std::vector<Index>(1, f));
      outcomes.push_back(parameterize_chart(m, c, requested, use_fallback));
      pieces.push_back(std::move(c));
    }
    return;
  }
  // More than two cells when `faces` has more than two components (a patch
  // that is not a disk, with require_disk_patches(false)).
  const std::size_t seeds = splitter.fps.run(faces, 2).size();
  std::vector<std::vector<Index> > cells(seeds);
  for(Index f : faces)
    cells[splitter.fps.cell(f)].push_back(f);
  const std::vector<std::vector<Index> > parts =
    refine_region_list(splitter.topology, splitter.fps, std::move(cells), 5);
  for(const std::vector<Index>& part : parts)
  {
    if(needs_split.too_large(part.size()))
    {
      split_and_parameterize(m, splitter, part, requested, use_fallback, pieces, outcomes, needs_split);
      continue;
    }
    Chart c = make_chart(m, part);
    const Chart_outcome outcome = parameterize_chart(m, c, requested, use_fallback);
    if(part.size() == 1 || !needs_split(c, outcome))
    {
      pieces.push_back(std::move(c));
      outcomes.push_back(outcome);
    }
    else
      split_and_parameterize(m, splitter, part, requested, use_fallback, pieces, outcomes, needs_split);
  }
}

// One Splitter per thread (both members keep per-query scratch state the
// size of the mesh), made on first use.
class Per_thread_splitter
{
public:
  explicit Per_thread_splitter(const Indexed_triangle_mesh& m) : m_(m) {}

  Splitter& local()
  {
#ifdef CGAL_LINKED_WITH_TBB
    std::unique_ptr<Splitter>& splitter = per_thread_.local();
#else
    std::unique_ptr<Splitter>& splitter = single_;
#endif
    if(!splitter)
      splitter.reset(new Splitter(m_));
    return *splitter;
  }

private:
  const Indexed_triangle_mesh& m_;
#ifdef CGAL_LINKED_WITH_TBB
  tbb::enumerable_thread_specific<std::unique_ptr<Splitter> > per_thread_;
#else
  std::unique_ptr<Splitter> single_;
#endif
};

// Whether a patch is split: before it is parameterized, when it has more
// than `max_chart_faces` faces; after, with the fallback on, when its chart
// is invalid or its area distortion exceeds `max_area_distortion` and it is
// large enough for pieces to help.
struct Split_rule
{
  const Indexed_triangle_mesh& m;
  double max_area_distortion;
  std::size_t max_chart_faces;
  bool use_fallback;

  bool too_large(std::size_t faces) const { return faces > max_chart_faces; }

  bool operator()(const Chart& c, const Chart_outcome& outcome) const
  {
    if(!use_fallback)
      return false;
    if(!outcome.valid)
      return true;
    return c.faces.size() >= smallest_chart_to_split && std::isfinite(max_area_distortion) &&
           chart_distortion(m, c).area > max_area_distortion;
  }

  // Charts below this size are not split for distortion: the pieces would
  // add more seams than they remove distortion.
  static constexpr std::size_t smallest_chart_to_split = 32;
};

} // namespace internal

/// \ingroup PkgDiskSegmentationRef
///
/// Parameterizes every patch of `tm` on its own with CGAL's
/// Surface_mesh_parameterization, in parallel, and writes per-corner UVs.
///
/// Each chart is validated: finite UVs, every triangle keeps the 3D winding
/// with a non-negligible area (charts that come out mirrored are mirrored
/// back), and the UV border is a simple polygon; together these make the
/// chart injective. With `use_fallback` (the default), an invalid chart is
/// redone with mean value coordinates, then Tutte's barycentric map, both on
/// a circle and injective by construction; if even those fail numerically,
/// the patch is split in two and each piece redone, and the pieces get new
/// patch ids (appended after the existing ones) in `face_patch_map`. Valid
/// charts whose area distortion exceeds `max_area_distortion` are split the
/// same way (the paper does not do this; it removes the few tube-like charts
/// that no flattening can keep near isometric). Patches with more than
/// `max_chart_faces` faces are split the same way before they are
/// parameterized, with or without the fallback.
///
/// UVs are per corner: `uv_map[h]` is the UV of `target(h)` as seen from
/// `face(h)`, so charts are cut along patch borders. Charts are not placed
/// relative to each other: see `pack_patches()`.
///
/// Charts do not depend on each other, and each is computed the same way on
/// any thread, so results do not depend on the number of threads.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` whose faces are triangles
/// @tparam FacePatchMap a model of `ReadWritePropertyMap` with `face_descriptor` as key type and an
///         integral value type; patch ids must be contiguous, `0` to `P - 1`
/// @tparam UVMap a model of `WritablePropertyMap` with `halfedge_descriptor` as key type and a 2D
///         point type (constructible from two `double`) as value type
/// @tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
///
/// @param tm a triangle mesh, manifold, without garbage
/// @param face_patch_map the patches, each a topological disk (see `segment_into_disks()`)
/// @param uv_map receives the UVs
/// @param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{parameterization_method}
///     \cgalParamDescription{the method of every chart}
///     \cgalParamType{`Parameterization_method`}
///     \cgalParamDefault{`default_parameterization_method` (ARAP)}
///   \cgalParamNEnd
///   \cgalParamNBegin{use_fallback}
///     \cgalParamDescription{whether invalid charts are redone (see above); when `false`, they are
///       kept as the method produced them and reported invalid}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_area_distortion}
///     \cgalParamDescription{charts (of at least 32 faces) whose area-weighted mean of
///       \f$ |\log(s_1 s_2)| \f$ exceeds this value are split and redone, recursively; only
///       with `use_fallback`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`default_max_area_distortion` (1.0); infinity disables splitting}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_chart_faces}
///     \cgalParamDescription{patches with more faces are split (recursively, in two) before they are
///       parameterized, which bounds the memory of each chart's linear systems}
///     \cgalParamType{`std::size_t`, at least 1}
///     \cgalParamDefault{`default_max_chart_faces` (131,072)}
///   \cgalParamNEnd
///   \cgalParamNBegin{require_disk_patches}
///     \cgalParamDescription{when `false`, patches that are not topological disks are parameterized
///       anyway, as a segmentation that ignores topology would be (for comparisons): they usually
///       fail, which the report says, instead of an exception}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{maximum number of threads (0: TBB's choice; 1: sequential). Without TBB, sequential.}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{called with `("parameterization", charts done, charts)` after each chart}
///     \cgalParamType{`std::function<void(const std::string&, std::size_t, std::size_t)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key type and the traits' `Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class, used to read coordinates}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{a \cgal Kernel deduced from the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map, vertex_index_map}
///     \cgalParamDescription{as in `voronoi_fps_segmentation()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// @return one report per chart and the counts of fallbacks, splits and invalid charts
///
/// @throws Input_error on a bad mesh (as `voronoi_fps_segmentation()`), on patch ids that are not
///         contiguous, or on a patch that is not a topological disk (unless `require_disk_patches(false)`).
template <typename TriangleMesh, typename FacePatchMap, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
Parameterization_report parameterize_patches(const TriangleMesh& tm,
                                             FacePatchMap face_patch_map,
                                             UVMap uv_map,
                                             const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<UVMap>::value_type UV;
  using internal::Index;

  const internal::Parameterization_settings settings = internal::parameterization_settings(np);
  const Parameterization_method method = settings.method;
  const bool use_fallback = settings.use_fallback;
  const unsigned int threads = settings.threads;
  const bool require_disks = settings.require_disks;
  const double max_area_distortion = settings.max_area_distortion;

  internal::Indexed_triangle_mesh m;
  std::vector<typename GT::face_descriptor> face_handles;
  std::vector<typename GT::vertex_descriptor> vertex_handles;
  internal::build_indexed_triangle_mesh(tm, np, m, face_handles, &vertex_handles);

  const std::vector<std::size_t> ids = internal::read_face_labels(face_handles, face_patch_map);
  const std::size_t number_of_patches = *std::max_element(ids.begin(), ids.end()) + 1;
  std::vector<std::vector<Index> > patch_faces(number_of_patches);
  for(Index f = 0; f < ids.size(); ++f)
    patch_faces[ids[f]].push_back(f);
  internal::Region_topology topology(m);
  for(std::size_t p = 0; p < number_of_patches; ++p)
  {
    if(patch_faces[p].empty())
      throw Input_error("patch ids are not contiguous: no face has id " + std::to_string(p));
    if(require_disks && !topology.is_disk(patch_faces[p]))
      throw Input_error("patch " + std::to_string(p) + " is not a topological disk");
  }

  // Largest charts first, so that threads end together.
  std::vector<std::size_t> order(number_of_patches);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return patch_faces[a].size() > patch_faces[b].size(); });

  // Each task parameterizes one patch and, if needed, splits it (see
  // Split_rule); pieces are numbered after the parallel pass, in patch
  // order, so ids do not depend on scheduling.
  const internal::Split_rule needs_split{ m, max_area_distortion, settings.max_chart_faces, use_fallback };
  std::vector<std::vector<internal::Chart> > pieces(number_of_patches);
  std::vector<std::vector<internal::Chart_outcome> > piece_outcomes(number_of_patches);
  internal::Per_thread_splitter splitter(m);
  internal::Progress progress = internal::Progress::from(np);
  internal::for_each_index(number_of_patches, threads, [&](std::size_t i) {
    const std::size_t p = order[i];
    if(needs_split.too_large(patch_faces[p].size()))
    {
      internal::split_and_parameterize(m, splitter.local(), patch_faces[p], method, use_fallback, pieces[p],
                                       piece_outcomes[p], needs_split);
      progress.step("parameterization", number_of_patches);
      return;
    }
    internal::Chart chart = internal::make_chart(m, patch_faces[p]);
    internal::Chart_outcome outcome = internal::parameterize_chart(m, chart, method, use_fallback);
    if(chart.faces.size() >= 2 && needs_split(chart, outcome))
    {
      internal::split_and_parameterize(m, splitter.local(), patch_faces[p], method, use_fallback, pieces[p],
                                       piece_outcomes[p], needs_split);
      for(internal::Chart_outcome& o : piece_outcomes[p])
        o.problem = outcome.problem;
    }
    else
    {
      pieces[p].push_back(std::move(chart));
      piece_outcomes[p].push_back(outcome);
    }
    progress.step("parameterization", number_of_patches);
  });

  Parameterization_report report;
  std::vector<internal::Chart> charts(number_of_patches);
  std::vector<internal::Chart_outcome> outcomes(number_of_patches);
  for(std::size_t p = 0; p < number_of_patches; ++p)
  {
    report.number_of_split_patches += (pieces[p].size() > 1) ? 1 : 0;
    charts[p] = std::move(pieces[p][0]);
    outcomes[p] = piece_outcomes[p][0];
  }
  for(std::size_t p = 0; p < number_of_patches; ++p)
    for(std::size_t i = 1; i < pieces[p].size(); ++i)
    {
      charts.push_back(std::move(pieces[p][i]));
      outcomes.push_back(piece_outcomes[p][i]);
    }

  report.charts.resize(charts.size());
  for(std::size_t p = 0; p < charts.size(); ++p)
  {
    const internal::Chart& c = charts[p];
    Chart_report& r = report.charts[p];
    r.patch = p;
    r.faces = c.faces.size();
    r.requested = method;
    r.used = outcomes[p].used;
    r.fallback = outcomes[p].fallback;
    r.split = (p >= number_of_patches) || (c.faces.size() != patch_faces[p].size());
    r.valid = outcomes[p].valid;
    r.method_error = outcomes[p].method_error;
    r.problem = outcomes[p].problem;
    const internal::Chart_distortion d = internal::chart_distortion(m, c);
    r.angle_distortion = d.angle;
    r.area_distortion = d.area;
    report.number_of_fallbacks += r.fallback ? 1 : 0;
    report.number_of_invalid_charts += r.valid ? 0 : 1;
    report.number_of_method_errors += r.method_error ? 1 : 0;

    // The corner of face f whose target is indexed vertex v gets uv[local v].
    for(std::size_t t = 0; t < c.faces.size(); ++t)
    {
      const Index f = c.faces[t];
      if(p >= number_of_patches || c.faces.size() != patch_faces[p].size())
        put(face_patch_map, face_handles[f],
            static_cast<typename boost::property_traits<FacePatchMap>::value_type>(p));
      // Three halfedges: build_indexed_triangle_mesh checked the triangles.
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_handles[f], tm), tm))
        for(int j = 0; j < 3; ++j)
          if(vertex_handles[m.corners[f][j]] == target(h, tm))
          {
            const std::array<double, 2>& u = c.uv[c.triangles[t][j]];
            put(uv_map, h, UV(u[0], u[1]));
          }
    }
  }
  return report;
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_PARAMETERIZE_PATCHES_H
