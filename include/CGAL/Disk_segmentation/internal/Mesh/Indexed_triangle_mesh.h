// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Builds the indexed triangle mesh from a FaceGraph, whole or a range of
// its faces, reading the coordinates through the named parameters.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_MESH_INDEXED_TRIANGLE_MESH_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_MESH_INDEXED_TRIANGLE_MESH_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Coordinate_normalization.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Face_group_cuts.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh_type.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Morton_order.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Pinched_vertex_splitting.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Kernel/global_functions.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Builds the faces of the indexed mesh from the faces in `face_range` of
// `tm`. Faces of the range get indices 0..n-1 in range order; `face_index`
// must map each of them to that index (`no_index` for faces outside the
// range). `vertex_index(v)` gives the dense index of v, or `no_index` for a
// vertex not yet in `out.points`: such a vertex is appended and numbered by
// `vertex_index.assign(v, i)`.
//
// Throws Input_error on a face that is not a triangle.
template <typename TriangleMesh, typename FaceRange, typename CoordinatesOf,
          typename FaceIndexOf, typename VertexIndexOf>
void build_indexed_triangle_mesh(const TriangleMesh& tm,
                                 const FaceRange& face_range,
                                 const CoordinatesOf& coordinates_of,
                                 const FaceIndexOf& face_index,
                                 VertexIndexOf& vertex_index,
                                 std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertex_handles,
                                 Indexed_triangle_mesh& out)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  out.corners.clear();
  out.neighbors.clear();

  std::size_t face_counter = 0;
  for(face_descriptor f : face_range)
  {
    std::array<Index, 3> vs;
    std::array<Index, 3> nbs;
    int n = 0;
    // At most four steps: the fourth halfedge throws.
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
    {
      if(n == 3)
        throw Input_error("the mesh has a face with more than three vertices (face #" +
                          std::to_string(face_counter) + "); triangulate it first");
      const vertex_descriptor v = source(h, tm);
      Index vi = vertex_index(v);
      if(vi == no_index)
      {
        vi = static_cast<Index>(out.points.size());
        vertex_index.assign(v, vi);
        out.points.push_back(coordinates_of(v));
        vertex_handles.push_back(v);
      }
      vs[n] = vi;
      // Edge (source(h), target(h)) is edge n of the face.
      const halfedge_descriptor o = opposite(h, tm);
      nbs[n] = is_border(o, tm) ? no_index : face_index(face(o, tm));
      ++n;
    }
    if(n != 3)
      throw Input_error("the mesh has a face with fewer than three vertices (face #" +
                        std::to_string(face_counter) + ")");

    put_smallest_vertex_first(vs, nbs);
    out.corners.push_back(vs);
    out.neighbors.push_back(nbs);
    ++face_counter;
  }
}

// Reads vertex coordinates as doubles through the vertex point map and the
// geometric traits of the named parameters. The algorithms need distances
// and areas only as approximations of the geodesic structure, so doubles
// suffice whatever the kernel.
template <typename TriangleMesh, typename NamedParameters>
auto make_coordinates_reader(const TriangleMesh& tm, const NamedParameters& np)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type Vertex_point_map;
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point;
  static_assert(is_kernel_point<Point>::value,
                "CGAL::Disk_segmentation: the vertex point map's value type must be a CGAL point with a "
                "kernel (e.g. Kernel::Point_3), not a plain array or a user type");
  // Without a kernel nothing below compiles; leaving it out keeps the
  // static_assert the only error.
  if constexpr(is_kernel_point<Point>::value)
  {
    typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    const auto vpm = vertex_point_map_parameter(tm, np);
    const Geom_traits gt = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
    return [vpm, gt](vertex_descriptor v) -> std::array<double, 3>
    {
      const auto& p = get(vpm, v);
      return {{ CGAL::to_double(gt.compute_x_3_object()(p)),
                CGAL::to_double(gt.compute_y_3_object()(p)),
                CGAL::to_double(gt.compute_z_3_object()(p)) }};
    };
  }
  else
    return [](vertex_descriptor) { return std::array<double, 3>{{ 0., 0., 0. }}; };
}

