// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reroutes the borders between kept charts (Border_router) and
// parameterizes the changed charts again, giving back what breaks them.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_REROUTING_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_REROUTING_H

#include <CGAL/Disk_segmentation/internal/Chart_selection/Chart_choice.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Border_rerouting.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_distortion.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Chart_merging.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_method_chain.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_parameterization.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_topology.h>
#include <CGAL/Disk_segmentation/internal/Execution/parallel.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// An arc is rerouted only if the new path is this much shorter (a fraction
// of the arc): smaller gains would re-parameterize both charts for a border
// that looks the same.
constexpr double least_reroute_gain = 0.02;

// Arcs of a chart loaded (Bound_test::load) above this are left as they are: such a chart
// almost always breaks the bound once its border moves, and each try costs
// two parameterizations. Measured on the 23 shipped meshes (one run, two
// meshes at a time): without the gate 384 of 1641 rerouted arcs kept, cut
// summed 431.1 -> 422.0, parameterization +29 %; at 0.9, 279 of 801 kept,
// cut 424.6, +11 %; at 0.8, 170 of 391 kept.
constexpr double largest_reroute_load = 0.9;

// Reroutes the arcs between the charts `labels` gives (per face, the index
// in `kept`; `size`: faces per chart, both updated) one after another, and
// returns the changes made. The router's per-vertex and per-face arrays are
// freed on return, before the charts are solved again, where the memory
// peaks.
template <typename Rule, typename ForEach>
std::vector<Arc_change> reroute_arcs(const Indexed_triangle_mesh& m, Region_topology& topology,
                                     const std::vector<Kept_chart>& kept, const Rule& rule,
                                     std::vector<Index>& labels, std::vector<std::size_t>& size,
                                     const ForEach& for_each)
{
  const std::size_t n = kept.size();
  Border_router router(m);
  router.assign(labels, n);
  std::vector<char> locked(m.number_of_faces(), 0);
  std::vector<Arc_change> changes;
  std::vector<double> load(n, 0.);
  for_each(n, [&](std::size_t i) { load[i] = rule.test().load(chart_distortion(m, kept[i].chart)); });
  for(const Border_arc& arc : router.arcs(labels))
  {
    if(load[arc.a] > largest_reroute_load || load[arc.b] > largest_reroute_load)
      continue;
    Arc_change change;
    if(!router.reroute(labels, size, locked, topology, arc, least_reroute_gain, change))
      continue;
    if(rule.too_large(size[change.a]) || rule.too_large(size[change.b]))
    {
      router.undo(labels, size, change);
      continue;
    }
    for(const auto& moved : change.old_labels)
      locked[moved.first] = 1;
    changes.push_back(std::move(change));
  }
  return changes;
}

// The faces of chart `i` (`chart` before the changes) under `labels`: those
// it kept, and those it gained through its changes not given back; sorted.
inline std::vector<Index> current_faces(const Chart& chart, std::size_t i, const std::vector<Index>& labels,
                                        const std::vector<Arc_change>& changes,
                                        const std::vector<std::size_t>& changes_of_i,
                                        const std::vector<char>& given_back)
{
  std::vector<Index> f;
  for(Index g : chart.faces)
    if(labels[g] == i)
      f.push_back(g);
  for(std::size_t k : changes_of_i)
    if(!given_back[k])
      for(const auto& moved : changes[k].old_labels)
        if(labels[moved.first] == i && moved.second != i)
          f.push_back(moved.first);
  std::sort(f.begin(), f.end());
  return f;
}

