// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_PARAMETERIZE_PATCHES_H
#define CGAL_DISK_SEGMENTATION_PARAMETERIZE_PATCHES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Distortion_bound.h>
#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Merge_tree.h>
#include <CGAL/Disk_segmentation/Parameterization_method.h>
#include <CGAL/Disk_segmentation/merge_disk_regions.h>
#include <CGAL/Disk_segmentation/parameters.h>
#include <CGAL/Disk_segmentation/refine_to_topological_disks.h>
#include <CGAL/Disk_segmentation/internal/Border_smoother.h>
#include <CGAL/Disk_segmentation/internal/Canonical_parameters.h>
#include <CGAL/Disk_segmentation/internal/Chart_rerouting.h>
#include <CGAL/Disk_segmentation/internal/Chart_convexity.h>
#include <CGAL/Disk_segmentation/internal/Chart_distortion.h>
#include <CGAL/Disk_segmentation/internal/Chart_merging.h>
#include <CGAL/Disk_segmentation/internal/Chart_parameterization.h>
#include <CGAL/Disk_segmentation/internal/Chart_restriction.h>
#include <CGAL/Disk_segmentation/internal/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Inherited_elimination_order.h>
#include <CGAL/Disk_segmentation/internal/parallel.h>
#include <CGAL/Disk_segmentation/internal/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Parameter_checks.h>
#include <CGAL/Disk_segmentation/internal/Progress.h>
#include <CGAL/Disk_segmentation/internal/Region_curvature.h>
#include <CGAL/Disk_segmentation/internal/Region_topology.h>
#include <CGAL/Disk_segmentation/internal/Voronoi_fps.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/enumerable_thread_specific.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <numeric>
#include <string>
#include <tuple>
#include <unordered_set>
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
  /// it exceeded the distortion bound, or it had more than `max_chart_faces` faces).
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
  /// Largest s1/s2 of a triangle of the chart.
  double max_stretch = 1;
  /// Smallest and largest s1 s2 of a triangle, the chart scaled to its 3D area.
  double min_area_scale = 1, max_area_scale = 1;
  /// 95th percentile of s1/s2 over the chart's triangles.
  double stretch_p95 = 1;
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
  /// With `max_number_of_charts`: how many charts there were under the distortion bound before
  /// merges brought them down to the budget (0 when they were within it).
  std::size_t charts_before_budget = 0;
  /// `false` when the charts are more than `max_number_of_charts`: no two adjacent charts have a
  /// union that is a disk with a valid map (and at most `max_chart_faces` faces).
  bool chart_budget_met = true;
};

namespace internal {

struct Parameterization_settings
{
  Parameterization_method method;
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
  s.threads = number_of_threads_parameter(np);
  s.bound = distortion_bound_parameters(np);
  s.smooth_borders = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::smooth_borders), true);
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

inline double region_area(const Indexed_triangle_mesh& m, const std::vector<Index>& faces)
{
  double area = 0;
  for(Index f : faces)
    area += m.area(f);
  return area;
}

// What splitting a chart needs: farthest-point sampling and the disk test.
struct Splitter
{
  explicit Splitter(const Indexed_triangle_mesh& m)
    : fps(m), topology(m), labels(m.number_of_faces(), no_index), vertex_slot(m.number_of_vertices(), no_index)
  {}
  Voronoi_fps fps;
  Region_topology topology;
  std::vector<Index> labels;       // no_index outside the region being split
  std::vector<Index> vertex_slot;  // scratch of restrict_chart()
};

// A parameterized chart whose UVs its sub-disks may reuse.
typedef std::shared_ptr<const std::pair<Chart, Chart_outcome> > Parent_chart;

// Tries `c` with the UVs its nearest parameterized ancestor `parent` gives
// it: when they are valid and meet the bound, no solver runs. Pieces of a
// chart that is over the bound as a whole often meet it (the distortion
// sits in a part of it).
template <typename NeedsSplit>
bool accept_restriction(const Parent_chart& parent, Chart& c, Chart_outcome& outcome, Splitter& splitter,
                        const NeedsSplit& needs_split)
{
  if(!parent || c.faces.size() < 2 || !restrict_chart(parent->first, c, splitter.vertex_slot).empty())
    return false;
  Chart_outcome restricted = parent->second;
  restricted.valid = true;
  if(needs_split(c, restricted))
    return false;
  outcome = restricted;
  return true;
}

// Removes the saw teeth between the parts of a split region (see
// Border_smoother); the parts stay disks.
inline void smooth_parts(const Border_smoother& smoother, Splitter& splitter, const std::vector<Index>& faces,
                         std::vector<std::vector<Index> >& parts)
{
  for(Index i = 0; i < parts.size(); ++i)
    for(Index f : parts[i])
      splitter.labels[f] = i;
  if(smoother.smooth(splitter.labels, faces) > 0)
  {
    for(std::vector<Index>& part : parts)
      part.clear();
    for(Index f : faces)
      parts[splitter.labels[f]].push_back(f);
  }
  for(Index f : faces)
    splitter.labels[f] = no_index;
}

// A vertex whose angle defect exceeds this (radians) is a cone point: the
// corner of a CAD part, the tip of a spike. Any flattening distorts the
// faces around a cone point inside a chart, and a Voronoi split of two far
// seeds keeps it inside one piece, then inside one piece of that, down to
// pieces of a few faces (fandisk) that merges must glue back; cells of two
// seeds on opposite sides of it put it on the border of both, where it
// opens freely. Measured on the 33 meshes (23 shipped, 10 of the peers'
// table), against farthest seeds: charts 3262 -> 2857 (ChineseDragon-10kv
// 354 -> 256), cut summed over the meshes 600.6 -> 596.0, parameterization
// time 19.8 -> 17.1 s (one run); at 0.5 rad, 3094 charts.
constexpr double smallest_cone_defect = 0.3;

