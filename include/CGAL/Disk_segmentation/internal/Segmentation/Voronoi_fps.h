// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_VORONOI_FPS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_VORONOI_FPS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>

#include <CGAL/assertions.h>
#include <CGAL/Random.h>

#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Joint farthest-point sampling and geodesic Voronoi partition on the dual
// graph of a set of faces (Maggioli et al. 2025, as used by the paper).
//
// Every new seed is the face farthest from all current seeds. A Dijkstra from
// it visits only the faces whose distance strictly improves, which are exactly
// the faces that move to the new cell; the farthest face is read from a lazy
// max-heap. The expected cost is O(F log F log n) instead of n full Dijkstras.
//
// Ties are broken by face index everywhere (distances first, then the smaller
// index), so the result does not depend on memory layout or traversal order.
// Cells are connected: a face that changes cell reaches the new seed through
// faces that changed too (any face on its new shortest path improved as well).
class Voronoi_fps
{
public:
  explicit Voronoi_fps(const Indexed_triangle_mesh& m)
    : m_(m),
      arc_(m.number_of_faces()),
      distance_(m.number_of_faces(), infinity()),
      cell_(m.number_of_faces(), no_index),
      member_(m.number_of_faces(), 0),
      is_seed_(m.number_of_faces(), 0)
  {
    for(Index f = 0; f < m.number_of_faces(); ++f)
      for(int i = 0; i < 3; ++i)
        arc_[f][i] = (m.neighbors[f][i] == no_index) ? infinity() : m.dual_arc_length(f, i);
  }

  // Partitions `region` (distinct face indices in increasing order) into the
  // Voronoi cells of at most `n` farthest-point seeds, with at least one seed
  // in every edge-connected component of the region. The first seed of a
  // component is `first_seed` when it lies there, otherwise a random face of
  // the component when `rng` is given, otherwise the face farthest from the
  // component's smallest face. Returns the seeds in the order they were
  // chosen; `cell(f)` then is the position of the seed of f in that list.
  std::vector<Index> run(const std::vector<Index>& region, std::size_t n,
                         Index first_seed = no_index, CGAL::Random* rng = nullptr)
  {
    CGAL_precondition(std::is_sorted(region.begin(), region.end()));
    std::vector<Index> seeds;
    if(region.empty())
      return seeds;

    enter(region);
    seed_components(region, first_seed, rng, seeds);

    const std::size_t target = (std::min)((std::max)(n, seeds.size()), region.size());

    // One multi-source Dijkstra from the component seeds.
    for(Index f : region)
      distance_[f] = infinity();
    for(std::size_t s = 0; s < seeds.size(); ++s)
      make_seed(seeds[s], static_cast<Index>(s));
    relax_from(seeds, false);

    if(seeds.size() < target && target - seeds.size() <= most_scanned_seeds)
    {
      // A few seeds (the segmentation's 10, a split's 2 or 5): one scan per
      // seed finds the farthest face, in the heap's order, and no heap is
      // kept; pushing every improved distance into it cost more (Voronoi
      // sampling of refined_elephant x4, 355k faces: 0.40 -> 0.24 s).
      while(seeds.size() < target)
      {
        Index s = no_index;
        std::pair<double, Index> best;
        for(Index f : region)
          if(is_seed_[f] != stamp_)
          {
            const std::pair<double, Index> key(farthest_key(f, distance_[f]), reversed(f));
            if(s == no_index || best < key)
            {
              best = key;
              s = f;
            }
          }
        CGAL_assertion(s != no_index);
        make_seed(s, static_cast<Index>(seeds.size()));
        seeds.push_back(s);
        relax_from(std::vector<Index>(1, s), false);
      }
    }
    else if(seeds.size() < target)
    {
      farthest_.clear();
      for(Index f : region)
        if(is_seed_[f] != stamp_)
          farthest_.push_back(std::make_pair(farthest_key(f, distance_[f]), reversed(f)));
      std::make_heap(farthest_.begin(), farthest_.end());

      // One seed per pass, so target - seeds.size() <= |region| passes. The
      // last seed's improvements need not enter the heap.
      while(seeds.size() < target)
      {
        const Index s = pop_farthest(region);
        CGAL_assertion(s != no_index);
        make_seed(s, static_cast<Index>(seeds.size()));
        seeds.push_back(s);
        const std::vector<Index> source(1, s);
        relax_from(source, seeds.size() < target);
      }
    }
    return seeds;
  }

  // Partitions `region` into the Voronoi cells of `seeds` (faces of the
  // region); `cell(f)` then is the position of the seed of f. Returns false
  // if a face of the region is reached from no seed (another component).
  bool run_from_seeds(const std::vector<Index>& region, const std::vector<Index>& seeds)
  {
    enter(region);
    for(std::size_t s = 0; s < seeds.size(); ++s)
    {
      CGAL_precondition(member_[seeds[s]] == stamp_);
      make_seed(seeds[s], static_cast<Index>(s));
    }
    relax_from(seeds, false);
    for(Index f : region)
      if(cell_[f] == no_index)
        return false;
    return true;
  }

  Index cell(Index f) const { return cell_[f]; }

private:
  typedef std::pair<double, Index> Entry;  // (distance, face)

