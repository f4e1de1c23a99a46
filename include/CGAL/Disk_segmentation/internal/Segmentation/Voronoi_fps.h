// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Joint farthest-point sampling and geodesic Voronoi partition of a set
// of faces on the dual graph.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_VORONOI_FPS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_VORONOI_FPS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>

#include <CGAL/assertions.h>
#include <CGAL/Random.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// The length of every arc of the dual graph (infinite where a face has no
// neighbor), by face and edge.
typedef std::vector<std::array<double, 3> > Dual_arcs;

inline Dual_arcs dual_arcs(const Indexed_triangle_mesh& m)
{
  Dual_arcs arcs(m.number_of_faces());
  for(Index f = 0; f < m.number_of_faces(); ++f)
  {
    const std::array<double, 3> centroid_of_f = m.centroid(f);
    for(int i = 0; i < 3; ++i)
      arcs[f][i] = m.neighbors[f][i] == no_index ? std::numeric_limits<double>::infinity()
                                                 : m.dual_arc_length(f, i, centroid_of_f);
  }
  return arcs;
}

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
  // Its arrays are sized to the region of the last call, not to the mesh:
  // one sampler per thread splits charts in parallel, and mesh-sized arrays
  // cost 44 bytes per face per thread (refined_elephant x4, 355k faces,
  // 2 threads: 31 MB of the 190 MB heap peak). The arcs' lengths come from
  // `mesh_arcs` (see dual_arcs()) if given, which must outlive the sampler;
  // else each call measures those of its region (the splitters do: half a
  // percent more instructions on refined_elephant than one shared table,
  // and no memory per face).
  explicit Voronoi_fps(const Indexed_triangle_mesh& m, const Dual_arcs* mesh_arcs = nullptr)
    : m_(m), mesh_arcs_(mesh_arcs)
  {}

  // Partitions `region` (distinct face indices in increasing order) into the
  // Voronoi cells of at most `n` farthest-point seeds, with at least one seed
  // in every edge-connected component of the region. The first seed of a
  // component is `first_seed` when it lies there, otherwise a random face of
  // the component when `rng` is given, otherwise the face farthest from the
  // component's smallest face. Returns the seeds in the order they were
  // chosen; `cells()[k]` then is the position in that list of the seed of
  // the k-th face of the region.
  std::vector<Index> run(const std::vector<Index>& region, std::size_t n,
                         Index first_seed = no_index, CGAL::Random* rng = nullptr)
  {
    CGAL_precondition(std::is_sorted(region.begin(), region.end()));
    std::vector<Index> seeds;
    enter(region);
    if(region.empty())
      return seeds;
    const std::size_t size = region.size();

    std::vector<Index> local_seeds;
    seed_components(first_seed, rng, local_seeds);

    const std::size_t target = (std::min)((std::max)(n, local_seeds.size()), size);

    // One multi-source Dijkstra from the component seeds.
    std::fill(distance_.begin(), distance_.end(), infinity());
    for(std::size_t s = 0; s < local_seeds.size(); ++s)
      make_seed(local_seeds[s], static_cast<Index>(s));
    relax_from(local_seeds, false);

    if(local_seeds.size() < target && target - local_seeds.size() <= most_scanned_seeds)
    {
      // A few seeds (the segmentation's 10, a split's 2 or 5): one scan per
      // seed finds the farthest face, in the heap's order, and no heap is
      // kept; pushing every improved distance into it cost more (Voronoi
      // sampling of refined_elephant x4, 355k faces: 0.40 -> 0.24 s).
      while(local_seeds.size() < target)
      {
        Index s = no_index;
        std::pair<double, Index> best;
        for(Index k = 0; k < size; ++k)
          if(!is_seed_[k])
          {
            const std::pair<double, Index> key(farthest_key(k, distance_[k]), reversed(k));
            if(s == no_index || best < key)
            {
              best = key;
              s = k;
            }
          }
        CGAL_assertion(s != no_index);
        make_seed(s, static_cast<Index>(local_seeds.size()));
        local_seeds.push_back(s);
        relax_from(std::vector<Index>(1, s), false);
      }
    }
    else if(local_seeds.size() < target)
    {
      farthest_.clear();
      for(Index k = 0; k < size; ++k)
        if(!is_seed_[k])
          farthest_.push_back(std::make_pair(farthest_key(k, distance_[k]), reversed(k)));
      std::make_heap(farthest_.begin(), farthest_.end());

      // One seed per pass, so target - seeds.size() <= |region| passes. The
      // last seed's improvements need not enter the heap.
      while(local_seeds.size() < target)
      {
        const Index s = pop_farthest();
        CGAL_assertion(s != no_index);
        make_seed(s, static_cast<Index>(local_seeds.size()));
        local_seeds.push_back(s);
        const std::vector<Index> source(1, s);
        relax_from(source, local_seeds.size() < target);
      }
    }
    seeds.reserve(local_seeds.size());
    for(Index s : local_seeds)
      seeds.push_back((*region_)[s]);
    return seeds;
  }

  // Partitions `region` into the Voronoi cells of `seeds` (faces of the
  // region); `cells()` then gives the position of each face's seed. Returns
  // false if a face of the region is reached from no seed (another
  // component), or if a seed is not in the region.
  bool run_from_seeds(const std::vector<Index>& region, const std::vector<Index>& seeds)
  {
    enter(region);
    std::vector<Index> local_seeds;
    for(std::size_t s = 0; s < seeds.size(); ++s)
    {
      const Index k = local(seeds[s]);
      if(k == no_index)
        return false;
      make_seed(k, static_cast<Index>(s));
      local_seeds.push_back(k);
    }
    relax_from(local_seeds, false);
    for(Index c : cell_)
      if(c == no_index)
        return false;
    return true;
  }

  // Per face of the region of the last call, in its order: the position of
  // its seed.
  const std::vector<Index>& cells() const { return cell_; }

