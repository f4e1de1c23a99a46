// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The per-corner atlas of a face graph flattened into arrays, shared by the
// atlas writers: mesh vertices, texture vertices (one per mesh vertex and
// chart, or per distinct UV where a chart sees a vertex at two places) and
// faces as lists of (vertex, texture vertex) corners.

#ifndef CGAL_DISK_SEGMENTATION_IO_INTERNAL_ATLAS_CORNERS_H
#define CGAL_DISK_SEGMENTATION_IO_INTERNAL_ATLAS_CORNERS_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/functional/hash.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <cstring>
#include <ios>
#include <locale>
#include <ostream>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {
namespace internal {

// One texture vertex: a mesh vertex seen from one chart at one UV position.
// With UVs continuous inside each chart, there is one per (vertex, chart)
// pair; a vertex that a chart sees at two different UVs (e.g. a chart whose
// border touches itself at that vertex) gets one per UV, so no corner ever
// gets a UV other than its own.
struct Texture_vertex
{
  std::size_t vertex; // index of the mesh vertex, in vertices(mesh) order
  std::size_t chart;
  double u, v;
};

inline bool same_texture_vertex(const Texture_vertex& a, const Texture_vertex& b)
{
  return a.vertex == b.vertex && a.chart == b.chart && a.u == b.u && a.v == b.v;
}

// The mesh flattened into arrays, in the mesh's vertex and face orders.
struct Atlas_corners
{
  std::vector<std::array<double, 3> > points;  // per mesh vertex
  std::vector<std::size_t> face_chart;          // per face
  std::vector<std::size_t> face_begin;          // per face + 1: first corner
  std::vector<std::size_t> corner_vertex;       // per corner: mesh vertex index
  std::vector<std::size_t> corner_texture;      // per corner: texture vertex index
  std::vector<Texture_vertex> textures;         // in order of first use

  std::size_t number_of_faces() const { return face_chart.size(); }
  std::size_t face_size(std::size_t f) const { return face_begin[f + 1] - face_begin[f]; }
};

template <typename Mesh, typename Patch_map, typename UV_map>
Atlas_corners flatten(const Mesh& mesh, const Patch_map& patch, const UV_map& uv)
{
  typedef boost::graph_traits<Mesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  Atlas_corners a;
  const auto vpm = get(CGAL::vertex_point, mesh);
  std::unordered_map<vertex_descriptor, std::size_t, boost::hash<vertex_descriptor> > vertex_index;
  vertex_index.reserve(static_cast<std::size_t>(num_vertices(mesh)));
  for(vertex_descriptor v : vertices(mesh))
  {
    const auto& p = get(vpm, v);
    vertex_index.emplace(v, a.points.size());
    a.points.push_back({{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }});
  }

  // The texture vertices of each mesh vertex, chained through `next_of`
  // from the latest: a vertex has one per chart around it (more only where
  // a chart sees it twice), so the chain is short; a hash map over all the
  // corners took 6 % of the tool's time on 300k faces.
  const std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> latest(a.points.size(), none), next_of;
  a.face_begin.push_back(0);
  for(face_descriptor f : faces(mesh))
  {
    const std::size_t chart = static_cast<std::size_t>(get(patch, f));
    a.face_chart.push_back(chart);
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const std::size_t vi = vertex_index.at(target(h, mesh));
      const auto& t = get(uv, h);
      const Texture_vertex key = { vi, chart, CGAL::to_double(t.x()), CGAL::to_double(t.y()) };
      std::size_t k = latest[vi];
      while(k != none && !same_texture_vertex(a.textures[k], key))
        k = next_of[k];
      if(k == none)
      {
        k = a.textures.size();
        a.textures.push_back(key);
        next_of.push_back(latest[vi]);
        latest[vi] = k;
      }
      a.corner_vertex.push_back(vi);
      a.corner_texture.push_back(k);
    }
    a.face_begin.push_back(a.corner_vertex.size());
  }
  return a;
}

// Restores the formatting state of a stream when leaving a scope.
class Stream_state_saver
{
public:
  explicit Stream_state_saver(std::ostream& out)
    : out_(out), flags_(out.flags()), precision_(out.precision()), locale_(out.getloc())
  {}
  ~Stream_state_saver()
  {
    out_.flags(flags_);
    out_.precision(precision_);
    out_.imbue(locale_);
  }
  Stream_state_saver(const Stream_state_saver&) = delete;
  Stream_state_saver& operator=(const Stream_state_saver&) = delete;

private:
  std::ostream& out_;
  std::ios_base::fmtflags flags_;
  std::streamsize precision_;
  std::locale locale_;
};

template <typename T>
void append_bytes(std::vector<unsigned char>& buffer, const std::vector<T>& values)
{
  const std::size_t bytes = values.size() * sizeof(T);
  const std::size_t offset = buffer.size();
  buffer.resize(offset + bytes);
  if(bytes != 0)
    std::memcpy(buffer.data() + offset, values.data(), bytes);
}

inline void write_to_ostream(void* context, void* data, int size)
{
  static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), std::streamsize(size));
}

} // namespace internal
} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_INTERNAL_ATLAS_CORNERS_H
