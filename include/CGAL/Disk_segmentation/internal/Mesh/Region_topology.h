// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_MESH_REGION_TOPOLOGY_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_MESH_REGION_TOPOLOGY_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>

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

// Counts the topology of regions. Scratch arrays are sized to the mesh once
// and reset only where a region touched them, so that a query costs
// O(region size), not O(mesh size).
class Region_topology
{
public:
  explicit Region_topology(const Indexed_triangle_mesh& m)
    : m_(m),
      face_mark_(m.number_of_faces(), 0),
      vertex_mark_(m.number_of_vertices(), 0),
      faces_at_vertex_(m.number_of_vertices(), 0),
      interior_halfedges_at_vertex_(m.number_of_vertices(), 0)
  {}

  const Indexed_triangle_mesh& mesh() const { return m_; }

  // `region` lists distinct face indices.
  Region_counts count(const std::vector<Index>& region)
  {
    Region_counts c;
    c.faces = region.size();
    if(region.empty())
      return c;

    const Index stamp = next_stamp();
    for(Index f : region)
      face_mark_[f] = stamp;

    // Around a vertex v of a manifold mesh, the region's faces form
    // (faces at v) - (interior edges at v) open fans, or one closed fan when
    // both counts are equal. Each interior edge is seen from both of its
    // faces, hence the halfedge count below is twice the edge count.
    for(Index f : region)
      for(Index v : m_.corners[f])
        if(vertex_mark_[v] != stamp)
        {
          vertex_mark_[v] = stamp;
          faces_at_vertex_[v] = 0;
          interior_halfedges_at_vertex_[v] = 0;
          touched_vertices_.push_back(v);
        }

    std::size_t boundary_halfedges = 0;
    for(Index f : region)
    {
      for(int i = 0; i < 3; ++i)
      {
        ++faces_at_vertex_[m_.corners[f][i]];
        const Index g = m_.neighbors[f][i];
        if(g != no_index && face_mark_[g] == stamp)
        {
          ++interior_halfedges_at_vertex_[m_.corners[f][i]];
          ++interior_halfedges_at_vertex_[m_.corners[f][(i + 1) % 3]];
        }
        else
          ++boundary_halfedges;
      }
    }

    c.vertices = touched_vertices_.size();
    c.edges = (3 * c.faces + boundary_halfedges) / 2;
    for(Index v : touched_vertices_)
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
      if(input_vertex_mark_.empty())
        input_vertex_mark_.assign(m_.number_of_vertices(), 0);
      for(Index v : touched_vertices_)
      {
        Index& mark = input_vertex_mark_[m_.input_vertex(v)];
        if(mark == stamp)
        {
          c.has_pinched_vertex = true;
          --c.vertices;
        }
        mark = stamp;
      }
    }
    touched_vertices_.clear();

    c.edge_components = count_edge_components(region, stamp);
    return c;
  }

  bool is_disk(const std::vector<Index>& region) { return count(region).is_disk(); }

private:
  Index next_stamp()
  {
    if(++stamp_ == 0)
    {
      // Wrapped around after 2^32 queries: forget every old mark.
      std::fill(face_mark_.begin(), face_mark_.end(), 0);
      std::fill(vertex_mark_.begin(), vertex_mark_.end(), 0);
      std::fill(visit_mark_.begin(), visit_mark_.end(), 0);
      std::fill(input_vertex_mark_.begin(), input_vertex_mark_.end(), 0);
      stamp_ = 1;
    }
    return stamp_;
  }

  // Region faces carry `stamp` in face_mark_.
  std::size_t count_edge_components(const std::vector<Index>& region, Index stamp)
  {
    if(visit_mark_.empty())
      visit_mark_.assign(m_.number_of_faces(), 0);
    std::size_t components = 0;
    for(Index seed : region)
    {
      if(visit_mark_[seed] == stamp)
        continue;
      ++components;
      visit_mark_[seed] = stamp;
      stack_.push_back(seed);
      // Each face is pushed once (visit_mark_): at most |region| passes in all.
      while(!stack_.empty())
      {
        const Index f = stack_.back();
        stack_.pop_back();
        for(Index g : m_.neighbors[f])
          if(g != no_index && face_mark_[g] == stamp && visit_mark_[g] != stamp)
          {
            visit_mark_[g] = stamp;
            stack_.push_back(g);
          }
      }
    }
    return components;
  }

  const Indexed_triangle_mesh& m_;
  Index stamp_ = 0;
  std::vector<Index> face_mark_, vertex_mark_, visit_mark_, input_vertex_mark_;
  std::vector<Index> faces_at_vertex_, interior_halfedges_at_vertex_;
  std::vector<Index> touched_vertices_, stack_;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_MESH_REGION_TOPOLOGY_H
