// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_PATCH_PARAMETERIZATION_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_PATCH_PARAMETERIZATION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Merge_tree.h>
#include <CGAL/Disk_segmentation/Parameterization_method.h>
#include <CGAL/Disk_segmentation/Parameterization_report.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Chart_merging.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Chart_rerouting.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Chart_splitting.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Merge_tree_descent.h>
#include <CGAL/Disk_segmentation/internal/Execution/Progress.h>
#include <CGAL/Disk_segmentation/internal/Execution/parallel.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_topology.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_distortion.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_parameterization.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameterization_settings.h>
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
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_PATCH_PARAMETERIZATION_H
