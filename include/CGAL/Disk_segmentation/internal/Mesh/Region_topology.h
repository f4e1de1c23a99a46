// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The topology of a region of the indexed mesh, and whether it is a disk,
// in time and memory proportional to the region.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_MESH_REGION_TOPOLOGY_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_MESH_REGION_TOPOLOGY_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_slots.h>

#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Topology of a set of faces ("region") of an Indexed_triangle_mesh.
struct Region_counts
{
  std::size_t vertices = 0, edges = 0, faces = 0;
  std::size_t edge_components = 0;  // components through edges inside the region
  bool joins_split_vertex = false;   // holds two copies of an input vertex split by its fans

  long euler_characteristic() const
  {
    return static_cast<long>(vertices) - static_cast<long>(edges) + static_cast<long>(faces);
  }

  // Cutting the region apart at every vertex where its faces form k >= 2
  // fans (a pinched vertex) gives k - 1 more vertices and a surface S with
  // boundary, orientable since the input is, and as edge-connected as the
  // region: chi(S) = 2 - 2g - b <= 1 (b >= 1: an open fan borders S). So an
  // edge-connected region with a pinched vertex has chi <= 0, and one with
  // chi = 1 has none: S is the region, g = 0 and b = 1, a topological disk.
  // chi = 1 alone is not enough (two triangles touching at one vertex have
  // chi = 1, in two edge components). Copies of a split input vertex are
  // fans cut apart already, possibly of a closed S (chi = 2): flagged.
  bool is_disk() const
  {
    return faces > 0 && edge_components == 1 && !joins_split_vertex && euler_characteristic() == 1;
  }
};

// Counts the topology of regions in time and memory proportional to the
// region, not to the mesh (every chart splitter thread holds one).
class Region_topology
{
public:
  explicit Region_topology(const Indexed_triangle_mesh& m) : m_(m) {}

  const Indexed_triangle_mesh& mesh() const { return m_; }

  // `region` lists distinct face indices.
  Region_counts count(const std::vector<Index>& region)
  {
    Region_counts c;
    c.faces = region.size();
    if(region.empty())
      return c;

    faces_.clear_for_keys(region);
    for(Index f : region)
      faces_.insert(f);
    vertices_.clear_for_corners(m_, region);
    for(std::vector<Index>* scratch : { &neighbor_position_, &stack_ })
      release_if_far_larger(*scratch, 3 * region.size());
    release_if_far_larger(visited_, 3 * region.size());
    neighbor_position_.resize(3 * region.size());

    std::size_t boundary_halfedges = 0;
    for(std::size_t p = 0; p < region.size(); ++p)
    {
      const Index f = region[p];
      for(int i = 0; i < 3; ++i)
      {
        vertices_.insert(m_.corners[f][i]);
        const Index g = m_.neighbors[f][i];
        const Index q = g == no_index ? no_index : faces_.find(g);
        neighbor_position_[3 * p + i] = q;
        if(q == no_index)
          ++boundary_halfedges;
      }
    }
    c.vertices = vertices_.size();
    c.edges = (3 * c.faces + boundary_halfedges) / 2;
    // The copies of a pinched input vertex (one per fan) are one vertex of
    // the input's surface.
    if(!m_.split_from.empty())
    {
      input_vertices_.clear(c.vertices);
      visited_.assign(c.vertices, 0);
      for(Index f : region)
        for(Index v : m_.corners[f])
        {
          unsigned char& seen = visited_[vertices_.find(v)];
          if(seen)
            continue;
          seen = 1;
          // A copy met before leaves the count as it was. (Its number is no
          // test: the latest input vertex met has number size() - 1 too.)
          const std::size_t known = input_vertices_.size();
          input_vertices_.insert(m_.input_vertex(v));
          if(input_vertices_.size() == known)
          {
            c.joins_split_vertex = true;
            --c.vertices;
          }
        }
    }

    c.edge_components = count_edge_components(region.size());
    return c;
  }

  bool is_disk(const std::vector<Index>& region) { return count(region).is_disk(); }

private:
  // Over the region's positions, through neighbor_position_.
  std::size_t count_edge_components(std::size_t n)
  {
    visited_.assign(n, 0);
    std::size_t components = 0;
    for(std::size_t seed = 0; seed < n; ++seed)
    {
      if(visited_[seed])
        continue;
      ++components;
      visited_[seed] = 1;
      stack_.push_back(static_cast<Index>(seed));
      // Each face is pushed once (visited_): at most n passes in all.
      while(!stack_.empty())
      {
        const Index p = stack_.back();
        stack_.pop_back();
        for(int i = 0; i < 3; ++i)
        {
          const Index q = neighbor_position_[3 * p + i];
          if(q != no_index && !visited_[q])
          {
            visited_[q] = 1;
            stack_.push_back(q);
          }
        }
      }
    }
    return components;
  }

  const Indexed_triangle_mesh& m_;
  Region_slots faces_, vertices_, input_vertices_;
  std::vector<Index> neighbor_position_, stack_;
  std::vector<unsigned char> visited_;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_MESH_REGION_TOPOLOGY_H