// The whole of `tm` as an indexed mesh, faces and vertices renumbered along
// the surface (see renumber_for_locality()), with the face descriptors in
// index order.
// `vertex_handles`, when given, receives the vertex descriptors in index order.
template <typename TriangleMesh, typename NamedParameters>
void build_indexed_triangle_mesh(const TriangleMesh& tm,
                                 const NamedParameters& np,
                                 Indexed_triangle_mesh& out,
                                 std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_handles,
                                 std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>* vertex_handles_out = nullptr)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  if(faces(tm).empty())
    throw Input_error("the mesh has no face");

  const auto coordinates_of = make_coordinates_reader(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);

  face_handles.clear();
  face_handles.reserve(num_faces(tm));
  // The face index map is used only to name faces: indices follow the range
  // order, so that indices are dense even when the map is not.
  std::vector<Index> dense_face(num_faces(tm), no_index);
  bool dense = true;
  Index counter = 0;
  for(face_descriptor f : faces(tm))
  {
    const std::size_t i = static_cast<std::size_t>(get(fim, f));
    if(i >= dense_face.size() || dense_face[i] != no_index) { dense = false; break; }
    dense_face[i] = counter++;
    face_handles.push_back(f);
  }
  if(!dense)
    throw Input_error("the face index map is not a bijection onto [0, number of faces)");

  // Vertices are numbered in range order (not in order of appearance in
  // faces, which depends on where each face's halfedge starts); faces
  // rotate their corners by it, then both are renumbered along the surface.
  std::vector<Index> dense_vertex(num_vertices(tm), no_index);
  std::vector<vertex_descriptor> vertex_handles;
  vertex_handles.reserve(num_vertices(tm));
  out.points.clear();
  out.points.reserve(num_vertices(tm));
  for(vertex_descriptor v : vertices(tm))
  {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    if(i >= dense_vertex.size() || dense_vertex[i] != no_index)
      throw Input_error("the vertex index map is not a bijection onto [0, number of vertices)");
    dense_vertex[i] = static_cast<Index>(vertex_handles.size());
    vertex_handles.push_back(v);
    out.points.push_back(coordinates_of(v));
  }

  auto face_index_of = [&](face_descriptor f) { return dense_face[static_cast<std::size_t>(get(fim, f))]; };
  struct Vertex_index_of
  {
    const decltype(vim)& map; const std::vector<Index>& dense;
    Index operator()(vertex_descriptor v) const { return dense[static_cast<std::size_t>(get(map, v))]; }
    void assign(vertex_descriptor, Index) const { CGAL_assertion(false); }
  } vertex_index_of{vim, dense_vertex};

  std::vector<vertex_descriptor> no_new_vertex;
  build_indexed_triangle_mesh(tm, faces(tm), coordinates_of, face_index_of, vertex_index_of, no_new_vertex, out);
  check_and_split_vertices(tm, vertex_handles, out);
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters,
                                                       Disk_segmentation::internal_np::face_material_map_t>::value)
  {
    const auto materials =
      checked_face_group_map<TriangleMesh>(get_parameter(np, Disk_segmentation::internal_np::face_material_map));
    typedef typename boost::property_traits<std::decay_t<decltype(materials)> >::value_type Material;
    std::vector<Material> material;
    material.reserve(face_handles.size());
    for(face_descriptor f : face_handles)
      material.push_back(get(materials, f));
    cut_between_face_groups(material, vertex_handles, out);
  }
  renumber_for_locality(out, face_handles, vertex_handles);
  normalize_coordinates(out);
  out.crease_penalty = crease_penalty_parameter(np);
  if(vertex_handles_out != nullptr)
    vertex_handles_out->swap(vertex_handles);
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_MESH_INDEXED_TRIANGLE_MESH_H