  static double infinity() { return std::numeric_limits<double>::infinity(); }

  static constexpr std::size_t most_scanned_seeds = 16;

  // Max-heap entries order equal distances by increasing face index.
  static Index reversed(Index f) { return no_index - f; }

  // Distances are measured in the frame of each face's component; seeds
  // compete across components in the common frame (exact: a power of two).
  double farthest_key(Index f, double d) const { return d * m_.common_unit(f); }

  // Makes `region` the current region, every face unreached.
  void enter(const std::vector<Index>& region)
  {
    ++stamp_;
    if(stamp_ == 0)
    {
      std::fill(member_.begin(), member_.end(), 0);
      std::fill(is_seed_.begin(), is_seed_.end(), 0);
      stamp_ = 1;
    }
    for(Index f : region)
    {
      member_[f] = stamp_;
      distance_[f] = infinity();
      cell_[f] = no_index;
    }
  }

  void make_seed(Index s, Index c)
  {
    distance_[s] = 0.;
    cell_[s] = c;
    is_seed_[s] = stamp_;
  }

  // Dijkstra from `sources` (already at distance 0) inside the current
  // region; `on_settle(f, d)` sees each face once its distance d is final.
  // Only strictly shorter distances are written, so that faces at equal
  // distance keep their older cell.
  template <typename OnSettle>
  void relax_from(const std::vector<Index>& sources, bool track_farthest, const OnSettle& on_settle)
  {
    for(Index s : sources)
      queue_.push(Entry(0., s));
    // Bound: a distance is written only when it strictly drops, and arcs are
    // >= 0 (a NaN arc relaxes nothing), so a settled face never drops again:
    // each face is settled once and pushes at most 3 entries.
    while(!queue_.empty())
    {
      const Entry top = queue_.top();
      queue_.pop();
      const Index f = top.second;
      if(top.first > distance_[f])
        continue;
      on_settle(f, top.first);
      for(int i = 0; i < 3; ++i)
      {
        const Index g = m_.neighbors[f][i];
        if(g == no_index || member_[g] != stamp_)
          continue;
        const double d = top.first + arc_[f][i];
        if(d < distance_[g])
        {
          distance_[g] = d;
          cell_[g] = cell_[f];
          queue_.push(Entry(d, g));
          if(track_farthest)
          {
            farthest_.push_back(std::make_pair(farthest_key(g, d), reversed(g)));
            std::push_heap(farthest_.begin(), farthest_.end());
          }
        }
      }
    }
  }

  void relax_from(const std::vector<Index>& sources, bool track_farthest)
  {
    relax_from(sources, track_farthest, [](Index, double) {});
  }

  Index pop_farthest(const std::vector<Index>& region)
  {
    // Stale entries (distance since lowered, or face since made a seed)
    // accumulate; rebuild when they dominate to keep memory O(region).
    if(farthest_.size() > 4 * region.size() + 64)
    {
      farthest_.clear();
      for(Index f : region)
        if(is_seed_[f] != stamp_)
          farthest_.push_back(std::make_pair(farthest_key(f, distance_[f]), reversed(f)));
      std::make_heap(farthest_.begin(), farthest_.end());
    }
    // Each pass pops an entry: at most the heap's size.
    while(!farthest_.empty())
    {
      std::pop_heap(farthest_.begin(), farthest_.end());
      const std::pair<double, Index> top = farthest_.back();
      farthest_.pop_back();
      const Index f = reversed(top.second);
      if(is_seed_[f] != stamp_ && top.first == farthest_key(f, distance_[f]))
        return f;
    }
    return no_index;
  }

  // Finds the edge-connected components of the region in order of their
  // smallest face and appends one seed per component to `seeds`.
  void seed_components(const std::vector<Index>& region, Index first_seed,
                       CGAL::Random* rng, std::vector<Index>& seeds)
  {
    std::vector<Index> component;
    for(Index root : region)
    {
      if(distance_[root] != infinity())
        continue;
      // A Dijkstra from the smallest face labels the component and finds
      // the face farthest from it.
      distance_[root] = 0.;
      component.clear();
      Index farthest = root;
      double farthest_distance = 0.;
      bool has_first_seed = false;
      relax_from(std::vector<Index>(1, root), false, [&](Index f, double d)
      {
        if(rng != nullptr)  // only a random seed needs the component's faces
          component.push_back(f);
        has_first_seed = has_first_seed || f == first_seed;
        if(d > farthest_distance || (d == farthest_distance && f < farthest))
        {
          farthest = f;
          farthest_distance = d;
        }
      });

      Index seed = farthest;
      if(has_first_seed)
        seed = first_seed;
      else if(rng != nullptr)
      {
        std::sort(component.begin(), component.end());
        seed = component[static_cast<std::size_t>(rng->get_int(0, static_cast<int>(component.size())))];
      }
      seeds.push_back(seed);
    }
  }

  const Indexed_triangle_mesh& m_;
  std::vector<std::array<double, 3> > arc_;
  std::vector<double> distance_;
  std::vector<Index> cell_;
  std::vector<Index> member_, is_seed_;
  Index stamp_ = 0;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue_;
  std::vector<std::pair<double, Index> > farthest_;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_VORONOI_FPS_H