// Straightens the borders between the kept charts (see Border_router), then
// parameterizes again every chart whose faces changed. A chart that is then
// invalid, no longer a disk, above the size cap or over the bound (`rule`)
// gives back arcs it took part in (see give_back below), which changes its
// neighbors in turn; rounds go on until every changed chart meets the
// bound, and a chart whose arcs were all given back keeps its former map.
// Arcs are rerouted one after another in a fixed order and charts are
// parameterized independently, so the result does not depend on the
// schedule. Returns the number of arcs kept rerouted.
template <typename Rule, typename ForEach>
std::size_t reroute_kept_charts(const Chart_choice<Rule>& choice, Region_topology& topology,
                                std::vector<Kept_chart>& kept, const ForEach& for_each)
{
  const Indexed_triangle_mesh& m = choice.mesh;
  const Rule& rule = choice.needs_split;
  const std::size_t n = kept.size();
  std::vector<Index> labels(m.number_of_faces(), no_index);
  std::vector<std::size_t> size(n, 0);
  for(std::size_t i = 0; i < n; ++i)
  {
    for(Index f : kept[i].chart.faces)
      labels[f] = static_cast<Index>(i);
    size[i] = kept[i].chart.faces.size();
  }
  std::vector<Arc_change> changes = reroute_arcs(m, topology, kept, rule, labels, size, for_each);
  if(changes.empty())
    return 0;

  std::vector<std::vector<std::size_t> > changes_of(n);
  for(std::size_t k = 0; k < changes.size(); ++k)
  {
    changes_of[changes[k].a].push_back(k);
    changes_of[changes[k].b].push_back(k);
  }
  std::vector<char> given_back(changes.size(), 0), dirty(n, 0);
  for(const Arc_change& c : changes)
    dirty[c.a] = dirty[c.b] = 1;
  auto modified = [&](std::size_t i) {
    for(std::size_t k : changes_of[i])
      if(!given_back[k])
        return true;
    return false;
  };
  // Faces chart i gained through change k, less those it lost.
  auto net_gain = [&](std::size_t i, std::size_t k) {
    long gain = 0;
    for(const auto& moved : changes[k].old_labels)
      gain += moved.second == i ? -1 : 1;
    return gain;
  };
  // A chart over the bound first gives back the arcs through which it grew
  // (distortion grows with a chart's area), and all of them only if it
  // grew through none: most charts that shrink still meet the bound, so
  // their neighbors keep their straighter borders.
  auto give_back = [&](std::size_t i) {
    bool grew = false;
    for(std::size_t k : changes_of[i])
      grew = grew || (!given_back[k] && net_gain(i, k) > 0);
    for(std::size_t k : changes_of[i])
      if(!given_back[k] && (!grew || net_gain(i, k) > 0))
      {
        given_back[k] = 1;
        for(const auto& moved : changes[k].old_labels)
          labels[moved.first] = moved.second;
        dirty[changes[k].a] = dirty[changes[k].b] = 1;
      }
  };
  std::vector<Chart> rerouted(n);
  std::vector<Chart_outcome> outcomes(n);
  // Rounds end: each one that fails gives back at least one arc.
  for(;;)
  {
    std::vector<std::size_t> to_solve;
    std::vector<std::vector<Index> > faces;
    for(std::size_t i = 0; i < n; ++i)
    {
      if(!dirty[i])
        continue;
      dirty[i] = 0;
      if(!modified(i))
        continue;
      to_solve.push_back(i);
      faces.push_back(current_faces(kept[i].chart, i, labels, changes, changes_of[i], given_back));
    }
    std::vector<char> failed(to_solve.size(), 0);
    // The disk test shares its scratch arrays: before the parallel part.
    // Giving arcs back may grow a chart past the size cap again.
    for(std::size_t j = 0; j < to_solve.size(); ++j)
      failed[j] = !rule.too_large(faces[j].size()) && topology.is_disk(faces[j]) ? 0 : 1;
    auto chart_size = [&](std::size_t j) { return faces[j].size(); };
    for_each_largest_first(for_each, to_solve.size(), chart_size, [&](std::size_t j) {
      if(failed[j])
        return;
      const std::size_t i = to_solve[j];
      rerouted[i] = make_chart(m, faces[j]);
      // From LSCM: the two former maps glued (as merges start) fold or
      // break the bound far more often (dino: 2 of 119 arcs kept, against
      // 20 from LSCM).
      Early_look look{ &choice.early_look, Early_judgement() };
      outcomes[i] = choice.solve(rerouted[i], rule.on_invalid_map(), &look);
      failed[j] = rule(rerouted[i], outcomes[i], look.ended) ? 1 : 0;
    });
    bool any = false;
    for(std::size_t j = 0; j < to_solve.size(); ++j)
      if(failed[j])
      {
        give_back(to_solve[j]);
        any = true;
      }
    if(!any)
      break;
  }

  std::size_t kept_arcs = 0;
  for(std::size_t k = 0; k < changes.size(); ++k)
    kept_arcs += given_back[k] ? 0 : 1;
  for(std::size_t i = 0; i < n; ++i)
    if(modified(i))
    {
      kept[i].chart = std::move(rerouted[i]);
      kept[i].outcome.used = outcomes[i].used;
      kept[i].outcome.fallback = outcomes[i].fallback;
    }
  return kept_arcs;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_CHART_REROUTING_H
