// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Merges adjacent kept charts whose union is a disk and still meets the
// bound, by the merge score of the segmentation.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_MERGING_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_MERGING_H

#include <CGAL/Disk_segmentation/internal/Chart_selection/Chart_choice.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Parameterization_settings.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_distortion.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_parameterization.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_warm_start.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Inherited_elimination_order.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_topology.h>
#include <CGAL/Disk_segmentation/internal/Execution/parallel.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <tuple>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// A chart kept by the top-down choice: its patch and path in the merge
// tree order the charts (see parameterize_indexed_patches()).
struct Kept_chart
{
  std::size_t patch;
  std::vector<std::size_t> path;
  Chart chart;
  Chart_outcome outcome;
  bool alive = true;
};

// Merges adjacent kept charts whose union is a disk and, parameterized,
// still meets the bound: the descent and the Voronoi splits stop at the
// first level that meets it, so two pieces of different parents can often
// be one chart. Pairs go by the merge score of the segmentation (shared
// border over the square root of the larger area: the most seam removed
// for the size first). A pair is tried only if the sum of the two charts'
// excesses (mean distortion over its bound, see Split_rule) is at most
// `largest_excess_sum`: distortion adds up about linearly with area, but a
// union re-parameterized as a whole often does better than the sum; the
// others would almost never meet the bound and cost a parameterization each.
//
// Rounds: each takes the best untried pairs, no chart twice, tests them in
// parallel (`for_each`) and applies the successes in order, so the result
// does not depend on the schedule.
// Measured on 10 meshes of CGAL's data set (medians; time summed): at 1,
// 34 charts, cut length 15.3, 6.3 s; at 1.15, 30 charts, cut 14.2, 7.3 s;
// at 1.3, 25.5 charts, cut 12.8, 9.5 s, but UV area 0.52 instead of 0.57.
constexpr double largest_excess_sum = 1.15;

// A key for a set of faces (sorted), so that a union equal to a region the
// top-down choice already parameterized and rejected is not tried again:
// on large meshes such unions were half of the merging time (they are the
// tree nodes above the charts) and almost never met the bound from the
// glued start either. Two sets with one key (a 2^-64 chance per pair)
// would only skip one merge attempt.
inline std::uint64_t region_key(const std::vector<Index>& sorted_faces)
{
  std::uint64_t key = 0xcbf29ce484222325ull ^ sorted_faces.size();
  for(Index f : sorted_faces)
  {
    key = (key ^ f) * 0x100000001b3ull;
    key ^= key >> 29;
  }
  return key;
}

// How much merging charts a and b adds to the area-weighted sum of excesses
// over the bound, if their union's excess is `union_excess`.
inline double excess_growth(double union_excess, std::size_t a, std::size_t b, const std::vector<double>& area,
                            const std::vector<double>& excess)
{
  return union_excess * (area[a] + area[b]) - excess[a] * area[a] - excess[b] * area[b];
}

// Over a chart budget, of the valid unions of a round, keeps the `wanted`
// ones that add least to the area-weighted sum of excesses; the others are
// forgotten as tried, since they failed on rank only.
template <typename Tried>
void keep_least_excess_growth(const std::vector<std::pair<std::size_t, std::size_t> >& round,
                              const std::vector<double>& union_excess, const std::vector<double>& area,
                              const std::vector<double>& excess, std::size_t wanted, std::vector<char>& accepted,
                              std::set<Tried>& tried, const std::vector<std::size_t>& version)
{
  std::vector<std::pair<double, std::size_t> > growth;  // growth, index in the round
  for(std::size_t i = 0; i < round.size(); ++i)
    if(accepted[i])
    {
      const std::size_t a = round[i].first, b = round[i].second;
      const double g = excess_growth(union_excess[i], a, b, area, excess);
      growth.emplace_back(std::isfinite(g) ? g : std::numeric_limits<double>::max(), i);
    }
  std::sort(growth.begin(), growth.end());
  for(std::size_t k = wanted; k < growth.size(); ++k)
  {
    const std::size_t i = growth[k].second, a = round[i].first, b = round[i].second;
    accepted[i] = 0;
    tried.erase(Tried(a, version[a], b, version[b]));
  }
}

