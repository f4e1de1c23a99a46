// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Greedy merging of adjacent disk regions into larger disks (the paper's
// Algorithm 2).

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_DISK_REGION_MERGER_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_DISK_REGION_MERGER_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Vertex_faces.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Greedy merging of adjacent disk regions (the paper's Algorithm 2).
//
// Two disks glued along one boundary arc, and nothing else, form a disk; by
// inclusion-exclusion, chi(Si u Sj) = 1 iff chi(Si n Sj) = 1. The shared
// part (common vertices and edges) must therefore be a single open path:
// at least one edge, V = E + 1, and connected. A lone common vertex elsewhere
// would make the union pinched there, which the connectivity test catches.
//
// The best pair by score J = l_ij / sqrt(max(A_i, A_j)) merges first. Rather
// than rescanning all pairs after every merge, candidates sit in a lazy
// max-heap stamped with the versions of their two regions; a merge bumps the
// versions and pushes fresh candidates for the merged region only. The
// topology test runs when a candidate reaches the top: a pair's validity
// depends on its two regions alone, so testing it late gives the same
// sequence of merges as the full rescan, with a total order on candidates
// (score, then smaller ids) that makes the sequence deterministic.
class Disk_region_merger
{
public:
  // `labels` holds region ids in [0, number_of_regions); every region must
  // be a topological disk.
  Disk_region_merger(const Indexed_triangle_mesh& m, std::vector<Index>& labels,
                     std::size_t number_of_regions)
    : m_(m), labels_(labels),
      faces_(number_of_regions), area_(number_of_regions, 0.),
      version_(number_of_regions, 0), shared_length_(number_of_regions),
      vertex_faces_(m, true), vertex_mark_(m.number_of_vertices(), 0), node_(number_of_regions)
  {
    for(Index r = 0; r < number_of_regions; ++r)
      node_[r] = r;
    for(Index f = 0; f < labels.size(); ++f)
    {
      faces_[labels[f]].push_back(f);
      area_[labels[f]] += m.area(f);
      for(int i = 0; i < 3; ++i)
      {
        const Index g = m.neighbors[f][i];
        // Each edge once, from its face of smaller index.
        if(g != no_index && f < g && labels[g] != labels[f])
        {
          const double l = m.edge_length(f, i);
          shared_length_[labels[f]][labels[g]] += l;
          shared_length_[labels[g]][labels[f]] += l;
        }
      }
    }
  }

  // Merges while some valid pair scores at least `threshold`; returns the
  // number of merges done.
  std::size_t run(double threshold)
  {
    threshold_ = threshold;
    for(Index r = 0; r < faces_.size(); ++r)
      for(const auto& nl : shared_length_[r])
        if(r < nl.first)
          push_candidate(r, nl.first, nl.second);

    std::size_t merges = 0;
    // Lazy heap, bound by pushes: each pass pops one candidate; a merge kills
    // a region for good, so at most R - 1 merges, each pushing at most R
    // candidates, on top of one per adjacent pair at the start.
    while(!heap_.empty())
    {
      std::pop_heap(heap_.begin(), heap_.end());
      const Candidate c = heap_.back();
      heap_.pop_back();
      if(version_[c.a] != c.version_a || version_[c.b] != c.version_b)
        continue;
      if(!union_is_disk(c.a, c.b))
        continue;
      merge(c.a, c.b);
      ++merges;
    }
    return merges;
  }

  // The merges done, in order: merge i made tree node (regions + i) out of
  // the two nodes it lists (see Merge_tree).
  const std::vector<std::array<std::size_t, 2> >& merges() const { return merges_; }

private:
  struct Candidate
  {
    double score;
    Index a, b, version_a, version_b;  // a < b

    // Max-heap order: higher score first, then smaller ids.
    bool operator<(const Candidate& o) const
    {
      if(score != o.score) return score < o.score;
      return std::tie(o.a, o.b, o.version_a, o.version_b) < std::tie(a, b, version_a, version_b);
    }
  };

  double score(Index a, Index b, double shared_length) const
  {
    // A region without area (degenerate faces only) merges first into any
    // neighbor it forms a disk with: alone it could not be parameterized.
    if(!(area_[a] > 0.) || !(area_[b] > 0.))
      return std::numeric_limits<double>::infinity();
    return shared_length / std::sqrt((std::max)(area_[a], area_[b]));
  }

  void push_candidate(Index a, Index b, double shared_length)
  {
    const double s = score(a, b, shared_length);
    if(!(s >= threshold_))
      return;
    if(b < a) std::swap(a, b);
    heap_.push_back(Candidate{ s, a, b, version_[a], version_[b] });
    std::push_heap(heap_.begin(), heap_.end());
  }

  bool union_is_disk(Index a, Index b)
  {
    const Index small = faces_[a].size() <= faces_[b].size() ? a : b;
    const Index other = (small == a) ? b : a;

    if(++stamp_ == 0)
    {
      std::fill(vertex_mark_.begin(), vertex_mark_.end(), 0);
      stamp_ = 1;
    }
    shared_vertices_.clear();
    shared_edges_.clear();
    for(Index f : faces_[small])
    {
      for(int i = 0; i < 3; ++i)
      {
        const Index g = m_.neighbors[f][i];
        if(g != no_index && labels_[g] == other)
        {
          const std::pair<Index, Index> e = m_.edge_vertices(f, i);
          shared_edges_.emplace_back(m_.input_vertex(e.first), m_.input_vertex(e.second));
        }

        // Vertices as in the input: the fans of a pinched vertex are one.
        const Index v = m_.input_vertex(m_.corners[f][i]);
        if(vertex_mark_[v] == stamp_)
          continue;
        vertex_mark_[v] = stamp_;
        for(Index k = vertex_faces_.begin[v]; k < vertex_faces_.begin[v + 1]; ++k)
          if(labels_[vertex_faces_.faces[k]] == other)
          {
            shared_vertices_.push_back(v);
            break;
          }
      }
    }

    if(shared_edges_.empty() || shared_vertices_.size() != shared_edges_.size() + 1)
      return false;

    // V = E + 1: the shared part is a path iff it is connected.
    std::sort(shared_vertices_.begin(), shared_vertices_.end());
    parent_.resize(shared_vertices_.size());
    for(Index i = 0; i < parent_.size(); ++i) parent_[i] = i;
    std::size_t components = shared_vertices_.size();
    for(const auto& e : shared_edges_)
    {
      const Index x = find_root(position_of(e.first)), y = find_root(position_of(e.second));
      if(x != y) { parent_[x] = y; --components; }
    }
    return components == 1;
  }

  Index position_of(Index v) const
  {
    return static_cast<Index>(std::lower_bound(shared_vertices_.begin(), shared_vertices_.end(), v) -
                              shared_vertices_.begin());
  }

  // Ends: links join two distinct roots only, so parent_ is a forest; at
  // most |shared_vertices_| steps.
  Index find_root(Index i)
  {
    while(parent_[i] != i) { parent_[i] = parent_[parent_[i]]; i = parent_[i]; }
    return i;
  }

  // The region with more faces absorbs the other (ties: smaller id), so
  // that every face is relabelled O(log F) times overall.
  void merge(Index a, Index b)
  {
    const bool a_absorbs = faces_[a].size() > faces_[b].size() ||
                           (faces_[a].size() == faces_[b].size() && a < b);
    const Index keep = a_absorbs ? a : b, gone = a_absorbs ? b : a;
    merges_.push_back({{ node_[a], node_[b] }});
    node_[keep] = faces_.size() + merges_.size() - 1;

    for(Index f : faces_[gone]) labels_[f] = keep;
    faces_[keep].insert(faces_[keep].end(), faces_[gone].begin(), faces_[gone].end());
    std::vector<Index>().swap(faces_[gone]);
    area_[keep] += area_[gone];

    shared_length_[keep].erase(gone);
    for(const auto& nl : shared_length_[gone])
    {
      if(nl.first == keep)
        continue;
      shared_length_[keep][nl.first] += nl.second;
      auto& of_neighbor = shared_length_[nl.first];
      of_neighbor.erase(gone);
      of_neighbor[keep] += nl.second;
    }
    std::unordered_map<Index, double>().swap(shared_length_[gone]);

    ++version_[gone];
    ++version_[keep];
    for(const auto& nl : shared_length_[keep])
      push_candidate(keep, nl.first, nl.second);
  }

  const Indexed_triangle_mesh& m_;
  std::vector<Index>& labels_;
  std::vector<std::vector<Index> > faces_;
  std::vector<double> area_;
  std::vector<Index> version_;
  std::vector<std::unordered_map<Index, double> > shared_length_;
  Vertex_faces vertex_faces_;  // by input vertex: to find the vertices two regions share
  std::vector<Index> vertex_mark_;
  Index stamp_ = 0;
  double threshold_ = 0.;
  std::vector<Candidate> heap_;
  std::vector<Index> shared_vertices_, parent_;
  std::vector<std::pair<Index, Index> > shared_edges_;
  std::vector<std::size_t> node_;  // tree node of every live region
  std::vector<std::array<std::size_t, 2> > merges_;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_DISK_REGION_MERGER_H
