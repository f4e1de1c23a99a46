// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_MESH_INDEXED_TRIANGLE_MESH_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_MESH_INDEXED_TRIANGLE_MESH_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
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
  // Each connected component has its own frame (see normalize_coordinates):
  // its lengths times `component_unit` are in the units shared by all
  // components, which are the input's times `normalization_scale`. Empty
  // vectors: one frame for the whole mesh.
  std::vector<Index> face_component;             // face -> component
  std::vector<double> component_unit;            // component -> power of two <= 1
  double normalization_scale = 1;
  // Faces are renumbered along the surface (see renumber_for_locality()):
  // face -> its position in the input's face range. Empty: the same.
  std::vector<Index> input_face;
  // A pinched vertex of the input is one vertex per fan here (see
  // split_pinched_vertex()): vertex -> the one that stands for its input
  // vertex, so that topology is judged on the input. Empty: itself.
  std::vector<Index> split_from;
  // Dual arcs across an edge whose faces' normals make an angle theta are
  // 1 + crease_penalty (1 - cos theta) times longer (see dual_arc_length()).
  double crease_penalty = 0;

  std::size_t number_of_faces() const { return corners.size(); }
  std::size_t input_position(Index f) const { return input_face.empty() ? f : input_face[f]; }
  Index input_vertex(Index v) const { return split_from.empty() ? v : split_from[v]; }
  std::size_t number_of_vertices() const { return points.size(); }

  // What lengths of face f are multiplied by to compare them across components.
  double common_unit(Index f) const { return face_component.empty() ? 1. : component_unit[face_component[f]]; }

  const std::array<double, 3>& point(Index f, int i) const { return points[corners[f][i]]; }

  // Whether every corner of `faces` (not empty) is at one point: there all
  // arcs have length zero, distances tie everywhere, and Voronoi cells could
  // only peel a few faces off per split (quadratic on 10^5 such faces).
  bool at_one_point(const std::vector<Index>& faces) const
  {
    const std::array<double, 3>& p = point(faces.front(), 0);
    for(Index f : faces)
      for(int i = 0; i < 3; ++i)
        if(point(f, i) != p)
          return false;
    return true;
  }

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
    const std::array<double, 3> n = normal_vector(f);
    return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }

  // Area in the units shared by all components (see common_unit()).
  double common_area(Index f) const
  {
    const double unit = common_unit(f);
    return area(f) * unit * unit;
  }

  double total_common_area() const
  {
    double sum = 0.;
    for(std::size_t f = 0; f < corners.size(); ++f)
      sum += common_area(static_cast<Index>(f));
    return sum;
  }

  // Dual-graph arc length between f and its neighbor across edge i: the path
  // from the centroid of f through the edge midpoint to the neighbor's
  // centroid. It approximates the geodesic distance between the two faces
  // and, unlike centroid-to-centroid distances, follows the surface across
  // sharp dihedral angles.
  double dual_arc_length(Index f, int i) const { return dual_arc_length(f, i, centroid(f)); }

  // The same, with f's centroid given (a face's three arcs share it).
  double dual_arc_length(Index f, int i, const std::array<double, 3>& centroid_of_f) const
  {
    const Index g = neighbors[f][i];
    const std::array<double, 3> m = edge_midpoint(f, i);
    const double length = distance(centroid_of_f, m) + distance(m, centroid(g));
    return crease_penalty > 0 ? length * (1 + crease_penalty * (1 - normal_cosine(f, g))) : length;
  }

  // The cosine of the angle between the normals of faces f and g (1 if
  // either is degenerate).
  double normal_cosine(Index f, Index g) const
  {
    const std::array<double, 3> a = normal_vector(f), b = normal_vector(g);
    const double la = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    if(!(la > 0) || !(lb > 0))
      return 1;
    return (std::max)(-1., (std::min)(1., (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (la * lb)));
  }

  // Twice the area vector of face f.
  std::array<double, 3> normal_vector(Index f) const
  {
    const auto& a = point(f, 0); const auto& b = point(f, 1); const auto& c = point(f, 2);
    const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
    return {{ uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx }};
  }
};