// The faces of two charts, sorted.
inline std::vector<Index> union_faces(const std::vector<Index>& fa, const std::vector<Index>& fb)
{
  std::vector<Index> faces;
  faces.reserve(fa.size() + fb.size());
  // Charts mostly list their faces sorted: then a linear merge.
  if(std::is_sorted(fa.begin(), fa.end()) && std::is_sorted(fb.begin(), fb.end()))
    std::merge(fa.begin(), fa.end(), fb.begin(), fb.end(), std::back_inserter(faces));
  else
  {
    faces = fa;
    faces.insert(faces.end(), fb.begin(), fb.end());
    std::sort(faces.begin(), faces.end());
  }
  return faces;
}

// merge_kept_charts(), round by round: which chart every face is in, each
// chart's area and excess, the border lengths charts share, and the pairs
// already tried at their charts' current versions.
template <typename Rule, typename ForEach>
class Kept_chart_merger
{
public:
  Kept_chart_merger(const Chart_choice<Rule>& choice, Region_topology& topology, std::vector<Kept_chart>& kept,
                    const ForEach& for_each, const std::unordered_set<std::uint64_t>& rejected_regions,
                    std::size_t chart_budget)
    : choice_(choice), m_(choice.mesh), rule_(choice.needs_split), topology_(topology), kept_(kept),
      for_each_(for_each), rejected_regions_(rejected_regions), chart_budget_(chart_budget),
      to_budget_(chart_budget != no_chart_budget), n_(kept.size()), label_(m_.number_of_faces(), no_index),
      area_(n_, 0), excess_(n_, 0), version_(n_, 0), shared_(n_), alive_(n_)
  {
    for(std::size_t i = 0; i < n_; ++i)
      for(Index f : kept_[i].chart.faces)
      {
        label_[f] = static_cast<Index>(i);
        area_[i] += m_.area(f);
      }
    for_each_(n_, [&](std::size_t i) { excess_[i] = rule_.excess(kept_[i].chart); });
    for(Index f = 0; f < m_.number_of_faces(); ++f)
      for(int e = 0; e < 3; ++e)
      {
        const Index g = m_.neighbors[f][e];
        if(g == no_index || g < f || label_[f] == no_index || label_[g] == no_index || label_[f] == label_[g])
          continue;
        const double l = m_.edge_length(f, e);
        shared_[label_[f]][label_[g]] += l;
        shared_[label_[g]][label_[f]] += l;
      }
  }

  // Rounds end: every round tries at least one new (pair, versions), a
  // failure is never retried with the same versions, and a success removes
  // a chart (at most n - 1 of them).
  std::size_t run()
  {
    std::size_t merges = 0;
    while(!to_budget_ || alive_ > chart_budget_)
    {
      std::vector<Candidate> candidates = candidate_pairs();
      if(candidates.empty())
        break;
      std::sort(candidates.begin(), candidates.end());
      Round round;
      choose_round(candidates, round);
      if(round.pairs.empty())
        continue;
      solve_round(round);
      if(to_budget_)
        keep_least_excess_growth(round.pairs, round.union_excess, area_, excess_, alive_ - chart_budget_,
                                 round.accepted, tried_, version_);
      for(std::size_t i = 0; i < round.pairs.size(); ++i)
        if(round.accepted[i])
        {
          merge(round.pairs[i].first, round.pairs[i].second, std::move(round.unions[i]), round.outcomes[i],
                round.union_excess[i]);
          ++merges;
        }
    }
    kept_.erase(std::remove_if(kept_.begin(), kept_.end(), [](const Kept_chart& k) { return !k.alive; }),
                kept_.end());
    return merges;
  }

private:
  typedef std::tuple<std::size_t, std::size_t, std::size_t, std::size_t> Tried;  // a, version, b, version
  // (predicted excess of the union, with a budget), -score, a, b
  typedef std::tuple<double, double, std::size_t, std::size_t> Candidate;

