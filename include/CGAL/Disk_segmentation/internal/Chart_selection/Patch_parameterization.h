// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// parameterize_patches() on the indexed mesh: the patches, the descent,
// splits, merges and reroutes of charts, and the report.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_PATCH_PARAMETERIZATION_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_PATCH_PARAMETERIZATION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Merge_tree.h>
#include <CGAL/Disk_segmentation/Parameterization_method.h>
#include <CGAL/Disk_segmentation/Parameterization_report.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Chart_choice.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Chart_merging.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Chart_rerouting.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Chart_splitting.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Merge_tree_descent.h>
#include <CGAL/Disk_segmentation/internal/Execution/Progress.h>
#include <CGAL/Disk_segmentation/internal/Execution/parallel.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_topology.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Bound_test.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_distortion.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_parameterization.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Parameterization_settings.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Border_smoother.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Region_curvature.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
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

// The faces of every patch, in increasing order; throws Input_error if the
// ids are not contiguous or, with `require_disks`, if a patch is not a disk.
struct Patch_partition
{
  std::vector<std::size_t> ids;  // of every face
  std::vector<std::vector<Index> > faces;

  std::size_t size() const { return faces.size(); }

  Patch_partition(std::vector<std::size_t> face_ids, Region_topology& topology, bool require_disks)
    : ids(std::move(face_ids)), faces(*std::max_element(ids.begin(), ids.end()) + 1)
  {
    for(Index f = 0; f < ids.size(); ++f)
      faces[ids[f]].push_back(f);
    for(std::size_t p = 0; p < faces.size(); ++p)
    {
      if(faces[p].empty())
        throw Input_error("patch ids are not contiguous: no face has id " + std::to_string(p));
      if(require_disks && !topology.is_disk(faces[p]))
        throw Input_error("patch " + std::to_string(p) + " is not a topological disk");
    }
  }

  // Whether `c` is exactly the faces of one patch.
  bool is_whole_patch(const Chart& c) const
  {
    const std::size_t p = ids[c.faces.front()];
    if(c.faces.size() != faces[p].size())
      return false;
    for(Index f : c.faces)
      if(ids[f] != p)
        return false;
    return true;
  }
};

// Charts are chosen top-down: every candidate is parameterized; one that
// is invalid or exceeds the bound is replaced by its two children in the
// merge tree, and a rejected leaf (or patch, without a tree) is split by
// Voronoi cells (see Split_rule). Candidates do not depend on each other,
// so each is a task that runs as soon as a thread is free, and the
// charts, ordered by their place in the tree at the end, do not depend
// on the schedule. `rejected_regions` receives the region_key() of every
// region rejected, parameterized or predicted over the bound.
template <typename Rule>
std::vector<Kept_chart> descend_to_charts(const Chart_choice<Rule>& choice, const Patch_partition& patches,
                                          const Merge_tree* tree, unsigned int threads, Progress& progress,
                                          std::unordered_set<std::uint64_t>& rejected_regions)
{
  const Indexed_triangle_mesh& m = choice.mesh;
  const std::size_t number_of_patches = patches.size();
  std::vector<Descent_task> roots;
  {
    std::vector<std::size_t> tree_roots;
    if(tree != nullptr)
      tree_roots = patch_roots(m, *tree, patches.ids, number_of_patches);
    for(std::size_t p : largest_first(number_of_patches, [&](std::size_t q) { return patches.faces[q].size(); }))
      roots.push_back(Descent_task{
        Chart_candidate{ p, tree != nullptr ? tree_roots[p] : Chart_candidate::no_node, std::vector<std::size_t>(), 0. },
        false, Split_task() });
  }
  const Candidate_faces candidate_faces(tree, patches.faces);
  Per_thread_splitter splitter(m);

  // Why the requested method's chart of each patch as a whole was rejected.
  std::vector<std::string> patch_problem(number_of_patches);
  std::vector<Found_chart> found;
  std::mutex found_mutex;
  auto keep = [&](const Chart_candidate& c, bool in_split, std::vector<std::size_t> path, Chart&& chart,
                  const Chart_outcome& outcome) {
    Found_chart chart_found{ in_split, c.path.size(), Kept_chart{ c.patch, std::move(path), std::move(chart), outcome } };
    std::lock_guard<std::mutex> lock(found_mutex);
    found.push_back(std::move(chart_found));
  };
  auto reject = [&](std::uint64_t key) {
    std::lock_guard<std::mutex> lock(found_mutex);
    rejected_regions.insert(key);
  };
  auto try_candidate = [&](Chart_candidate& c, const auto& add) {
    const std::vector<Index> faces = candidate_faces(c);
    Chart chart;
    Chart_outcome outcome;
    const Region_trial trial = try_region(choice, splitter.local(), faces, c.excess_density, c.parent, chart, outcome);
    if(c.path.empty())
      patch_problem[c.patch] = outcome.problem;  // one task per patch writes it
    if(trial == Region_trial::kept)
    {
      keep(c, false, c.path, std::move(chart), outcome);
      progress.step("parameterization", number_of_patches);
      return;
    }
    // A region predicted too curved may still be rebuilt by a merge: the
    // prediction, unlike a parameterization, can be wrong.
    if(trial != Region_trial::predicted_curved)
      reject(region_key(faces));
    if(c.node != Chart_candidate::no_node && !tree->is_leaf(c.node))
      for(std::size_t j = 0; j < 2; ++j)
      {
        Chart_candidate child{ c.patch, tree->children(c.node)[j], c.path, c.excess_density, c.parent };
        child.path.push_back(j);
        add(Descent_task{ std::move(child), false, Split_task() });
      }
    else if(faces.size() > 1)
      add(Descent_task{ c, true, Split_task{ faces, c.excess_density, true, c.parent, c.path } });
  };
  for_each_growing(std::move(roots), threads, [&](Descent_task& task, const auto& add) {
    if(!task.in_split)
    {
      try_candidate(task.candidate, add);
      return;
    }
    split_step(
      choice, splitter.local(), task.region,
      [&](Split_task&& part) { add(Descent_task{ task.candidate, true, std::move(part) }); },
      [&](std::vector<std::size_t> path, Chart&& c, const Chart_outcome& outcome) {
        keep(task.candidate, true, std::move(path), std::move(c), outcome);
      },
      reject);
  });
  std::sort(found.begin(), found.end());
  std::vector<Kept_chart> kept;
  kept.reserve(found.size());
  for(Found_chart& f : found)
  {
    f.kept.outcome.problem = patch_problem[f.kept.patch];
    kept.push_back(std::move(f.kept));
  }
  return kept;
}