// Rotates a face's corners, and its neighbors alike, so that its smallest
// vertex index comes first (see Indexed_triangle_mesh); orientation is kept.
inline void put_smallest_vertex_first(std::array<Index, 3>& corners, std::array<Index, 3>& neighbors)
{
  const int first = int(std::min_element(corners.begin(), corners.end()) - corners.begin());
  std::rotate(corners.begin(), corners.begin() + first, corners.end());
  std::rotate(neighbors.begin(), neighbors.begin() + first, neighbors.end());
}

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

// Gives each fan of faces around a pinched vertex `v` but the first (in face
// order) a copy of `v`: same position, same descriptor in `vertex_handles`.
// `around` lists the corners (face, position) at `v` in increasing face
// order. Fans are found across the edges at `v`, through `m.neighbors`.
template <typename VertexHandles>
void split_pinched_vertex(Index v,
                          const std::vector<std::pair<Index, int> >& around,
                          VertexHandles& vertex_handles,
                          Indexed_triangle_mesh& m)
{
  std::vector<bool> reached(around.size(), false);
  auto position_of = [&around](Index f) {
    return std::size_t(std::lower_bound(around.begin(), around.end(), std::make_pair(f, 0)) - around.begin());
  };
  std::vector<std::size_t> stack;
  bool first_fan = true;
  for(std::size_t start = 0; start < around.size(); ++start)
  {
    if(reached[start])
      continue;
    Index copy = v;
    if(!first_fan)
    {
      copy = static_cast<Index>(m.points.size());
      const std::array<double, 3> p = m.points[v];
      if(m.split_from.empty())
      {
        m.split_from.resize(m.points.size());
        for(std::size_t i = 0; i < m.split_from.size(); ++i)
          m.split_from[i] = Index(i);
      }
      m.points.push_back(p);
      m.split_from.push_back(m.split_from[v]);
      vertex_handles.push_back(vertex_handles[v]);
    }
    first_fan = false;
    reached[start] = true;
    stack.assign(1, start);
    // Each corner is pushed once (`reached`): at most around.size() passes in all.
    while(!stack.empty())
    {
      const std::pair<Index, int> corner = around[stack.back()];
      stack.pop_back();
      m.corners[corner.first][corner.second] = copy;
      // The two edges of the face at v: (v, next) and (previous, v).
      for(int edge : { corner.second, (corner.second + 2) % 3 })
      {
        const Index g = m.neighbors[corner.first][edge];
        if(g == no_index)
          continue;
        const std::size_t q = position_of(g);
        if(q < around.size() && around[q].first == g && !reached[q])
        {
          reached[q] = true;
          stack.push_back(q);
        }
      }
    }
  }
}

// split_pinched_vertex() for each of `vertices` (`slot[v]` is v's position
// in it, `no_index` for the other vertices), with one pass over the faces.
template <typename VertexHandles>
void split_into_fans(const std::vector<Index>& vertices, const std::vector<Index>& slot,
                     VertexHandles& vertex_handles, Indexed_triangle_mesh& m)
{
  if(vertices.empty())
    return;
  std::vector<std::vector<std::pair<Index, int> > > around(vertices.size());
  for(Index f = 0; f < m.number_of_faces(); ++f)
    for(int i = 0; i < 3; ++i)
      if(slot[m.corners[f][i]] != no_index)
        around[slot[m.corners[f][i]]].emplace_back(f, i);
  for(std::size_t i = 0; i < vertices.size(); ++i)
    split_pinched_vertex(vertices[i], around[i], vertex_handles, m);
  // Faces keep their smallest vertex first (see Indexed_triangle_mesh).
  for(const auto& corners_at_vertex : around)
    for(const std::pair<Index, int>& corner : corners_at_vertex)
      put_smallest_vertex_first(m.corners[corner.first], m.neighbors[corner.first]);
}