  // The pairs of one round and what solving their unions gave.
  struct Round
  {
    std::vector<std::pair<std::size_t, std::size_t> > pairs;
    std::vector<std::vector<Index> > faces;  // the union of each pair, sorted
    std::vector<Chart> unions;
    std::vector<Chart_outcome> outcomes;
    std::vector<char> accepted;
    std::vector<double> union_excess;
  };

  std::vector<Candidate> candidate_pairs() const
  {
    std::vector<Candidate> candidates;
    for(std::size_t a = 0; a < n_; ++a)
      if(kept_[a].alive)
        for(const auto& entry : shared_[a])
        {
          const std::size_t b = entry.first;
          const double predicted = excess_[a] + excess_[b];
          if(b <= a || (!to_budget_ && !(predicted <= largest_excess_sum)) ||
             tried_.count(Tried(a, version_[a], b, version_[b])) ||
             rule_.too_large(kept_[a].chart.faces.size() + kept_[b].chart.faces.size()))
            continue;
          const double larger = (std::max)(area_[a], area_[b]);
          // Over the budget: the predicted growth of the area-weighted sum of excesses.
          const double growth = excess_growth(predicted, a, b, area_, excess_);
          candidates.emplace_back(to_budget_ && std::isfinite(growth) ? growth : 0.,
                                  larger > 0 ? -entry.second / std::sqrt(larger) : 0., a, b);
        }
    return candidates;
  }

  // Disjoint pairs, best first, whose union is a disk worth solving.
  void choose_round(const std::vector<Candidate>& candidates, Round& round)
  {
    std::vector<char> busy(n_, 0);
    for(const Candidate& c : candidates)
    {
      const std::size_t a = std::get<2>(c), b = std::get<3>(c);
      if(busy[a] || busy[b])
        continue;
      // Twice the pairs needed are solved, the best of them by their measured excess are taken.
      if(to_budget_ && round.pairs.size() >= 2 * (alive_ - chart_budget_))
        break;
      tried_.insert(Tried(a, version_[a], b, version_[b]));
      std::vector<Index> faces = union_faces(kept_[a].chart.faces, kept_[b].chart.faces);
      // A union predicted too curved (Split_rule::predicted_too_curved())
      // is not solved: traced on the 17,757 unions solved for 35 meshes,
      // 150 such unions were rejected (18 % of the faces solved) and 17
      // of the 9,731 accepted ones would have been.
      // Over the budget, a union rejected for the bound may still be taken.
      if((!to_budget_ && (rejected_regions_.count(region_key(faces)) != 0 || rule_.predicted_too_curved(faces))) ||
         !topology_.is_disk(faces))
        continue;
      busy[a] = busy[b] = 1;
      round.pairs.emplace_back(a, b);
      round.faces.push_back(std::move(faces));
    }
  }

