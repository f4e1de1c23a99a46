// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_INDEXED_TRIANGLE_MESH_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_INDEXED_TRIANGLE_MESH_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Kernel/global_functions.h>

#include <boost/graph/graph_traits.hpp>

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

typedef std::uint32_t Index;
constexpr Index no_index = (std::numeric_limits<Index>::max)();

// A triangle mesh flattened into arrays indexed by dense face and vertex
// indices. All algorithms of the package run on it: the hot loops then touch
// contiguous memory, and results do not depend on the input's mesh type.
//
// Each face stores its corners rotated so that the smallest vertex index comes
// first (orientation is kept). Every derived quantity (centroids, midpoints,
// lengths) is therefore computed with the same floating-point operations for
// any FaceGraph model holding the same mesh, which makes results identical on
// Surface_mesh and Polyhedron_3.
struct Indexed_triangle_mesh
{
  std::vector<std::array<Index, 3> > corners;    // face -> vertices (ccw)
  std::vector<std::array<Index, 3> > neighbors;  // face -> face across edge (corner i, corner i+1)
  std::vector<std::array<double, 3> > points;    // vertex -> coordinates
  double normalization_scale = 1;                // points = (input - center) * scale

  std::size_t number_of_faces() const { return corners.size(); }
  std::size_t number_of_vertices() const { return points.size(); }

  const std::array<double, 3>& point(Index f, int i) const { return points[corners[f][i]]; }

  static double distance(const std::array<double, 3>& a, const std::array<double, 3>& b)
  {
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
  }

  std::array<double, 3> centroid(Index f) const
  {
    const auto& a = point(f, 0); const auto& b = point(f, 1); const auto& c = point(f, 2);
    return {{ (a[0] + b[0] + c[0]) / 3., (a[1] + b[1] + c[1]) / 3., (a[2] + b[2] + c[2]) / 3. }};
  }

  // Endpoints of edge i of f, smaller vertex index first, so that both faces
  // of an edge compute bit-identical midpoints and lengths.
  std::pair<Index, Index> edge_vertices(Index f, int i) const
  {
    Index a = corners[f][i], b = corners[f][(i + 1) % 3];
    return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
  }

  double edge_length(Index f, int i) const
  {
    const std::pair<Index, Index> e = edge_vertices(f, i);
    return distance(points[e.first], points[e.second]);
  }

  std::array<double, 3> edge_midpoint(Index f, int i) const
  {
    const std::pair<Index, Index> e = edge_vertices(f, i);
    const auto& a = points[e.first]; const auto& b = points[e.second];
    return {{ (a[0] + b[0]) / 2., (a[1] + b[1]) / 2., (a[2] + b[2]) / 2. }};
  }

  double area(Index f) const
  {
    const auto& a = point(f, 0); const auto& b = point(f, 1); const auto& c = point(f, 2);
    const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
    const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    return 0.5 * std::sqrt(nx * nx + ny * ny + nz * nz);
  }

  // Dual-graph arc length between f and its neighbor across edge i: the path
  // from the centroid of f through the edge midpoint to the neighbor's
  // centroid. It approximates the geodesic distance between the two faces
  // and, unlike centroid-to-centroid distances, follows the surface across
  // sharp dihedral angles.
  double dual_arc_length(Index f, int i) const
  {
    const Index g = neighbors[f][i];
    const std::array<double, 3> m = edge_midpoint(f, i);
    return distance(centroid(f), m) + distance(m, centroid(g));
  }
};

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

    int first = 0;
    for(int i = 1; i < 3; ++i)
      if(vs[i] < vs[first]) first = i;
    out.corners.push_back({{ vs[first], vs[(first + 1) % 3], vs[(first + 2) % 3] }});
    out.neighbors.push_back({{ nbs[first], nbs[(first + 1) % 3], nbs[(first + 2) % 3] }});
    ++face_counter;
  }
}