// Two faces of `faces` (sorted) around the vertex v, on opposite sides of
// it: the first one, and the one the most steps from it around v.
inline std::vector<Index> opposite_faces_around(const Indexed_triangle_mesh& m, const std::vector<Index>& faces, Index v)
{
  std::vector<Index> fan;
  for(Index f : faces)
    if(m.corners[f][0] == v || m.corners[f][1] == v || m.corners[f][2] == v)
      fan.push_back(f);
  if(fan.size() < 2)
    return std::vector<Index>();
  std::vector<int> steps(fan.size(), -1);
  std::vector<std::size_t> queue(1, 0);
  steps[0] = 0;
  std::size_t farthest = 0;
  for(std::size_t q = 0; q < queue.size(); ++q)
  {
    const std::size_t i = queue[q];
    if(steps[i] > steps[farthest])
      farthest = i;
    for(Index g : m.neighbors[fan[i]])
    {
      const std::size_t j = static_cast<std::size_t>(std::lower_bound(fan.begin(), fan.end(), g) - fan.begin());
      if(g != no_index && j < fan.size() && fan[j] == g && steps[j] < 0)
      {
        steps[j] = steps[i] + 1;
        queue.push_back(j);
      }
    }
  }
  if(farthest == 0)
    return std::vector<Index>();
  return std::vector<Index>{ fan[0], fan[farthest] };
}

// A region below a rejected candidate (see split_and_parameterize()):
// to split (`split`), or to try as one chart. `path` extends the
// candidate's by the region's index among the parts of every split above
// it, so that pieces ordered by path come in the order a recursion gives.
struct Split_task
{
  std::vector<Index> faces;
  double excess_density;  // of the nearest parameterized ancestor (see Split_rule)
  bool split;
  Parent_chart parent;    // the nearest valid parameterized ancestor, if any
  std::vector<std::size_t> path;
};

// How a region fared when tried as one chart (see try_region()).
enum class Region_trial
{
  kept,              // its chart meets the bound (or it is a single triangle)
  too_large,         // not parameterized: over the size cap, or predicted over the bound
  predicted_curved,  // not parameterized: predicted too curved (Split_rule::predicted_too_curved())
  rejected           // parameterized, and invalid or over the bound
};

// Tries `faces` as one chart: with the UVs of `parent` when they do, else
// parameterized. A rejected chart that is valid becomes the `parent` of the
// region's parts, with its `excess_density`. `chart` and `outcome` are
// those of a kept chart; `outcome.problem` is also why a rejected one was.
template <typename NeedsSplit>
Region_trial try_region(const Indexed_triangle_mesh& m, Splitter& splitter, const std::vector<Index>& faces,
                        Parameterization_method requested, bool use_fallback, const NeedsSplit& needs_split,
                        const Arap_early_look& early_look, double& excess_density, Parent_chart& parent,
                        Chart& chart, Chart_outcome& outcome)
{
  const double area = region_area(m, faces);
  if(needs_split.too_large(faces.size()) || needs_split.predicted_over_bound(excess_density, area, faces.size()))
    return Region_trial::too_large;
  if(needs_split.predicted_too_curved(faces))
    return Region_trial::predicted_curved;
  chart = make_chart(m, faces);
  if(accept_restriction(parent, chart, outcome, splitter, needs_split))
    return Region_trial::kept;
  if(parent && has_elimination_order(parent->first))
    inherit_restricted_order(m, parent->first, chart);
  Early_look look{ &early_look, Early_judgement() };
  outcome = parameterize_chart(m, chart, requested, use_fallback, needs_split.on_invalid_map(), &look);
  double excess = 0.;
  if(faces.size() == 1 || !needs_split(chart, outcome, excess, look.ended))
    return Region_trial::kept;
  if(outcome.valid)
  {
    excess_density = needs_split.excess_density(excess, area);
    parent = std::make_shared<const std::pair<Chart, Chart_outcome> >(std::move(chart), outcome);
  }
  return Region_trial::rejected;
}

// One step of split_and_parameterize(): `task` either is split, and each
// part is given to `add` (last part first), or is tried as one chart,
// which `keep(path, chart, outcome)` receives or which, rejected, is given
// to `add` again to be split; `reject(key)` receives the region_key() of
// every region parameterized and rejected.
//
// Bound: a region of at least 2 faces gets at least two seeds, each
// keeping its own face, so every part is smaller, and a single triangle is
// always kept: at most |faces| - 1 splits below a candidate, nested as
// deep (far fewer in practice: cells halve the chart). A region whose
// points all coincide, where zero arcs would let a split take only one
// face off, is cut into single faces at once.
template <typename NeedsSplit, typename Add, typename Keep, typename Reject>
void split_step(const Indexed_triangle_mesh& m, Splitter& splitter, Split_task& task, Parameterization_method requested,
                bool use_fallback, const NeedsSplit& needs_split, const Arap_early_look& early_look, const Add& add,
                const Keep& keep, const Reject& reject)
{
  if(!task.split)
  {
    Chart c;
    Chart_outcome outcome;
    const Region_trial trial = try_region(m, splitter, task.faces, requested, use_fallback, needs_split, early_look,
                                          task.excess_density, task.parent, c, outcome);
    if(trial == Region_trial::kept)
    {
      keep(std::move(task.path), std::move(c), outcome);
      return;
    }
    if(trial == Region_trial::rejected)
    {
      std::vector<Index> sorted = task.faces;
      std::sort(sorted.begin(), sorted.end());
      reject(region_key(sorted));
    }
    task.split = true;
    add(std::move(task));
    return;
  }

  // Never valid as a whole, and Voronoi cells of zero arcs split it
  // slowly: single faces at once.
  if(m.at_one_point(task.faces))
  {
    for(std::size_t k = 0; k < task.faces.size(); ++k)
    {
      Chart c = make_chart(m, std::vector<Index>(1, task.faces[k]));
      const Chart_outcome outcome = parameterize_chart(m, c, requested, use_fallback);
      std::vector<std::size_t> path = task.path;
      path.push_back(k);
      keep(std::move(path), std::move(c), outcome);
    }
    return;
  }
  // More than two cells when the faces have more than two components (a
  // patch that is not a disk, with require_disk_patches(false)).
  // Under a bound, a region with a cone point inside (see
  // smallest_cone_defect) is split by two seeds on opposite sides of its
  // sharpest one instead.
  std::size_t seeds = 0;
  if(needs_split.curvature != nullptr)
  {
    double defect = 0.;
    const Index cone = needs_split.curvature->sharpest_interior_vertex(m, task.faces, defect);
    if(cone != no_index && std::abs(defect) > smallest_cone_defect)
    {
      const std::vector<Index> sides = opposite_faces_around(m, task.faces, cone);
      if(sides.size() == 2 && splitter.fps.run_from_seeds(task.faces, sides))
        seeds = 2;
    }
  }
  if(seeds == 0)
    seeds = splitter.fps.run(task.faces, 2).size();
  std::vector<std::vector<Index> > cells(seeds);
  for(Index f : task.faces)
    cells[splitter.fps.cell(f)].push_back(f);
  std::vector<std::vector<Index> > parts =
    refine_region_list(splitter.topology, splitter.fps, std::move(cells), default_number_of_subsamples);
  if(needs_split.smoother != nullptr)
    smooth_parts(*needs_split.smoother, splitter, task.faces, parts);
  for(std::size_t i = parts.size(); i-- > 0;)
  {
    std::vector<std::size_t> path = task.path;
    path.push_back(i);
    add(Split_task{ std::move(parts[i]), task.excess_density, false, task.parent, std::move(path) });
  }
}