// Checks what the algorithms rely on beyond triangles: finite coordinates.
// The faces around a vertex must form one fan (open or closed) for the
// algorithms; a pinched vertex, whose faces form several, is split in the
// indexed mesh (one vertex per fan, see split_pinched_vertex): the mesh is
// then cut there, as an atlas cuts it anyway, and `tm` is left as it is.
// The halfedge structure reaches only one fan from a vertex, so a vertex
// whose face count differs from the fan reached by circulation, or that
// meets the border twice, is pinched. Vertices without faces are ignored.
// Only meaningful when the indexed mesh covers all faces of `tm`. Returns the
// number of vertices added.
template <typename TriangleMesh, typename VertexHandles>
std::size_t check_and_split_vertices(const TriangleMesh& tm,
                                     VertexHandles& vertex_handles,
                                     Indexed_triangle_mesh& m)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  const std::size_t number_of_vertices = m.number_of_vertices();
  std::vector<Index> faces_per_vertex(number_of_vertices, 0);
  for(const auto& c : m.corners)
    for(Index v : c) ++faces_per_vertex[v];

  std::vector<Index> pinched_slot(number_of_vertices, no_index);
  std::vector<Index> pinched;
  for(std::size_t v = 0; v < number_of_vertices; ++v)
  {
    if(faces_per_vertex[v] == 0)
      continue;
    const auto& p = m.points[v];
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw Input_error("the mesh has a non-finite (NaN or infinite) coordinate at vertex #" +
                        std::to_string(v));
    std::size_t fan_faces = 0, border_halfedges = 0;
    // Ends: in a valid halfedge graph the circulation returns to its start
    // after the halfedges of one fan at v.
    for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(vertex_handles[v], tm), tm))
    {
      if(is_border(h, tm)) ++border_halfedges;
      else ++fan_faces;
    }
    if(border_halfedges > 1 || fan_faces != faces_per_vertex[v])
    {
      pinched_slot[v] = static_cast<Index>(pinched.size());
      pinched.push_back(static_cast<Index>(v));
    }
  }
  split_into_fans(pinched, pinched_slot, vertex_handles, m);
  return m.number_of_vertices() - number_of_vertices;
}

// Faces of different groups (`group[f]`, e.g. materials) never share a
// chart: the indexed mesh is cut along the edges between them (no neighbor
// across), as if they were borders, and a vertex on such an edge gets one
// copy per fan left around it (see split_pinched_vertex()), so that every
// pass of the package sees the groups as separate surfaces. Returns the
// number of vertices added.
template <typename Group, typename VertexHandles>
std::size_t cut_between_face_groups(const std::vector<Group>& group, VertexHandles& vertex_handles,
                                    Indexed_triangle_mesh& m)
{
  const std::size_t number_of_vertices = m.number_of_vertices();
  std::vector<Index> cut_slot(number_of_vertices, no_index);
  std::vector<Index> cut_vertices;
  for(Index f = 0; f < m.number_of_faces(); ++f)
    for(int i = 0; i < 3; ++i)
    {
      const Index g = m.neighbors[f][i];
      if(g == no_index || group[f] == group[g])
        continue;
      m.neighbors[f][i] = no_index;
      for(Index v : { m.corners[f][i], m.corners[f][(i + 1) % 3] })
        if(cut_slot[v] == no_index)
        {
          cut_slot[v] = static_cast<Index>(cut_vertices.size());
          cut_vertices.push_back(v);
        }
    }
  split_into_fans(cut_vertices, cut_slot, vertex_handles, m);
  return m.number_of_vertices() - number_of_vertices;
}

// Spreads the low 21 bits of x three bits apart (bit i to bit 3i).
inline std::uint64_t spread_bits_by_three(std::uint64_t x)
{
  x &= 0x1fffffull;
  x = (x | (x << 32)) & 0x1f00000000ffffull;
  x = (x | (x << 16)) & 0x1f0000ff0000ffull;
  x = (x | (x << 8)) & 0x100f00f00f00f00full;
  x = (x | (x << 4)) & 0x10c30c30c30c30c3ull;
  x = (x | (x << 2)) & 0x1249249249249249ull;
  return x;
}