  void solve_round(Round& round) const
  {
    const std::size_t size = round.pairs.size();
    round.unions.resize(size);
    round.outcomes.resize(size);
    round.accepted.assign(size, 0);
    round.union_excess.assign(size, 0.);
    auto union_size = [&](std::size_t i) { return round.faces[i].size(); };
    for_each_largest_first(for_each_, size, union_size, [&](std::size_t i) {
      Chart& u = round.unions[i];
      Chart_outcome& outcome = round.outcomes[i];
      u = make_chart(m_, round.faces[i]);
      const Chart& a = kept_[round.pairs[i].first].chart;
      const Chart& b = kept_[round.pairs[i].second].chart;
      if(has_elimination_order(a) && has_elimination_order(b))
        inherit_union_order(a, b, u);
      // ARAP from the two maps glued rather than from LSCM: half the time
      // on the merges, the same charts on 10 meshes of CGAL's data.
      const Chart_uv start = glue_chart_maps(a, b, u);
      const Chart_uv* from = start.empty() ? nullptr : &start;
      if(to_budget_)
      {
        // Any valid map will do: the fallbacks are tried, ARAP runs to the end.
        outcome = choice_.solve(u, On_invalid_map::redo, nullptr, from);
        round.accepted[i] = outcome.valid ? 1 : 0;
        if(round.accepted[i] && !rule_.test().bounds_nothing())
          round.union_excess[i] = rule_.excess(u);
        return;
      }
      if(!start.empty() && rule_.glued_too_concave(u, start))
        return;
      Early_look look{ &choice_.early_look, Early_judgement() };
      outcome = choice_.solve(u, rule_.on_invalid_map(), &look, from);
      round.accepted[i] = rule_(u, outcome, round.union_excess[i], look.ended) ? 0 : 1;
    });
  }

  // The union takes the place of the first of the two in chart order.
  void merge(std::size_t a, std::size_t b, Chart&& u, const Chart_outcome& outcome, double union_excess)
  {
    Kept_chart& keep = kept_[a];
    Kept_chart& gone = kept_[b];
    if(std::tie(gone.patch, gone.path) < std::tie(keep.patch, keep.path))
    {
      keep.patch = gone.patch;
      keep.path = gone.path;
    }
    keep.chart = std::move(u);
    keep.outcome.used = outcome.used;
    keep.outcome.fallback = outcome.fallback;
    keep.outcome.valid = true;  // an invalid part (use_fallback(false)) may join a valid union
    gone.alive = false;
    --alive_;
    for(Index f : gone.chart.faces)
      label_[f] = static_cast<Index>(a);
    area_[a] += area_[b];
    excess_[a] = union_excess;
    shared_[a].erase(b);
    for(const auto& entry : shared_[b])
    {
      if(entry.first == a)
        continue;
      shared_[a][entry.first] += entry.second;
      shared_[entry.first].erase(b);
      shared_[entry.first][a] += entry.second;
    }
    shared_[b].clear();
    ++version_[a];
    ++version_[b];
  }

  const Chart_choice<Rule>& choice_;
  const Indexed_triangle_mesh& m_;
  const Rule& rule_;
  Region_topology& topology_;
  std::vector<Kept_chart>& kept_;
  const ForEach& for_each_;
  const std::unordered_set<std::uint64_t>& rejected_regions_;
  const std::size_t chart_budget_;
  const bool to_budget_;
  const std::size_t n_;
  std::vector<Index> label_;
  std::vector<double> area_, excess_;
  std::vector<std::size_t> version_;
  std::vector<std::map<std::size_t, double> > shared_;
  std::set<Tried> tried_;
  std::size_t alive_;
};

// With a `chart_budget` (see max_number_of_charts), merging goes on past
// the bound until at most `chart_budget` charts are left or no union of
// two adjacent charts is a disk with a valid map: a union is accepted when
// its map is valid, whatever its distortion. Pairs are tried by the growth
// of the area-weighted sum of excesses predicted from the parts' excesses,
// then by the merge score; a round solves twice as many pairs as charts are
// over the budget and keeps those whose measured growth is least, at most
// as many as charts are over, so the budget is met exactly when it can be.
template <typename Rule, typename ForEach>
std::size_t merge_kept_charts(const Chart_choice<Rule>& choice, Region_topology& topology, std::vector<Kept_chart>& kept,
                              const ForEach& for_each, const std::unordered_set<std::uint64_t>& rejected_regions,
                              std::size_t chart_budget = no_chart_budget)
{
  return Kept_chart_merger<Rule, ForEach>(choice, topology, kept, for_each, rejected_regions, chart_budget).run();
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_MERGING_H