// Checks what the algorithms rely on beyond triangles: finite coordinates,
// and faces around every vertex forming a single fan (open or closed). The
// halfedge structure reaches only one fan from a vertex, so a vertex whose
// face count differs from the fan reached by circulation, or that meets the
// border twice, is pinched. Vertices without faces are ignored. Only
// meaningful when the indexed mesh covers all faces of `tm`.
template <typename TriangleMesh, typename VertexHandles>
void check_vertices(const TriangleMesh& tm,
                    const VertexHandles& vertex_handles,
                    const Indexed_triangle_mesh& m)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  std::vector<Index> faces_per_vertex(m.number_of_vertices(), 0);
  for(const auto& c : m.corners)
    for(Index v : c) ++faces_per_vertex[v];

  for(std::size_t v = 0; v < vertex_handles.size(); ++v)
  {
    if(faces_per_vertex[v] == 0)
      continue;
    const auto& p = m.points[v];
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw Input_error("the mesh has a non-finite (NaN or infinite) coordinate at vertex #" +
                        std::to_string(v));
    std::size_t fan_faces = 0, border_halfedges = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(vertex_handles[v], tm), tm))
    {
      if(is_border(h, tm)) ++border_halfedges;
      else ++fan_faces;
    }
    if(border_halfedges > 1 || fan_faces != faces_per_vertex[v])
      throw Input_error("the mesh is not manifold: the faces around vertex #" + std::to_string(v) +
                        " form more than one fan; split it first "
                        "(e.g. Polygon_mesh_processing::duplicate_non_manifold_vertices)");
  }
}

// Centers the used vertices and scales them by a power of two so that the
// bounding box's largest side lies in [1, 2). Every algorithm of the package
// is invariant under similarities, and scaling by a power of two is exact,
// so results do not change, while huge (1e30) and tiny (1e-30) meshes meet
// the floating-point ranges of unit-size ones (no overflow of squared
// lengths, no underflow of areas).
inline void normalize_coordinates(Indexed_triangle_mesh& m)
{
  std::array<double, 3> lo{{ std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity() }};
  std::array<double, 3> hi{{ -lo[0], -lo[1], -lo[2] }};
  for(const auto& c : m.corners)
    for(Index v : c)
      for(int k = 0; k < 3; ++k)
      {
        lo[k] = (std::min)(lo[k], m.points[v][k]);
        hi[k] = (std::max)(hi[k], m.points[v][k]);
      }
  const double side = (std::max)(hi[0] - lo[0], (std::max)(hi[1] - lo[1], hi[2] - lo[2]));
  if(!(side > 0) || !std::isfinite(side))
    return;
  int exponent = 0;
  std::frexp(side, &exponent);  // side = f * 2^exponent, f in [0.5, 1)
  const double scale = std::ldexp(1., 1 - exponent);
  const std::array<double, 3> center{{ (lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2 }};
  for(auto& p : m.points)
    for(int k = 0; k < 3; ++k)
      p[k] = (p[k] - center[k]) * scale;
  m.normalization_scale = scale;
}

// Reads vertex coordinates as doubles through the vertex point map and the
// geometric traits of the named parameters. The algorithms need distances
// and areas only as approximations of the geodesic structure, so doubles
// suffice whatever the kernel.
template <typename TriangleMesh, typename NamedParameters>
auto make_coordinates_reader(const TriangleMesh& tm, const NamedParameters& np)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const Geom_traits gt = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  return [vpm, gt](vertex_descriptor v) -> std::array<double, 3>
  {
    const auto& p = get(vpm, v);
    return {{ CGAL::to_double(gt.compute_x_3_object()(p)),
              CGAL::to_double(gt.compute_y_3_object()(p)),
              CGAL::to_double(gt.compute_z_3_object()(p)) }};
  };
}

// The whole of `tm` as an indexed mesh, with the face descriptors in index order.
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
  // faces, which depends on where each face's halfedge starts).
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
  check_vertices(tm, vertex_handles, out);
  normalize_coordinates(out);
  if(vertex_handles_out != nullptr)
    vertex_handles_out->swap(vertex_handles);
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_INDEXED_TRIANGLE_MESH_H