// Renumbers faces along a Morton (Z-order) curve of their centroids, and
// vertices in order of first use by the renumbered faces: faces close on
// the surface get close indices. Every pass of the package goes over
// regions in index order and reads their vertices; in a file's own order a
// compact region can be spread over the whole index range (CGAL's Loop
// step keeps one child of face i at i and appends the other three, so
// after L levels a patch lies in 2^L distant ranges). The order depends on
// the geometry and on the input order only among faces of one cell of the
// curve (2^-21 of the bounding box), so atlases barely depend on how the
// file lists its faces. `face_handles` and `vertex_handles` are permuted
// alike. Needs finite coordinates (see check_and_split_vertices).
template <typename FaceHandles, typename VertexHandles>
void renumber_for_locality(Indexed_triangle_mesh& m, FaceHandles& face_handles, VertexHandles& vertex_handles)
{
  constexpr double infinity = std::numeric_limits<double>::infinity();
  const std::size_t nf = m.number_of_faces(), nv = m.number_of_vertices();
  std::array<double, 3> lo{{ infinity, infinity, infinity }}, hi{{ -infinity, -infinity, -infinity }};
  for(const auto& c : m.corners)
    for(Index v : c)
      for(int k = 0; k < 3; ++k)
      {
        lo[k] = (std::min)(lo[k], m.points[v][k]);
        hi[k] = (std::max)(hi[k], m.points[v][k]);
      }
  // Halves first: the box of coordinates near the double range's ends
  // would overflow its side.
  std::array<double, 3> cells_per_half_unit;
  for(int k = 0; k < 3; ++k)
  {
    const double half_side = hi[k] / 2 - lo[k] / 2;
    cells_per_half_unit[k] = half_side > 0 ? double(1u << 21) / half_side : 0.;
  }
  std::vector<std::pair<std::uint64_t, Index> > key(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    std::uint64_t code = 0;
    for(int k = 0; k < 3; ++k)
    {
      const double sum = m.point(Index(f), 0)[k] / 6 + m.point(Index(f), 1)[k] / 6 + m.point(Index(f), 2)[k] / 6;
      // A subnormal box side makes the scale infinite: clamp before converting.
      const double cell = (sum - lo[k] / 2) * cells_per_half_unit[k];
      const double clamped = cell >= 0 ? (std::min)(cell, double((1u << 21) - 1)) : 0.;
      code |= spread_bits_by_three(std::uint64_t(clamped)) << k;
    }
    key[f] = std::make_pair(code, Index(f));
  }
  std::sort(key.begin(), key.end());

  std::vector<Index> new_face(nf);
  for(std::size_t i = 0; i < nf; ++i)
    new_face[key[i].second] = Index(i);
  std::vector<Index> new_vertex(nv, no_index);
  std::vector<Index> old_vertex;
  old_vertex.reserve(nv);
  for(std::size_t i = 0; i < nf; ++i)
    for(Index v : m.corners[key[i].second])
      if(new_vertex[v] == no_index)
      {
        new_vertex[v] = Index(old_vertex.size());
        old_vertex.push_back(v);
      }
  for(std::size_t v = 0; v < nv; ++v)  // vertices of no face, last
    if(new_vertex[v] == no_index)
    {
      new_vertex[v] = Index(old_vertex.size());
      old_vertex.push_back(Index(v));
    }

  std::vector<std::array<Index, 3> > corners(nf), neighbors(nf);
  FaceHandles faces_in_order;
  faces_in_order.reserve(nf);
  for(std::size_t i = 0; i < nf; ++i)
  {
    const Index f = key[i].second;
    for(int j = 0; j < 3; ++j)
    {
      corners[i][j] = new_vertex[m.corners[f][j]];
      neighbors[i][j] = m.neighbors[f][j] == no_index ? no_index : new_face[m.neighbors[f][j]];
    }
    put_smallest_vertex_first(corners[i], neighbors[i]);
    faces_in_order.push_back(face_handles[f]);
  }
  m.corners.swap(corners);
  m.neighbors.swap(neighbors);
  face_handles.swap(faces_in_order);
  m.input_face.resize(nf);
  for(std::size_t i = 0; i < nf; ++i)
    m.input_face[i] = key[i].second;

  std::vector<std::array<double, 3> > points(nv);
  VertexHandles vertices_in_order;
  vertices_in_order.reserve(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    points[i] = m.points[old_vertex[i]];
    vertices_in_order.push_back(vertex_handles[old_vertex[i]]);
  }
  m.points.swap(points);
  vertex_handles.swap(vertices_in_order);
  if(!m.split_from.empty())
  {
    // The copies of an input vertex all stand for the first of them.
    std::vector<Index> split_from(nv, no_index);
    std::vector<Index> stands_for(nv, no_index);  // old representative -> new one
    for(std::size_t i = 0; i < nv; ++i)
    {
      Index& first = stands_for[m.split_from[old_vertex[i]]];
      if(first == no_index)
        first = Index(i);
      split_from[i] = first;
    }
    m.split_from.swap(split_from);
  }
}