private:
  typedef std::pair<double, Index> Entry;  // (distance, position in the region)

  static double infinity() { return std::numeric_limits<double>::infinity(); }

  static constexpr std::size_t most_scanned_seeds = 16;

  // Max-heap entries order equal distances by increasing face index; the
  // region is sorted, so positions order as the faces do.
  static Index reversed(Index k) { return no_index - k; }

  // Distances are measured in the frame of each face's component; seeds
  // compete across components in the common frame (exact: a power of two).
  double farthest_key(Index k, double d) const { return d * m_.common_unit((*region_)[k]); }

  // The position of face f in the region, or no_index if it is not there;
  // searched outward from position `near`: faces are numbered along the
  // surface, so a neighbor's position is mostly close.
  Index local(Index f, Index near = 0) const
  {
    const std::vector<Index>& region = *region_;
    if(contiguous_)
      return f >= region.front() && f - region.front() < region.size() ? f - region.front() : no_index;
    const Index size = static_cast<Index>(region.size());
    if(size == 0)
      return no_index;
    Index low = near, high = near;  // f is in [region[low], region[high]] if there
    for(Index step = 1; region[high] < f; step *= 2)
    {
      low = high;
      if(high == size - 1)
        return no_index;
      high = (std::min)(size - 1, high + step);
    }
    for(Index step = 1; f < region[low]; step *= 2)
    {
      high = low;
      if(low == 0)
        return no_index;
      low = low > step ? low - step : 0;
    }
    const auto it = std::lower_bound(region.begin() + low, region.begin() + high + 1, f);
    return *it == f ? static_cast<Index>(it - region.begin()) : no_index;
  }

  // Makes `region` the current region, every face unreached: its dual
  // graph in positions, with the arcs' lengths.
  void enter(const std::vector<Index>& region)
  {
    region_ = &region;
    const std::size_t size = region.size();
    contiguous_ = size > 0 && region.back() - region.front() + 1 == size;
    distance_.assign(size, infinity());
    cell_.assign(size, no_index);
    is_seed_.assign(size, 0);
    neighbor_.resize(size);
    arc_.resize(size);
    for(Index k = 0; k < size; ++k)
    {
      const Index f = region[k];
      const std::array<double, 3> centroid_of_f = m_.centroid(f);
      for(int i = 0; i < 3; ++i)
      {
        const Index g = m_.neighbors[f][i];
        if(g == no_index)
          neighbor_[k][i] = no_index;
        else
        {
          // Where it is when the faces between f and g are in the region too.
          const std::int64_t guess = std::int64_t(k) + (std::int64_t(g) - std::int64_t(f));
          neighbor_[k][i] =
            guess >= 0 && guess < std::int64_t(size) && region[std::size_t(guess)] == g ? Index(guess) : local(g, k);
        }
        if(mesh_arcs_ == nullptr)
          arc_[k][i] = neighbor_[k][i] == no_index ? infinity() : m_.dual_arc_length(f, i, centroid_of_f);
      }
      if(mesh_arcs_ != nullptr)
        arc_[k] = (*mesh_arcs_)[f];
    }
  }

  void make_seed(Index k, Index c)
  {
    distance_[k] = 0.;
    cell_[k] = c;
    is_seed_[k] = 1;
  }

  // Dijkstra from `sources` (already at distance 0) inside the current
  // region; `on_settle(k, d)` sees each face once its distance d is final.
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
      const Index k = top.second;
      if(top.first > distance_[k])
        continue;
      on_settle(k, top.first);
      for(int i = 0; i < 3; ++i)
      {
        const Index g = neighbor_[k][i];
        if(g == no_index)
          continue;
        const double d = top.first + arc_[k][i];
        if(d < distance_[g])
        {
          distance_[g] = d;
          cell_[g] = cell_[k];
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

  Index pop_farthest()
  {
    const std::size_t size = distance_.size();
    // Stale entries (distance since lowered, or face since made a seed)
    // accumulate; rebuild when they dominate to keep memory O(region).
    if(farthest_.size() > 4 * size + 64)
    {
      farthest_.clear();
      for(Index k = 0; k < size; ++k)
        if(!is_seed_[k])
          farthest_.push_back(std::make_pair(farthest_key(k, distance_[k]), reversed(k)));
      std::make_heap(farthest_.begin(), farthest_.end());
    }
    // Each pass pops an entry: at most the heap's size.
    while(!farthest_.empty())
    {
      std::pop_heap(farthest_.begin(), farthest_.end());
      const std::pair<double, Index> top = farthest_.back();
      farthest_.pop_back();
      const Index k = reversed(top.second);
      if(!is_seed_[k] && top.first == farthest_key(k, distance_[k]))
        return k;
    }
    return no_index;
  }

  // Finds the edge-connected components of the region in order of their
  // smallest face and appends one seed (a position) per component to
  // `seeds`.
  void seed_components(Index first_seed, CGAL::Random* rng, std::vector<Index>& seeds)
  {
    const std::vector<Index>& region = *region_;
    std::vector<Index> component;
    for(Index root = 0; root < region.size(); ++root)
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
      Index first_seed_position = no_index;
      relax_from(std::vector<Index>(1, root), false, [&](Index k, double d)
      {
        if(rng != nullptr)  // only a random seed needs the component's faces
          component.push_back(k);
        if(region[k] == first_seed)
        {
          has_first_seed = true;
          first_seed_position = k;
        }
        if(d > farthest_distance || (d == farthest_distance && k < farthest))
        {
          farthest = k;
          farthest_distance = d;
        }
      });

      Index seed = farthest;
      if(has_first_seed)
        seed = first_seed_position;
      else if(rng != nullptr)
      {
        std::sort(component.begin(), component.end());
        seed = component[static_cast<std::size_t>(rng->get_int(0, static_cast<int>(component.size())))];
      }
      seeds.push_back(seed);
    }
  }

  const Indexed_triangle_mesh& m_;
  const Dual_arcs* mesh_arcs_;
  const std::vector<Index>* region_ = nullptr;  // of the last call
  bool contiguous_ = false;                     // the region is an interval of faces
  std::vector<std::array<Index, 3> > neighbor_;  // positions, or no_index
  std::vector<std::array<double, 3> > arc_;
  std::vector<double> distance_;
  std::vector<Index> cell_;
  std::vector<char> is_seed_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue_;
  std::vector<std::pair<double, Index> > farthest_;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_VORONOI_FPS_H
