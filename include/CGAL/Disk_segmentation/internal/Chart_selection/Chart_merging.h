// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_MERGING_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_MERGING_H

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

// No chart budget: merge_kept_charts() merges only unions that meet the bound.
constexpr std::size_t no_chart_budget = std::size_t(-1);

// With a `chart_budget` (see max_number_of_charts), merging goes on past
// the bound until at most `chart_budget` charts are left or no union of
// two adjacent charts is a disk with a valid map: a union is accepted when
// its map is valid, whatever its distortion. Pairs are tried by the growth
// of the area-weighted sum of excesses predicted from the parts' excesses,
// then by the merge score; a round solves twice as many pairs as charts are
// over the budget and keeps those whose measured growth is least, at most
// as many as charts are over, so the budget is met exactly when it can be.
template <typename Rule, typename ForEach>
std::size_t merge_kept_charts(const Indexed_triangle_mesh& m, Region_topology& topology, std::vector<Kept_chart>& kept,
                              const Rule& rule, Parameterization_method method, bool use_fallback,
                              const ForEach& for_each, const std::unordered_set<std::uint64_t>& rejected_regions,
                              std::size_t chart_budget = no_chart_budget)
{
  const bool to_budget = chart_budget != no_chart_budget;
  const std::size_t n = kept.size();
  std::vector<Index> label(m.number_of_faces(), no_index);
  std::vector<double> area(n, 0), excess(n, 0);
  std::vector<std::size_t> version(n, 0);
  for(std::size_t i = 0; i < n; ++i)
    for(Index f : kept[i].chart.faces)
    {
      label[f] = static_cast<Index>(i);
      area[i] += m.area(f);
    }
  for_each(n, [&](std::size_t i) { excess[i] = rule.excess(kept[i].chart); });
  std::vector<std::map<std::size_t, double> > shared(n);
  for(Index f = 0; f < m.number_of_faces(); ++f)
    for(int e = 0; e < 3; ++e)
    {
      const Index g = m.neighbors[f][e];
      if(g == no_index || g < f || label[f] == no_index || label[g] == no_index || label[f] == label[g])
        continue;
      const double l = m.edge_length(f, e);
      shared[label[f]][label[g]] += l;
      shared[label[g]][label[f]] += l;
    }

  const Arap_early_look early_look = rule.early_look();
  typedef std::tuple<std::size_t, std::size_t, std::size_t, std::size_t> Tried;  // a, version, b, version
  std::set<Tried> tried;
  std::size_t merges = 0;
  std::size_t alive = n;
  // Rounds end: every round tries at least one new (pair, versions), a
  // failure is never retried with the same versions, and a success removes
  // a chart (at most n - 1 of them).
  while(!to_budget || alive > chart_budget)
  {
    // (predicted excess of the union, with a budget), -score, a, b
    std::vector<std::tuple<double, double, std::size_t, std::size_t> > candidates;
    for(std::size_t a = 0; a < n; ++a)
      if(kept[a].alive)
        for(const auto& entry : shared[a])
        {
          const std::size_t b = entry.first;
          const double predicted = excess[a] + excess[b];
          if(b <= a || (!to_budget && !(predicted <= largest_excess_sum)) ||
             tried.count(Tried(a, version[a], b, version[b])) ||
             rule.too_large(kept[a].chart.faces.size() + kept[b].chart.faces.size()))
            continue;
          const double larger = (std::max)(area[a], area[b]);
          // Over the budget: the predicted growth of the area-weighted sum of excesses.
          const double growth = excess_growth(predicted, a, b, area, excess);
          candidates.emplace_back(to_budget && std::isfinite(growth) ? growth : 0.,
                                  larger > 0 ? -entry.second / std::sqrt(larger) : 0., a, b);
        }
    if(candidates.empty())
      break;
    std::sort(candidates.begin(), candidates.end());

    std::vector<std::pair<std::size_t, std::size_t> > round;
    std::vector<std::vector<Index> > round_faces;  // the union of each pair, sorted
    std::vector<char> busy(n, 0);
    for(const auto& c : candidates)
    {
      const std::size_t a = std::get<2>(c), b = std::get<3>(c);
      if(busy[a] || busy[b])
        continue;
      // Twice the pairs needed are solved, the best of them by their measured excess are taken.
      if(to_budget && round.size() >= 2 * (alive - chart_budget))
        break;
      tried.insert(Tried(a, version[a], b, version[b]));
      const std::vector<Index>& fa = kept[a].chart.faces;
      const std::vector<Index>& fb = kept[b].chart.faces;
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
      // A union predicted too curved (Split_rule::predicted_too_curved())
      // is not solved: traced on the 17,757 unions solved for 35 meshes,
      // 150 such unions were rejected (18 % of the faces solved) and 17
      // of the 9,731 accepted ones would have been.
      // Over the budget, a union rejected for the bound may still be taken.
      if((!to_budget && (rejected_regions.count(region_key(faces)) != 0 || rule.predicted_too_curved(faces))) ||
         !topology.is_disk(faces))
        continue;
      busy[a] = busy[b] = 1;
      round.emplace_back(a, b);
      round_faces.push_back(std::move(faces));
    }
    if(round.empty())
      continue;

    std::vector<Chart> unions(round.size());
    std::vector<Chart_outcome> outcomes(round.size());
    std::vector<char> accepted(round.size(), 0);
    std::vector<double> union_excess(round.size(), 0.);
    auto union_size = [&](std::size_t i) { return round_faces[i].size(); };
    for_each_largest_first(for_each, round.size(), union_size, [&](std::size_t i) {
      unions[i] = make_chart(m, round_faces[i]);
      const Chart& a = kept[round[i].first].chart;
      const Chart& b = kept[round[i].second].chart;
      if(has_elimination_order(a) && has_elimination_order(b))
        inherit_union_order(m, a, b, unions[i]);
      // ARAP from the two maps glued rather than from LSCM: half the time
      // on the merges, the same charts on 10 meshes of CGAL's data.
      const Chart_uv start = glue_chart_maps(a, b, unions[i]);
      if(to_budget)
      {
        // Any valid map will do: the fallbacks are tried, ARAP runs to the end.
        outcomes[i] = parameterize_chart_from(m, unions[i], method, use_fallback, start.empty() ? nullptr : &start,
                                              On_invalid_map::redo, nullptr);
        accepted[i] = outcomes[i].valid ? 1 : 0;
        if(accepted[i] && !rule.bound.is_unbounded())
          union_excess[i] = rule.excess(unions[i]);
        return;
      }
      if(!start.empty() && rule.glued_too_concave(unions[i], start))
        return;
      Early_look look{ &early_look, Early_judgement() };
      outcomes[i] = parameterize_chart_from(m, unions[i], method, use_fallback, start.empty() ? nullptr : &start,
                                            rule.on_invalid_map(), &look);
      accepted[i] = rule(unions[i], outcomes[i], union_excess[i], look.ended) ? 0 : 1;
    });

    if(to_budget)
      keep_least_excess_growth(round, union_excess, area, excess, alive - chart_budget, accepted, tried, version);

    for(std::size_t i = 0; i < round.size(); ++i)
    {
      if(!accepted[i])
        continue;
      const std::size_t a = round[i].first, b = round[i].second;
      // The union takes the place of the first of the two in chart order.
      Kept_chart& keep = kept[a];
      Kept_chart& gone = kept[b];
      if(std::tie(gone.patch, gone.path) < std::tie(keep.patch, keep.path))
      {
        keep.patch = gone.patch;
        keep.path = gone.path;
      }
      keep.chart = std::move(unions[i]);
      keep.outcome.used = outcomes[i].used;
      keep.outcome.fallback = outcomes[i].fallback;
      keep.outcome.valid = true;  // an invalid part (use_fallback(false)) may join a valid union
      gone.alive = false;
      --alive;
      for(Index f : gone.chart.faces)
        label[f] = static_cast<Index>(a);
      area[a] += area[b];
      excess[a] = union_excess[i];
      shared[a].erase(b);
      for(const auto& entry : shared[b])
      {
        if(entry.first == a)
          continue;
        shared[a][entry.first] += entry.second;
        shared[entry.first].erase(b);
        shared[entry.first][a] += entry.second;
      }
      shared[b].clear();
      ++version[a];
      ++version[b];
      ++merges;
    }
  }
  kept.erase(std::remove_if(kept.begin(), kept.end(), [](const Kept_chart& k) { return !k.alive; }), kept.end());
  return merges;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_MERGING_H
