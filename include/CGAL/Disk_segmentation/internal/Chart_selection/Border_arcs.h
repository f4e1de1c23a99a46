// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The borders between the regions of a face labeling, cut into arcs from
// junction to junction, and the edge lookups the rerouting of arcs shares.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_BORDER_ARCS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_BORDER_ARCS_H

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Vertex_faces.h>

#include <algorithm>
#include <cstdint>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// A maximal path of edges between two regions `a` and `b`, from one
// junction vertex to another (a vertex on a third region, on the mesh's
// border, or where the border branches).
struct Border_arc
{
  Index a = no_index, b = no_index;
  std::vector<Index> vertices;
  double length = 0.;
};

// A rerouted arc: the faces that changed region, and the region each had.
struct Arc_change
{
  Index a = no_index, b = no_index;
  std::vector<std::pair<Index, Index> > old_labels;
};

// The borders between the regions of a face labeling (per face, a region
// or `no_index`) as the rerouting sees them: which edges separate two
// regions, which vertices are junctions, and the faces on each side of an
// edge.
class Region_borders
{
public:
  explicit Region_borders(const Indexed_triangle_mesh& m) : m_(m), vertex_faces_(m) {}

  const Indexed_triangle_mesh& mesh() const { return m_; }
  const Vertex_faces& vertex_faces() const { return vertex_faces_; }

  // The arcs between regions given by `labels` (per face; `no_index` for
  // faces that belong to none), in a deterministic order. Closed borders
  // without a junction are left out: they have no ends to join.
  std::vector<Border_arc> arcs(const std::vector<Index>& labels) const
  {
    const std::size_t nv = m_.number_of_vertices();
    // Edges between two labeled regions, per vertex.
    std::vector<Index> begin(nv + 1, 0);
    for(Index f = 0; f < m_.number_of_faces(); ++f)
      for(int e = 0; e < 3; ++e)
        if(separates(labels, f, e))
        {
          ++begin[m_.corners[f][e] + 1];
          ++begin[m_.corners[f][(e + 1) % 3] + 1];
        }
    for(std::size_t v = 0; v < nv; ++v)
      begin[v + 1] += begin[v];
    std::vector<Index> other(begin[nv]), fill(begin.begin(), begin.end() - 1);
    for(Index f = 0; f < m_.number_of_faces(); ++f)
      for(int e = 0; e < 3; ++e)
        if(separates(labels, f, e))
        {
          const Index u = m_.corners[f][e], w = m_.corners[f][(e + 1) % 3];
          other[fill[u]++] = w;
          other[fill[w]++] = u;
        }
    // A border vertex is a junction unless it has exactly two border edges
    // and only the two regions around it.
    std::vector<char> junction(nv, 0);
    for(Index v = 0; v < nv; ++v)
    {
      const Index border_edges = begin[v + 1] - begin[v];
      junction[v] = border_edges != 0 && (border_edges != 2 || !inside_two_regions(labels, v)) ? 1 : 0;
    }

    std::vector<Border_arc> result;
    std::unordered_set<std::uint64_t> walked;
    for(Index s = 0; s < nv; ++s)
    {
      if(!junction[s] || begin[s] == begin[s + 1])
        continue;
      for(Index k = begin[s]; k < begin[s + 1]; ++k)
      {
        Index from = s, to = other[k];
        if(walked.count(edge_key(from, to)) != 0)
          continue;
        Border_arc arc;
        regions_of_edge(labels, from, to, arc.a, arc.b);
        arc.vertices.push_back(from);
        for(;;)
        {
          walked.insert(edge_key(from, to));
          arc.length += Indexed_triangle_mesh::distance(m_.points[from], m_.points[to]);
          arc.vertices.push_back(to);
          if(junction[to])
            break;
          const Index next = other[begin[to]] == from ? other[begin[to] + 1] : other[begin[to]];
          from = to;
          to = next;
        }
        if(arc.vertices.front() != arc.vertices.back() && arc.a != no_index && arc.b != no_index)
          result.push_back(std::move(arc));
      }
    }
    return result;
  }

  static std::uint64_t edge_key(Index u, Index w)
  {
    return u < w ? (std::uint64_t(u) << 32 | w) : (std::uint64_t(w) << 32 | u);
  }

  // The faces f on the left (counterclockwise) and g on the right of the
  // edge from u to w: false on the mesh's border or if it is no edge.
  bool directed_faces(Index u, Index w, Index& f, Index& g) const
  {
    for(Index k = vertex_faces_.begin[u]; k < vertex_faces_.begin[u + 1]; ++k)
    {
      f = vertex_faces_.faces[k];
      for(int e = 0; e < 3; ++e)
        if(m_.corners[f][e] == u && m_.corners[f][(e + 1) % 3] == w)
        {
          g = m_.neighbors[f][e];
          return g != no_index;
        }
    }
    return false;
  }

  // The faces on both sides of the edge (u, w): false if it has only one
  // (on the mesh's border) or is not an edge.
  bool faces_of_edge(Index u, Index w, Index& f, Index& g) const
  {
    return directed_faces(u, w, f, g) || directed_faces(w, u, f, g);
  }

  // Whether f has a border edge of the mesh at its corner v.
  bool on_mesh_border_at(Index f, Index v) const
  {
    for(int e = 0; e < 3; ++e)
      if(m_.neighbors[f][e] == no_index && (m_.corners[f][e] == v || m_.corners[f][(e + 1) % 3] == v))
        return true;
    return false;
  }

private:
  // Whether edge e of f lies between two different labeled regions (seen
  // from the face of smaller index only).
  bool separates(const std::vector<Index>& labels, Index f, int e) const
  {
    const Index g = m_.neighbors[f][e];
    return g != no_index && f < g && labels[f] != no_index && labels[g] != no_index && labels[f] != labels[g];
  }

  // Whether every face around v belongs to one of at most two regions (all
  // labeled) and v is not on the mesh's border.
  bool inside_two_regions(const std::vector<Index>& labels, Index v) const
  {
    Index first = no_index, second = no_index;
    for(Index k = vertex_faces_.begin[v]; k < vertex_faces_.begin[v + 1]; ++k)
    {
      const Index f = vertex_faces_.faces[k];
      const Index l = labels[f];
      if(l == no_index || on_mesh_border_at(f, v))
        return false;
      if(l == first || l == second)
        continue;
      if(first == no_index)
        first = l;
      else if(second == no_index)
        second = l;
      else
        return false;
    }
    return true;
  }

  // The regions on both sides of the edge (u, w), smaller first.
  void regions_of_edge(const std::vector<Index>& labels, Index u, Index w, Index& a, Index& b) const
  {
    a = b = no_index;
    Index f, g;
    if(!faces_of_edge(u, w, f, g))
      return;
    a = (std::min)(labels[f], labels[g]);
    b = (std::max)(labels[f], labels[g]);
  }

  const Indexed_triangle_mesh& m_;
  Vertex_faces vertex_faces_;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_CHART_SELECTION_BORDER_ARCS_H
