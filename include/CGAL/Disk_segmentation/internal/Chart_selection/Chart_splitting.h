// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Splits a chart that breaks the bound into Voronoi pieces, reusing its
// parent's UVs; Split_rule says which charts are split.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_SPLITTING_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_SPLITTING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Distortion_bound.h>
#include <CGAL/Disk_segmentation/Parameterization_method.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Chart_choice.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Chart_merging.h>
#include <CGAL/Disk_segmentation/internal/Execution/parallel.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_slots.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_topology.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Bound_test.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_convexity.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_distortion.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_method_chain.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_parameterization.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_restriction.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_warm_start.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Inherited_elimination_order.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Border_smoother.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Region_curvature.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Region_refinement.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Voronoi_fps.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/enumerable_thread_specific.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

inline double region_area(const Indexed_triangle_mesh& m, const std::vector<Index>& faces)
{
  double area = 0;
  for(Index f : faces)
    area += m.area(f);
  return area;
}

// What splitting a chart needs: farthest-point sampling and the disk test,
// with scratch sized to the region at hand (one splitter per thread).
struct Splitter
{
  explicit Splitter(const Indexed_triangle_mesh& m) : fps(m), topology(m), labels(no_index) {}
  Voronoi_fps fps;
  Region_topology topology;
  Region_values<Index> labels;  // of a region's faces (a model of Border_smoother's Labels)
  Region_slots parent_vertices;  // scratch of restrict_chart()
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
  if(!parent || c.faces.size() < 2 || !restrict_chart(parent->first, c, splitter.parent_vertices).empty())
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
  splitter.labels.clear_for_keys(faces);
  for(Index i = 0; i < parts.size(); ++i)
    for(Index f : parts[i])
      splitter.labels.set(f, i);
  if(smoother.smooth_labels(splitter.labels, faces) > 0)
  {
    for(std::vector<Index>& part : parts)
      part.clear();
    for(Index f : faces)
      parts[splitter.labels.at(f)].push_back(f);
  }
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
Region_trial try_region(const Chart_choice<NeedsSplit>& choice, Splitter& splitter, const std::vector<Index>& faces,
                        double& excess_density, Parent_chart& parent, Chart& chart, Chart_outcome& outcome)
{
  const Indexed_triangle_mesh& m = choice.mesh;
  const NeedsSplit& needs_split = choice.needs_split;
  const double area = region_area(m, faces);
  if(needs_split.too_large(faces.size()) || needs_split.predicted_over_bound(excess_density, area, faces.size()))
    return Region_trial::too_large;
  if(needs_split.predicted_too_curved(faces))
    return Region_trial::predicted_curved;
  chart = make_chart(m, faces);
  if(accept_restriction(parent, chart, outcome, splitter, needs_split))
    return Region_trial::kept;
  if(parent && has_elimination_order(parent->first))
    inherit_restricted_order(parent->first, chart);
  Early_look look{ &choice.early_look, Early_judgement() };
  outcome = choice.solve(chart, needs_split.on_invalid_map(), &look);
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
void split_step(const Chart_choice<NeedsSplit>& choice, Splitter& splitter, Split_task& task, const Add& add,
                const Keep& keep, const Reject& reject)
{
  const Indexed_triangle_mesh& m = choice.mesh;
  const NeedsSplit& needs_split = choice.needs_split;
  if(!task.split)
  {
    Chart c;
    Chart_outcome outcome;
    const Region_trial trial = try_region(choice, splitter, task.faces, task.excess_density, task.parent, c, outcome);
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
      const Chart_outcome outcome = choice.solve(c, On_invalid_map::redo, nullptr);
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
  for(std::size_t k = 0; k < task.faces.size(); ++k)
    cells[splitter.fps.cells()[k]].push_back(task.faces[k]);
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
void split_and_parameterize(const Chart_choice<NeedsSplit>& choice, Splitter& splitter, const std::vector<Index>& faces,
                            std::vector<Chart>& pieces, std::vector<Chart_outcome>& outcomes,
                            std::vector<std::uint64_t>& rejected, double excess_density = 0,
                            Parent_chart parent = Parent_chart())
{
  if(faces.size() < 2)
    return;
  std::vector<Split_task> tasks;
  tasks.push_back(Split_task{ faces, excess_density, true, std::move(parent), std::vector<std::size_t>() });
  for_each_growing(std::move(tasks), 1, [&](Split_task& task, const auto& add) {
    split_step(choice, splitter, task, add,
               [&](std::vector<std::size_t>, Chart&& c, const Chart_outcome& outcome) {
                 pieces.push_back(std::move(c));
                 outcomes.push_back(outcome);
               },
               [&](std::uint64_t key) { rejected.push_back(key); });
  });
}

// One Splitter per thread (the disk test and the labels keep per-query
// scratch state the size of the mesh; the sampler's is the size of the
// region), made on first use.
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
// when it has more than `max_chart_faces` faces; after, when it exceeds the
// distortion bound, or when it is invalid and the fallback is on (without
// it, an invalid chart is kept and reported).
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

  // The bound's judge (see Bound_test): this rule reads no field of `bound`.
  Bound_test test() const { return Bound_test(bound); }

  // Under a bound, an invalid chart is replaced like one over the bound,
  // without the other starts and fallback methods: a chart whose first
  // start folds is large or twisted, and redone from a circle it rarely
  // meets the bound. Measured on 33 meshes (benchmark README): 36 % less
  // time, 0.8 % more charts.
  On_invalid_map on_invalid_map() const
  {
    return use_fallback && !test().bounds_nothing() ? On_invalid_map::report : On_invalid_map::redo;
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
    if(!outcome.valid)
      return use_fallback;
    if(test().bounds_nothing())
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
    return !test().meets_distortion(d) || too_concave(c, uv);
  }

  bool too_concave(const Chart& c, const Chart_uv& uv, double margin = 1.) const
  {
    if(!test().bounds_convexity())
      return false;
    double area = 0.;
    for(Index f : c.faces)
      area += m.common_area(f);
    return test().too_concave(chart_convexity(c, uv), area / total_area, margin);
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
    else if(j.measure * early_margin > 1. || test().p95_far_over(d, early_margin))
      j.verdict = Early_verdict::hopeless;
    return j;
  }

  // The early look of ARAP under this rule: none without a bound or
  // without the fallback (every chart is then kept as it comes).
  Arap_early_look early_look() const
  {
    if(test().bounds_nothing())
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
  double excess(const Chart_distortion& d) const { return test().mean_excess(d); }

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
    const double looser = test().looseness_of_means();
    return looser > 0. ? 4. * looser : std::numeric_limits<double>::infinity();
  }

  // Measured on 10 meshes of CGAL's data (see the benchmark README): with
  // margin 4 the prediction halves the time for 1% more charts (margin 2:
  // 11% more charts; 1.5x faster than margin 4 only on the largest mesh).
  static constexpr double prediction_margin = 4.;
  static constexpr std::size_t smallest_predicted_region = 64;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_SPLITTING_H