// Each patch's charts in tree order; the first keeps the patch's id if it
// is below the number of charts, the other charts fill the remaining ids in
// that order, so that ids stay contiguous (merging may leave a patch
// without a chart of its own).
inline void number_charts(std::vector<Kept_chart>& kept, std::size_t number_of_patches, std::vector<Chart>& charts,
                          std::vector<Chart_outcome>& outcomes)
{
  std::sort(kept.begin(), kept.end(), [](const Kept_chart& a, const Kept_chart& b) {
    return a.patch != b.patch ? a.patch < b.patch : a.path < b.path;
  });
  const std::size_t number_of_charts = kept.size();
  charts.assign(number_of_charts, Chart());
  outcomes.assign(number_of_charts, Chart_outcome());
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

// The report of every chart (its distortion measured in parallel), and
// the number of patches that are not one chart.
template <typename ForEach>
void report_charts(const Indexed_triangle_mesh& m, const Patch_partition& patches, const std::vector<Chart>& charts,
                   const std::vector<Chart_outcome>& outcomes, Parameterization_method method,
                   const ForEach& for_each, Parameterization_report& report)
{
  std::vector<Chart_distortion> distortion(charts.size());
  for_each_largest_first(for_each, charts.size(), [&](std::size_t p) { return charts[p].faces.size(); },
                         [&](std::size_t p) { distortion[p] = chart_distortion(m, charts[p]); });
  report.charts.resize(charts.size());
  std::vector<char> patch_is_one_chart(patches.size(), 0);
  for(std::size_t p = 0; p < charts.size(); ++p)
  {
    Chart_report& r = report.charts[p];
    r.patch = p;
    r.faces = charts[p].faces.size();
    r.requested = method;
    r.used = outcomes[p].used;
    r.fallback = outcomes[p].fallback;
    r.split = !patches.is_whole_patch(charts[p]);
    if(!r.split)
      patch_is_one_chart[patches.ids[charts[p].faces.front()]] = 1;
    r.valid = outcomes[p].valid;
    r.method_error = outcomes[p].method_error;
    r.problem = outcomes[p].problem;
    const Chart_distortion& d = distortion[p];
    r.angle_distortion = d.angle;
    r.area_distortion = d.area;
    r.max_stretch = d.max_stretch;
    r.min_area_scale = d.min_area_scale;
    r.max_area_scale = d.max_area_scale;
    r.stretch_p95 = d.stretch_p95;
    report.number_of_fallbacks += r.fallback ? 1 : 0;
    report.number_of_invalid_charts += r.valid ? 0 : 1;
    report.number_of_method_errors += r.method_error ? 1 : 0;
  }
  for(char one_chart : patch_is_one_chart)
    report.number_of_split_patches += one_chart ? 0 : 1;
}

// Writes the chart id of every face and the UVs of its corners, on one
// thread: the user's maps need not be thread-safe.
template <typename TriangleMesh, typename FacePatchMap, typename UVMap>
void write_chart_maps(const TriangleMesh& tm, const Indexed_input<TriangleMesh>& input,
                      const std::vector<Chart>& charts, FacePatchMap face_patch_map, UVMap uv_map)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<UVMap>::value_type UV;
  typedef typename boost::property_traits<FacePatchMap>::value_type Patch_id;
  for(std::size_t p = 0; p < charts.size(); ++p)
  {
    const Chart& c = charts[p];
    // The corner of face f whose target is indexed vertex v gets uv[local v].
    for(std::size_t t = 0; t < c.faces.size(); ++t)
    {
      const Index f = c.faces[t];
      put(face_patch_map, input.face_handles[f], static_cast<Patch_id>(p));
      // Three halfedges: build_indexed_triangle_mesh checked the triangles.
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(input.face_handles[f], tm), tm))
        for(int j = 0; j < 3; ++j)
          if(input.vertex_handles[input.mesh.corners[f][j]] == target(h, tm))
          {
            const std::array<double, 2>& u = c.uv[c.triangles[t][j]];
            put(uv_map, h, UV(u[0], u[1]));
          }
    }
  }
}

