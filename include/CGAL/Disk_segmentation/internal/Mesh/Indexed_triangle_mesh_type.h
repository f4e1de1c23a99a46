// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The indexed triangle mesh every algorithm of the package runs on: the
// arrays, the measures read from them, and the order of a face's corners.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_MESH_INDEXED_TRIANGLE_MESH_TYPE_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_MESH_INDEXED_TRIANGLE_MESH_TYPE_H

#include <CGAL/disable_warnings.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
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

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_MESH_INDEXED_TRIANGLE_MESH_TYPE_H