// A power of two 2^k such that `side` * 2^k lies in [1, 2), k bounded so
// that 2^k stays finite for a subnormal side; 1 for a zero or non-finite side.
inline double unit_scale(double side)
{
  if(!(side > 0) || !std::isfinite(side))
    return 1.;
  int exponent = 0;
  std::frexp(side, &exponent);  // side = f * 2^exponent, f in [0.5, 1)
  return std::ldexp(1., (std::min)(1 - exponent, std::numeric_limits<double>::max_exponent - 1));
}

// Centers each connected component of the used vertices and scales it by a
// power of two so that its bounding box side lies in [1, 2). Every
// algorithm of the package is invariant under similarities, and scaling by
// a power of two is exact, so results do not change, while huge (1e30) and
// tiny (1e-30) meshes meet the floating-point ranges of unit-size ones (no
// overflow of squared lengths, no underflow of areas). Each component gets
// its own frame because nothing relates positions across components, while
// one shared frame would lose a component much smaller than the mesh: a
// shared center rounds its shape away (a 1e-20 wide copy next to a 1e20
// wide one collapses to a point), a shared scale underflows its squared
// lengths and areas (a 1e-150 wide one next to a 1e150 wide one). Where
// sizes are compared across components (farthest-point seeds, atlas
// totals), `Indexed_triangle_mesh::common_unit` brings them to the frame of
// the largest component.
inline void normalize_coordinates(Indexed_triangle_mesh& m)
{
  constexpr double infinity = std::numeric_limits<double>::infinity();
  const std::size_t nv = m.number_of_vertices();
  m.face_component.clear();
  m.component_unit.clear();
  // Union-find over the corners: vertex -> component root.
  std::vector<Index> parent(nv);
  for(std::size_t v = 0; v < nv; ++v)
    parent[v] = static_cast<Index>(v);
  // Ends: a non-root's parent is a smaller index (unions link the larger root
  // to the smaller), so v strictly decreases.
  auto find = [&parent](Index v) {
    while(parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for(const auto& c : m.corners)
    for(int i = 1; i < 3; ++i)
    {
      const Index a = find(c[0]), b = find(c[i]);
      if(a != b)
        parent[(std::max)(a, b)] = (std::min)(a, b);
    }

  // Components numbered in order of first corner; bounding box of each.
  std::vector<std::array<double, 6> > box;  // lo, hi
  std::vector<Index> component_of_root(nv, no_index);
  for(const auto& c : m.corners)
    for(Index v : c)
    {
      Index& b = component_of_root[find(v)];
      if(b == no_index)
      {
        b = static_cast<Index>(box.size());
        box.push_back({{ infinity, infinity, infinity, -infinity, -infinity, -infinity }});
      }
      for(int k = 0; k < 3; ++k)
      {
        box[b][k] = (std::min)(box[b][k], m.points[v][k]);
        box[b][k + 3] = (std::max)(box[b][k + 3], m.points[v][k]);
      }
    }
  std::vector<double> side(box.size());
  double largest = 0;
  for(std::size_t b = 0; b < box.size(); ++b)
  {
    side[b] = (std::max)(box[b][3] - box[b][0], (std::max)(box[b][4] - box[b][1], box[b][5] - box[b][2]));
    largest = (std::max)(largest, side[b]);
  }
  if(!(largest > 0) || !std::isfinite(largest))
    return;
  m.normalization_scale = unit_scale(largest);
  std::vector<double> scale(box.size());
  for(std::size_t b = 0; b < box.size(); ++b)
    // A component whose vertices all coincide keeps the common frame.
    scale[b] = side[b] > 0 ? unit_scale(side[b]) : m.normalization_scale;
  if(box.size() > 1)  // one component: its frame is the common one
  {
    m.component_unit.resize(box.size());
    for(std::size_t b = 0; b < box.size(); ++b)
      m.component_unit[b] = m.normalization_scale / scale[b];  // exact, or 0 past the double range
    m.face_component.resize(m.number_of_faces());
    for(std::size_t f = 0; f < m.number_of_faces(); ++f)
      m.face_component[f] = component_of_root[find(m.corners[f][0])];
  }
  // Vertices without faces are never read: they are left as they are.
  for(std::size_t v = 0; v < nv; ++v)
  {
    const Index b = component_of_root[find(static_cast<Index>(v))];
    if(b != no_index)
      for(int k = 0; k < 3; ++k)
        m.points[v][k] = (m.points[v][k] - (box[b][k] / 2 + box[b][k + 3] / 2)) * scale[b];
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
