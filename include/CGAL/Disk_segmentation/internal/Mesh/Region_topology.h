// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

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
  bool has_pinched_vertex = false;   // a vertex whose region faces form >= 2 fans

  long euler_characteristic() const
  {
    return static_cast<long>(vertices) - static_cast<long>(edges) + static_cast<long>(faces);
  }

  // An edge-connected surface without pinched vertex is a 2-manifold with
  // boundary, orientable since the input is; chi = 2 - 2g - b = 1 then forces
  // g = 0 and b = 1: a topological disk. chi = 1 alone is not enough (two
  // triangles touching at one vertex have chi = 1).
  bool is_disk() const
  {
    return faces > 0 && edge_components == 1 && !has_pinched_vertex && euler_characteristic() == 1;
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

    // Around a vertex v of a manifold mesh, the region's faces form
    // (faces at v) - (interior edges at v) open fans, or one closed fan when
    // both counts are equal. Each interior edge is seen from both of its
    // faces, hence the halfedge count below is twice the edge count.
    vertices_.clear_for_corners(m_, region);
    for(std::vector<Index>* scratch : { &touched_vertices_, &faces_at_vertex_, &interior_halfedges_at_vertex_,
                                        &neighbor_position_, &stack_ })
      release_if_far_larger(*scratch, 3 * region.size());
    release_if_far_larger(visited_, region.size());
    touched_vertices_.clear();
    faces_at_vertex_.clear();
    interior_halfedges_at_vertex_.clear();
    neighbor_position_.resize(3 * region.size());
    std::size_t boundary_halfedges = 0;
    for(std::size_t p = 0; p < region.size(); ++p)
    {
      const Index f = region[p];
      Index corner[3];
      for(int i = 0; i < 3; ++i)
      {
        corner[i] = vertices_.insert(m_.corners[f][i]);
        if(corner[i] == touched_vertices_.size())
        {
          touched_vertices_.push_back(m_.corners[f][i]);
          faces_at_vertex_.push_back(0);
          interior_halfedges_at_vertex_.push_back(0);
        }
        ++faces_at_vertex_[corner[i]];
      }
      for(int i = 0; i < 3; ++i)
      {
        const Index g = m_.neighbors[f][i];
        const Index q = g == no_index ? no_index : faces_.find(g);
        neighbor_position_[3 * p + i] = q;
        if(q != no_index)
        {
          ++interior_halfedges_at_vertex_[corner[i]];
          ++interior_halfedges_at_vertex_[corner[(i + 1) % 3]];
        }
        else
          ++boundary_halfedges;
      }
    }

    c.vertices = touched_vertices_.size();
    c.edges = (3 * c.faces + boundary_halfedges) / 2;
    for(std::size_t v = 0; v < touched_vertices_.size(); ++v)
    {
      // Both endpoint counters got one increment per interior halfedge.
      const Index interior_edges = interior_halfedges_at_vertex_[v] / 2;
      if(faces_at_vertex_[v] >= interior_edges + 2)
        c.has_pinched_vertex = true;
    }
    // Each copy of a pinched input vertex is one of its fans: two of them
    // in the region are one input vertex, with two fans.
    if(!m_.split_from.empty())
    {
      input_vertices_.clear(touched_vertices_.size());
      for(Index v : touched_vertices_)
        if(input_vertices_.insert(m_.input_vertex(v)) + 1 != input_vertices_.size())
        {
          c.has_pinched_vertex = true;
          --c.vertices;
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
  std::vector<Index> touched_vertices_, faces_at_vertex_, interior_halfedges_at_vertex_;
  std::vector<Index> neighbor_position_, stack_;
  std::vector<unsigned char> visited_;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_MESH_REGION_TOPOLOGY_H