// parameterize_patches() on `tm` already indexed (`input`), with its
// parameters read (`settings`, `progress`) and the merge tree given apart,
// so that uv_atlas() can pass its own whatever the type of its parameters,
// and run it again with other settings without another instantiation.
template <typename TriangleMesh, typename FacePatchMap, typename UVMap>
Parameterization_report parameterize_indexed_patches(const TriangleMesh& tm, const Indexed_input<TriangleMesh>& input,
                                                     FacePatchMap face_patch_map, UVMap uv_map,
                                                     const Parameterization_settings& settings,
                                                     Progress& progress, const Merge_tree* tree)
{
  const Indexed_triangle_mesh& m = input.mesh;
  const unsigned int threads = settings.threads;
  const auto for_each = [&](std::size_t n, const auto& work) { for_each_index(n, threads, work); };
  Region_topology topology(m);
  const Patch_partition patches(read_face_labels(input.face_handles, face_patch_map), topology,
                                settings.require_disks);

  const Border_smoother smoother(m);
  const bool bounded = !Bound_test(settings.bound).bounds_nothing();
  std::unique_ptr<Interior_curvature> curvature;
  if(bounded)
    curvature.reset(new Interior_curvature(m));
  const Split_rule needs_split{ m, settings.bound, settings.max_chart_faces, settings.use_fallback,
                                settings.smooth_borders ? &smoother : nullptr, curvature.get(), m.total_common_area() };
  const Chart_choice<Split_rule> choice(m, *settings.method, settings.use_fallback, needs_split);

  std::unordered_set<std::uint64_t> rejected_regions;
  Parameterization_report report;
  std::vector<Kept_chart> kept = descend_to_charts(choice, patches, tree, threads, progress, rejected_regions);
  std::size_t solved_before = choice.tally.faces;
  auto count_solved_since = [&](std::size_t& count) {
    count += choice.tally.faces - solved_before;
    solved_before = choice.tally.faces;
  };
  if(bounded && settings.merge_charts)
  {
    merge_kept_charts(choice, topology, kept, for_each, rejected_regions);
    count_solved_since(report.solved_faces_in_merges);
  }
  if(bounded && settings.straighten_borders)
  {
    reroute_kept_charts(choice, topology, kept, for_each);
    count_solved_since(report.solved_faces_in_reroutes);
  }
  if(kept.size() > settings.max_charts)
  {
    // The budget wins over the bound, never over validity or max_chart_faces.
    report.charts_before_budget = kept.size();
    merge_kept_charts(choice, topology, kept, for_each, rejected_regions, settings.max_charts);
    count_solved_since(report.solved_faces_in_merges);
    report.chart_budget_met = kept.size() <= settings.max_charts;
  }
  report.solved_faces = choice.tally.faces;
  report.number_of_solves = choice.tally.charts;
  progress("parameterization", patches.size(), patches.size());

  std::vector<Chart> charts;
  std::vector<Chart_outcome> outcomes;
  number_charts(kept, patches.size(), charts, outcomes);
  report_charts(m, patches, charts, outcomes, settings.method->id(), for_each, report);
  write_chart_maps(tm, input, charts, face_patch_map, uv_map);
  return report;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_PATCH_PARAMETERIZATION_H