// Splits a chart into the Voronoi cells of two seeds (one per component if
// it has more), refined to disks, and parameterizes each piece on its own; a
// piece too large to parameterize, or for which `needs_split` holds once
// parameterized, is split again (see split_step()). Pieces come in the
// order of a recursion. The region_key() of every piece that was
// parameterized and split again is added to `rejected`.
template <typename NeedsSplit>
void split_and_parameterize(const Indexed_triangle_mesh& m, Splitter& splitter, const std::vector<Index>& faces,
                            Parameterization_method requested, bool use_fallback, std::vector<Chart>& pieces,
                            std::vector<Chart_outcome>& outcomes, const NeedsSplit& needs_split,
                            std::vector<std::uint64_t>& rejected, double excess_density = 0,
                            Parent_chart parent = Parent_chart())
{
  if(faces.size() < 2)
    return;
  const Arap_early_look early_look = needs_split.early_look();
  std::vector<Split_task> tasks;
  tasks.push_back(Split_task{ faces, excess_density, true, std::move(parent), std::vector<std::size_t>() });
  for_each_growing(std::move(tasks), 1, [&](Split_task& task, const auto& add) {
    split_step(m, splitter, task, requested, use_fallback, needs_split, early_look, add,
               [&](std::vector<std::size_t>, Chart&& c, const Chart_outcome& outcome) {
                 pieces.push_back(std::move(c));
                 outcomes.push_back(outcome);
               },
               [&](std::uint64_t key) { rejected.push_back(key); });
  });
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

// Whether a chart is replaced by smaller ones: before it is parameterized,
// when it has more than `max_chart_faces` faces; after, with the fallback
// on, when it is invalid or exceeds the distortion bound.
struct Split_rule
{
  const Indexed_triangle_mesh& m;
  Distortion_bound bound;
  std::size_t max_chart_faces;
  bool use_fallback;
  const Border_smoother* smoother = nullptr;  // smooths the borders between pieces, if not null
  const Interior_curvature* curvature = nullptr;  // predicts charts too curved to meet the bound, if not null
  double total_area = 0.;  // of the mesh, in common_area() units

  bool too_large(std::size_t faces) const { return faces > max_chart_faces; }

  // Under a bound, an invalid chart is replaced like one over the bound,
  // without the other starts and fallback methods: a chart whose first
  // start folds is large or twisted, and redone from a circle it rarely
  // meets the bound. Measured on 33 meshes (benchmark README): 36 % less
  // time, 0.8 % more charts.
  On_invalid_map on_invalid_map() const
  {
    return use_fallback && !bound.is_unbounded() ? On_invalid_map::report : On_invalid_map::redo;
  }

  bool operator()(const Chart& c, const Chart_outcome& outcome,
                  const Early_judgement& ended = Early_judgement()) const
  {
    double measured;
    return (*this)(c, outcome, measured, ended);
  }

  // The same, measuring the chart once: `measured_excess` gets its
  // excess() when it was measured (a valid chart under a bound), else 0.
  // A chart whose ARAP iterations the early look ended (`ended`, see
  // Early_look) is not measured again: the judgement was drawn from the
  // map it has.
  bool operator()(const Chart& c, const Chart_outcome& outcome, double& measured_excess,
                  const Early_judgement& ended = Early_judgement()) const
  {
    measured_excess = 0.;
    if(!use_fallback)
      return false;
    if(!outcome.valid)
      return true;
    if(bound.is_unbounded())
      return false;
    if(ended.verdict != Early_verdict::iterate_on)
    {
      measured_excess = ended.measure;
      return ended.verdict == Early_verdict::hopeless;
    }
    const Chart_distortion d = chart_distortion(m, c);
    measured_excess = excess(d);
    return breaks_bound(c, c.uv, d);
  }

  // Whether chart `c` under the map `uv`, of distortion `d`, breaks the
  // bound or the convexity bound: the test of a parameterized chart, and
  // of an early ARAP iterate.
  bool breaks_bound(const Chart& c, const Chart_uv& uv, const Chart_distortion& d) const
  {
    return !d.meets(bound) || too_concave(c, uv);
  }

  bool too_concave(const Chart& c, const Chart_uv& uv, double margin = 1.) const
  {
    if(!(bound.min_convexity > 0.))
      return false;
    double area = 0.;
    for(Index f : c.faces)
      area += m.common_area(f);
    return chart_convexity(c, uv) < margin * bound.min_convexity_of(area / total_area);
  }

  // Whether the union of two parameterized charts is not worth
  // parameterizing, from `start`, their two maps glued (see
  // glue_chart_maps()): when its convexity is under
  // glued_convexity_margin of the bound. ARAP moves the seam, not the
  // outline, so the union's chart fills its hull about as the glued maps
  // do: traced on every merge tried for 35 meshes (the shipped ones, the
  // peers' table, bunny00 and refined_elephant subdivided once), 21,491
  // unions, the convexity after ARAP was within 0.01 of the glued one for
  // the large unions, and of the 3,630 unions under 0.97 of their bound, 2
  // (22 faces in all) met the bound; the others took 38 % of the faces
  // parameterized by merges.
  bool glued_too_concave(const Chart& c, const Chart_uv& start) const
  {
    return too_concave(c, start, glued_convexity_margin);
  }
  static constexpr double glued_convexity_margin = 0.97;

  // Whether the ARAP iterations of a chart may end early (see
  // Arap_early_look): when the iterate meets the bound with its mean
  // distortions at most early_accepted_excess of their bounds, or when a
  // mean distortion or the 95th percentile of s1/s2 exceeds its bound more
  // than 1 / early_margin times. Traced on the 4,668 charts parameterized
  // for the 10 meshes of the peers' table (descent, splits, merges,
  // reroutes): of the 2,791 that met the bound after 10 iterations, 2,134
  // met it after 2 within 0.7 of the means' bounds and 8 were that far over
  // it; of the 1,877 that did not, 1,078 were that far over it after 2 and
  // 16 met it. A chart accepted early keeps a map a little less converged
  // (mean distortions about 5 % higher), which leaves less room to merge it
  // with its neighbors: accepting at the bound itself gave 6 % more charts
  // on those meshes, at 0.7 of it 2 %.
  //
  // A good enough chart meets the bound and a hopeless one does not (both
  // its mean excess and its 95th percentile say so), so the judgement
  // stands for the chart's test above; its measure is excess(d).
  Early_judgement early_verdict(const Chart& c, const Chart_uv& uv) const
  {
    const Chart_distortion d = chart_distortion(m, c, uv);
    Early_judgement j;
    j.measure = excess(d);
    if(j.measure <= early_accepted_excess && !breaks_bound(c, uv, d))
      j.verdict = Early_verdict::good_enough;
    else if(j.measure * early_margin > 1. || (d.stretch_p95 - 1.) * early_margin > bound.max_stretch_p95 - 1.)
      j.verdict = Early_verdict::hopeless;
    return j;
  }

  // The early look of ARAP under this rule: none without a bound or
  // without the fallback (every chart is then kept as it comes).
  Arap_early_look early_look() const
  {
    if(!use_fallback || bound.is_unbounded())
      return Arap_early_look();
    return [this](const Chart& c, const Chart_uv& uv) { return early_verdict(c, uv); };
  }
  static constexpr double early_accepted_excess = 0.7;
  static constexpr double early_margin = 0.7;

  // How far a chart is over the bounds on the means, per unit of 3D area
  // (0 when it is within them), from its excess() and 3D area. Distortion
  // grows about linearly with the area of a chart on a smooth surface, so
  // a piece of a rejected chart is predicted to have this density times
  // its own area.
  static double excess_density(double excess, double area)
  {
    if(!(area > 0))
      return 0;
    return excess > 1 ? excess / area : 0.;
  }

  // The larger of a chart's two mean distortions over their bounds (0 for
  // an infinite bound; above 1: over the bound).
  double excess(const Chart_distortion& d) const
  {
    const double e = (std::max)(std::isfinite(bound.max_angle_distortion) ? d.angle / bound.max_angle_distortion : 0.,
                                std::isfinite(bound.max_area_distortion) ? d.area / bound.max_area_distortion : 0.);
    return std::isfinite(e) ? e : std::numeric_limits<double>::infinity();
  }

  double excess(const Chart& c) const { return excess(chart_distortion(m, c)); }

  // Whether a region is not worth parameterizing: its predicted excess is
  // so far over the bound that it is split at once. Only a prediction: it
  // saves time (large regions are parameterized once rather than at every
  // level) and never lets a chart over the bound through.
  // Small regions are always tried: developable pieces (a cylinder beside
  // a sharp corner) break the linear prediction, and they are cheap.
  bool predicted_over_bound(double density, double area, std::size_t faces) const
  {
    return faces >= smallest_predicted_region && density * area > prediction_margin;
  }

  // Whether a region holds so much Gaussian curvature, in all or spread
  // over it (see Interior_curvature), that its chart would break the bound:
  // it is split without being parameterized. Only a prediction, like
  // predicted_over_bound(), made before any ancestor was measured; it
  // spares the largest solves (the whole patches at the top of the tree).
  bool predicted_too_curved(const std::vector<Index>& faces) const
  {
    if(curvature == nullptr || faces.size() < smallest_predicted_region)
      return false;
    const double limit = curvature_limit();
    const Interior_curvature::Totals held = curvature->totals(m, faces);
    return std::abs(held.signed_total) > limit || held.spread > spread_factor * limit;
  }

  // The curvature spread over a region (Interior_curvature::Totals) is
  // held to twice the limit on its signed total: 8 steradians at the
  // default bounds. Measured on the 634 candidates of at least 64 faces
  // that the descent parameterized on 35 meshes (the 23 shipped, the
  // peers' 10, bunny00 and refined_elephant subdivided once): the accepted
  // ones spread at most 5.7 (nefertiti, 307 faces); above 8, 81 were all
  // rejected, 56 % of the faces the descent parameterized and rejected
  // (refined_elephant x4: 338k of the 521k faces it parameterized; those
  // candidates were 7-23 times over the bound).
  static constexpr double spread_factor = 2.;

  // 4 steradians (a third of a sphere) at the default bounds on the means,
  // in proportion to the looser of the two otherwise. Measured on the
  // 712 candidates of at least 64 faces that the descent parameterized on
  // 33 meshes (the shipped ones and the peers' table): the 87 above 4 were
  // all rejected, 40 % of the faces parameterized; the accepted ones held
  // at most 3.4.
  double curvature_limit() const
  {
    const Distortion_bound defaults;
    double looser = 0.;
    if(std::isfinite(bound.max_angle_distortion))
      looser = (std::max)(looser, bound.max_angle_distortion / defaults.max_angle_distortion);
    if(std::isfinite(bound.max_area_distortion))
      looser = (std::max)(looser, bound.max_area_distortion / defaults.max_area_distortion);
    return looser > 0. ? 4. * looser : std::numeric_limits<double>::infinity();
  }

  // Measured on 10 meshes of CGAL's data (see the benchmark README): with
  // margin 4 the prediction halves the time for 1% more charts (margin 2:
  // 11% more charts; 1.5x faster than margin 4 only on the largest mesh).
  static constexpr double prediction_margin = 4.;
  static constexpr std::size_t smallest_predicted_region = 64;
};


// One chart to try: a node of the merge tree, or a whole patch when there is
// no tree. `path` (the child indices from the patch's root) orders the
// charts of a patch the same way whatever the schedule.
struct Chart_candidate
{
  std::size_t patch;
  std::size_t node;  // Merge_tree node, or no_node
  std::vector<std::size_t> path;
  double excess_density;  // of the nearest parameterized ancestor (see Split_rule)
  Parent_chart parent;    // the nearest valid parameterized ancestor, if any
  static constexpr std::size_t no_node = std::size_t(-1);
};

// A task of the top-down choice (see parameterize_indexed_patches()): a
// candidate of the merge tree (or a whole patch), or, `in_split`, a region
// of the split below the rejected leaf `candidate`.
struct Descent_task
{
  Chart_candidate candidate;
  bool in_split;
  Split_task region;
};

// Where a kept chart comes in the merges' order: the charts the tree gave,
// level by level (tree depth, then patch and path), then the pieces of the
// splits, by the depth, patch and path of their leaf and then in the order
// of a recursion (their path, which extends the leaf's).
struct Found_chart
{
  bool in_split;
  std::size_t depth;  // of the tree candidate the chart comes from
  Kept_chart kept;

  bool operator<(const Found_chart& o) const
  {
    return std::tie(in_split, depth, kept.patch, kept.path) < std::tie(o.in_split, o.depth, o.kept.patch, o.kept.path);
  }
};

// Faces of every node's leaves, gathered from the tree (or the patches).
class Candidate_faces
{
public:
  Candidate_faces(const Merge_tree* tree, const std::vector<std::vector<Index> >& patch_faces)
    : tree_(tree), patch_faces_(patch_faces)
  {
    if(tree_ == nullptr)
      return;
    leaf_faces_.resize(tree_->number_of_leaves);
    for(Index f = 0; f < tree_->face_leaves.size(); ++f)
      leaf_faces_[tree_->face_leaves[f]].push_back(f);
  }

  std::vector<Index> operator()(const Chart_candidate& c) const
  {
    if(c.node == Chart_candidate::no_node)
      return patch_faces_[c.patch];
    std::vector<Index> faces;
    // Ends: every internal node has two children of smaller id.
    std::vector<std::size_t> stack(1, c.node);
    while(!stack.empty())
    {
      const std::size_t n = stack.back();
      stack.pop_back();
      if(tree_->is_leaf(n))
        faces.insert(faces.end(), leaf_faces_[n].begin(), leaf_faces_[n].end());
      else
        for(std::size_t child : tree_->children(n))
          stack.push_back(child);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
  }

private:
  const Merge_tree* tree_;
  const std::vector<std::vector<Index> >& patch_faces_;
  std::vector<std::vector<Index> > leaf_faces_;
};

// The root of every patch in `tree`, after checking that the tree's roots
// are exactly the patches.
inline std::vector<std::size_t> patch_roots(const Indexed_triangle_mesh& m, const Merge_tree& tree,
                                            const std::vector<std::size_t>& face_patches, std::size_t number_of_patches)
{
  if(tree.face_leaves.size() != face_patches.size())
    throw Input_error("merge_tree: it has " + std::to_string(tree.face_leaves.size()) + " faces, the mesh " +
                      std::to_string(face_patches.size()));
  for(const auto& children : tree.merges)
    for(std::size_t i = 0; i < 2; ++i)
      if(children[i] >= tree.number_of_nodes())
        throw Input_error("merge_tree: a merge names node " + std::to_string(children[i]) + " which does not exist");
  for(std::size_t i = 0; i < tree.merges.size(); ++i)
    if(tree.merges[i][0] >= tree.number_of_leaves + i || tree.merges[i][1] >= tree.number_of_leaves + i ||
       tree.merges[i][0] == tree.merges[i][1])
      throw Input_error("merge_tree: merge " + std::to_string(i) + " does not join two earlier nodes");
  const std::vector<std::size_t> parent = tree.parents();
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> root_of_patch(number_of_patches, none), patch_of_root(tree.number_of_nodes(), none);
  for(std::size_t f = 0; f < face_patches.size(); ++f)
  {
    if(tree.face_leaves[f] >= tree.number_of_leaves)
      throw Input_error("merge_tree: face #" + std::to_string(m.input_position(Index(f))) + " has no leaf");
    const std::size_t root = tree.root_of_leaf(tree.face_leaves[f], parent);
    const std::size_t p = face_patches[f];
    if(root_of_patch[p] == none && patch_of_root[root] == none)
    {
      root_of_patch[p] = root;
      patch_of_root[root] = p;
    }
    else if(root_of_patch[p] != root || patch_of_root[root] != p)
      throw Input_error("merge_tree: its roots are not the patches of face_patch_map (face #" +
                        std::to_string(m.input_position(Index(f))) + ")");
  }
  return root_of_patch;
}

} // namespace internal

namespace internal {

// `tm` as an indexed mesh, with its face and vertex descriptors in index
// order: built once by uv_atlas() for both the segmentation and the
// parameterization.
template <typename TriangleMesh>
struct Indexed_input
{
  Indexed_triangle_mesh mesh;
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> face_handles;
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vertex_handles;

  template <typename NamedParameters>
  Indexed_input(const TriangleMesh& tm, const NamedParameters& np)
  {
    build_indexed_triangle_mesh(tm, np, mesh, face_handles, &vertex_handles);
  }
};

// parameterize_patches() on `tm` already indexed (`input`), with its
// parameters read (`settings`, `progress`) and the merge tree given apart,
// so that uv_atlas() can pass its own whatever the type of its parameters,
// and run it again with other settings without another instantiation.
template <typename TriangleMesh, typename FacePatchMap, typename UVMap>
Parameterization_report parameterize_indexed_patches(const TriangleMesh& tm, const Indexed_input<TriangleMesh>& input,
                                                     FacePatchMap face_patch_map, UVMap uv_map,
                                                     const Parameterization_settings& settings,
                                                     internal::Progress& progress, const Merge_tree* tree)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<UVMap>::value_type UV;
  using internal::Index;

  const Parameterization_method method = settings.method;
  const bool use_fallback = settings.use_fallback;
  const unsigned int threads = settings.threads;
  const auto for_each = [&](std::size_t n, const auto& work) { internal::for_each_index(n, threads, work); };
  const bool require_disks = settings.require_disks;

  const internal::Indexed_triangle_mesh& m = input.mesh;
  const auto& face_handles = input.face_handles;
  const auto& vertex_handles = input.vertex_handles;

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

  // Charts are chosen top-down: every candidate is parameterized; one that
  // is invalid or exceeds the bound is replaced by its two children in the
  // merge tree, and a rejected leaf (or patch, without a tree) is split by
  // Voronoi cells (see Split_rule). Candidates do not depend on each other,
  // so each is a task that runs as soon as a thread is free, and the
  // charts, ordered by their place in the tree at the end, do not depend
  // on the schedule.
  std::vector<internal::Descent_task> roots;
  {
    std::vector<std::size_t> tree_roots;
    if(tree != nullptr)
      tree_roots = internal::patch_roots(m, *tree, ids, number_of_patches);
    for(std::size_t p : internal::largest_first(number_of_patches, [&](std::size_t q) { return patch_faces[q].size(); }))
      roots.push_back(internal::Descent_task{
        internal::Chart_candidate{ p, tree != nullptr ? tree_roots[p] : internal::Chart_candidate::no_node,
                                   std::vector<std::size_t>(), 0. },
        false, internal::Split_task() });
  }
  const internal::Candidate_faces candidate_faces(tree, patch_faces);
  const internal::Border_smoother smoother(m);
  const bool bounded = use_fallback && !settings.bound.is_unbounded();
  std::unique_ptr<internal::Interior_curvature> curvature;
  if(bounded)
    curvature.reset(new internal::Interior_curvature(m));
  const internal::Split_rule needs_split{ m, settings.bound, settings.max_chart_faces, use_fallback,
                                          settings.smooth_borders ? &smoother : nullptr, curvature.get(),
                                          m.total_common_area() };
  internal::Per_thread_splitter splitter(m);
  const internal::Arap_early_look early_look = needs_split.early_look();

  // Why the requested method's chart of each patch as a whole was rejected.
  std::vector<std::string> patch_problem(number_of_patches);
  // Regions rejected, parameterized or predicted over the bound (see
  // region_key()).
  std::unordered_set<std::uint64_t> rejected_regions;
  std::vector<internal::Found_chart> found;
  std::mutex found_mutex;
  auto keep = [&](const internal::Chart_candidate& c, bool in_split, std::vector<std::size_t> path,
                  internal::Chart&& chart, const internal::Chart_outcome& outcome) {
    internal::Found_chart chart_found{ in_split, c.path.size(),
                                       internal::Kept_chart{ c.patch, std::move(path), std::move(chart), outcome } };
    std::lock_guard<std::mutex> lock(found_mutex);
    found.push_back(std::move(chart_found));
  };
  auto reject = [&](std::uint64_t key) {
    std::lock_guard<std::mutex> lock(found_mutex);
    rejected_regions.insert(key);
  };
  auto try_candidate = [&](internal::Chart_candidate& c, const auto& add) {
    const std::vector<Index> faces = candidate_faces(c);
    internal::Chart chart;
    internal::Chart_outcome outcome;
    const internal::Region_trial trial =
      internal::try_region(m, splitter.local(), faces, method, use_fallback, needs_split, early_look,
                           c.excess_density, c.parent, chart, outcome);
    if(c.path.empty())
      patch_problem[c.patch] = outcome.problem;  // one task per patch writes it
    if(trial == internal::Region_trial::kept)
    {
      keep(c, false, c.path, std::move(chart), outcome);
      progress.step("parameterization", number_of_patches);
      return;
    }
    // A region predicted too curved may still be rebuilt by a merge: the
    // prediction, unlike a parameterization, can be wrong.
    if(trial != internal::Region_trial::predicted_curved)
      reject(internal::region_key(faces));
    if(c.node != internal::Chart_candidate::no_node && !tree->is_leaf(c.node))
      for(std::size_t j = 0; j < 2; ++j)
      {
        internal::Chart_candidate child{ c.patch, tree->children(c.node)[j], c.path, c.excess_density, c.parent };
        child.path.push_back(j);
        add(internal::Descent_task{ std::move(child), false, internal::Split_task() });
      }
    else if(faces.size() > 1)
      add(internal::Descent_task{ c, true, internal::Split_task{ faces, c.excess_density, true, c.parent, c.path } });
  };
  internal::for_each_growing(std::move(roots), threads, [&](internal::Descent_task& task, const auto& add) {
    if(!task.in_split)
    {
      try_candidate(task.candidate, add);
      return;
    }
    internal::split_step(
      m, splitter.local(), task.region, method, use_fallback, needs_split, early_look,
      [&](internal::Split_task&& part) { add(internal::Descent_task{ task.candidate, true, std::move(part) }); },
      [&](std::vector<std::size_t> path, internal::Chart&& c, const internal::Chart_outcome& outcome) {
        keep(task.candidate, true, std::move(path), std::move(c), outcome);
      },
      reject);
  });
  std::sort(found.begin(), found.end());
  std::vector<internal::Kept_chart> kept;
  kept.reserve(found.size());
  for(internal::Found_chart& f : found)
  {
    f.kept.outcome.problem = patch_problem[f.kept.patch];
    kept.push_back(std::move(f.kept));
  }
  found.clear();
  if(bounded && settings.merge_charts)
    internal::merge_kept_charts(m, topology, kept, needs_split, method, use_fallback, for_each, rejected_regions);
  if(bounded && settings.straighten_borders)
    internal::reroute_kept_charts(m, topology, kept, needs_split, method, use_fallback, for_each);
  Parameterization_report report;
  if(kept.size() > settings.max_charts)
  {
    // The budget wins over the bound, never over validity or max_chart_faces.
    report.charts_before_budget = kept.size();
    internal::merge_kept_charts(m, topology, kept, needs_split, method, use_fallback, for_each, rejected_regions,
                                settings.max_charts);
    report.chart_budget_met = kept.size() <= settings.max_charts;
  }
  progress("parameterization", number_of_patches, number_of_patches);

  // Each patch's charts in tree order; the first keeps the patch's id if
  // it is below the number of charts, the other charts fill the remaining
  // ids in that order, so that ids stay contiguous (merging may leave a
  // patch without a chart of its own).
  std::sort(kept.begin(), kept.end(), [](const internal::Kept_chart& a, const internal::Kept_chart& b) {
    return a.patch != b.patch ? a.patch < b.patch : a.path < b.path;
  });
  const std::size_t number_of_charts = kept.size();
  std::vector<internal::Chart> charts(number_of_charts);
  std::vector<internal::Chart_outcome> outcomes(number_of_charts);
  {
    std::vector<char> filled(number_of_charts, 0), first_of_patch(number_of_patches, 1);
    std::vector<std::size_t> others;
    for(std::size_t k = 0; k < kept.size(); ++k)
    {
      const std::size_t p = kept[k].patch;
      if(first_of_patch[p] && p < number_of_charts)
      {
        charts[p] = std::move(kept[k].chart);
        outcomes[p] = kept[k].outcome;
        filled[p] = 1;
      }
      else
        others.push_back(k);
      first_of_patch[p] = 0;
    }
    std::size_t next = 0;
    for(std::size_t k : others)
    {
      while(filled[next])
        ++next;
      charts[next] = std::move(kept[k].chart);
      outcomes[next] = kept[k].outcome;
      filled[next] = 1;
    }
  }
  // Whether a chart is exactly the faces of one patch.
  auto is_whole_patch = [&](const internal::Chart& c) {
    const std::size_t p = ids[c.faces.front()];
    if(c.faces.size() != patch_faces[p].size())
      return false;
    for(Index f : c.faces)
      if(ids[f] != p)
        return false;
    return true;
  };
  {
    std::vector<char> whole(number_of_patches, 0);
    for(const internal::Chart& c : charts)
      if(is_whole_patch(c))
        whole[ids[c.faces.front()]] = 1;
    for(std::size_t p = 0; p < number_of_patches; ++p)
      report.number_of_split_patches += whole[p] ? 0 : 1;
  }
  // Measured in parallel: distortion is most of the work of this loop,
  // whose writes to the user's maps stay on one thread.
  std::vector<internal::Chart_distortion> distortion(charts.size());
  internal::for_each_largest_first(for_each, charts.size(), [&](std::size_t p) { return charts[p].faces.size(); },
                                   [&](std::size_t p) { distortion[p] = internal::chart_distortion(m, charts[p]); });
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
    r.split = !is_whole_patch(c);
    r.valid = outcomes[p].valid;
    r.method_error = outcomes[p].method_error;
    r.problem = outcomes[p].problem;
    const internal::Chart_distortion& d = distortion[p];
    r.angle_distortion = d.angle;
    r.area_distortion = d.area;
    r.max_stretch = d.max_stretch;
    r.min_area_scale = d.min_area_scale;
    r.max_area_scale = d.max_area_scale;
    r.stretch_p95 = d.stretch_p95;
    report.number_of_fallbacks += r.fallback ? 1 : 0;
    report.number_of_invalid_charts += r.valid ? 0 : 1;
    report.number_of_method_errors += r.method_error ? 1 : 0;

    // The corner of face f whose target is indexed vertex v gets uv[local v].
    for(std::size_t t = 0; t < c.faces.size(); ++t)
    {
      const Index f = c.faces[t];
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
/// ids in `face_patch_map` (the first chart of a patch keeps the patch's id
/// where it can; ids stay contiguous, `0` to the number of charts minus
/// one). Valid
/// charts that exceed the distortion bound (`Distortion_bound`; the paper
/// has none) are replaced the same way: with a `merge_tree`, a patch is
/// first replaced by the two disks it was merged from, recursively down to
/// the tree's leaves, which are then split; candidates are parameterized
/// in parallel, each as soon as its parent is rejected. Under a finite bound, a chart of more
/// than one triangle whose map is invalid is replaced the same way at once,
/// without the other methods (a map redone on a circle rarely meets the
/// bound, and it was a third of the time on meshes with such charts).
/// Patches with more than
/// `max_chart_faces` faces are split the same way before they are
/// parameterized, with or without the fallback.
///
/// A chart budget (`max_number_of_charts`, UVAtlas's maxChartNumber; not in
/// the paper) is applied last: when the charts chosen above are more than
/// the budget, adjacent charts whose union is a disk are merged, and a
/// union is kept when its map is valid, whatever its distortion, until the
/// budget is met. Pairs are solved in the order of the growth of the
/// area-weighted sum of excesses over the bound that their own excesses
/// predict; of each round's solved unions, those whose measured growth is
/// least are kept. So validity and `max_chart_faces`
/// win over the budget, and the budget wins over the distortion bound; the
/// report says when the budget could not be met (`chart_budget_met`) and
/// how many charts the bound alone gave. Without a budget, or when the
/// bound gives no more charts than the budget, nothing changes.
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
/// @tparam NamedParameters a sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters"
///
/// @param tm a triangle mesh, manifold, without garbage
/// @param face_patch_map the patches, each a topological disk (see `segment_into_disks()`)
/// @param uv_map receives the UVs
/// @param np an optional sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters" among the ones listed below
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
///   \cgalParamNBegin{distortion_bound}
///     \cgalParamDescription{the distortion every chart of two faces or more must meet, and the
///       convexity of the large ones (only with `use_fallback`); a single triangle is laid out
///       isometrically}
///     \cgalParamType{`Distortion_bound`}
///     \cgalParamDefault{`Distortion_bound()`; `Distortion_bound::unbounded()` keeps the paper's charts}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_angle_distortion, max_area_distortion, max_stretch, max_area_scale, max_stretch_p95, min_convexity}
///     \cgalParamDescription{override one field of `distortion_bound`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{the field of `distortion_bound`}
///   \cgalParamNEnd
///   \cgalParamNBegin{smooth_borders}
///     \cgalParamDescription{whether the borders between the pieces of a split patch lose their saw
///       teeth (see `segment_into_disks()`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{merge_charts}
///     \cgalParamDescription{whether adjacent charts are merged, once chosen, when their union is a disk
///       that meets the bound (only with `use_fallback` and a bound); merged charts may join pieces of
///       different patches}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{straighten_borders}
///     \cgalParamDescription{whether, once the charts are chosen and merged, each border arc between
///       two of them (from one junction to the next) is replaced by a shorter edge path near it that
///       prefers creases, the faces in between changing sides; the changed charts are parameterized
///       again, and an arc is given back wherever a chart stops being a disk or meeting the bound
///       (only with `use_fallback` and a bound). Not in the paper.}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{merge_tree}
///     \cgalParamDescription{the merges that made the patches (filled by `segment_into_disks()`); charts
///       over the bound are replaced by their children in it before they are split by Voronoi cells}
///     \cgalParamType{`Merge_tree*`}
///     \cgalParamDefault{`nullptr`: over-bound patches are split by Voronoi cells at once}
///     \cgalParamExtra{its roots must be the patches of `face_patch_map`, else `Input_error`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_chart_faces}
///     \cgalParamDescription{patches with more faces are split (recursively, in two) before they are
///       parameterized, which bounds the memory of each chart's linear systems}
///     \cgalParamType{`std::size_t`, at least 1}
///     \cgalParamDefault{`default_max_chart_faces` (\f$ 2^{17} = 131072 \f$)}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_number_of_charts}
///     \cgalParamDescription{the chart budget: charts over it are merged past the distortion bound
///       (see above)}
///     \cgalParamType{`std::size_t`, at least 1}
///     \cgalParamDefault{no budget}
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
///     \cgalParamDescription{called with `("parameterization", charts done, charts)` after each chart;
///       a `false` result stops the work with `Cancelled`, the maps untouched (see \ref DS_Errors)}
///     \cgalParamType{a callable of `(const std::string&, std::size_t, std::size_t)` returning `bool` or `void`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key type and the traits' `Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class, used only to read coordinates: they are converted with `CGAL::to_double()` and all computation runs in `double` whatever the kernel}
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
///
/// Complexity, for `F` faces and `V` vertices, with `M` the smaller of `F`
/// and `max_chart_faces`: expected \f$ O(F + V) \f$ time to read the mesh and
/// test the patches. A chart of `m` faces is parameterized in expected
/// \f$ O(m^{3/2}) \f$ time and \f$ O(m \log m) \f$ memory, the usual bounds of
/// the sparse factorization of its Laplacian with a fill-reducing ordering
/// (ARAP's ten iterations reuse one factorization; each fallback method adds
/// one), and validated in \f$ O(m \log m) \f$ time. The candidates of one
/// level of the merge tree, or of the Voronoi splits below it, are disjoint,
/// so a level costs expected \f$ O(F (\sqrt{M} + \log F)) \f$ time; there are
/// as many levels as the tree is high plus the depth of the splits (one
/// level when every patch meets the bound), and each round of chart merging
/// costs at most as much as a level. Memory: \f$ O(F + V) \f$ per thread,
/// plus the UVs of the parameterized ancestors that candidates reuse
/// (\f$ O(F) \f$ per level) and one factorization per thread (expected
/// \f$ O(M \log M) \f$).
template <typename TriangleMesh, typename FacePatchMap, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
Parameterization_report parameterize_patches(const TriangleMesh& tm,
                                             FacePatchMap face_patch_map,
                                             UVMap uv_map,
                                             const NamedParameters& np = parameters::default_values())
{
  static_assert(internal::Check_patch_map<FacePatchMap>::value, "");
  static_assert(internal::Check_named_parameters<NamedParameters>::value, "");
  // The mesh is read through a chain of its maps only: one instantiation for
  // any chain of values.
  const internal::Indexed_input<TriangleMesh> input(tm, internal::forward_mesh_parameters(np, parameters::default_values()));
  const Merge_tree* given = internal::merge_tree_parameter(np);
  Merge_tree tree;
  if(given != nullptr)
    tree = internal::face_leaves_to_mesh_order(input.mesh, *given);
  internal::Progress progress = internal::Progress::from(np);
  return internal::parameterize_indexed_patches(tm, input, internal::checked_patch_map<TriangleMesh>(face_patch_map),
                                                internal::checked_uv_map<TriangleMesh>(uv_map),
                                                internal::parameterization_settings(np), progress,
                                                given != nullptr ? &tree : nullptr);
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_PARAMETERIZE_PATCHES_H
