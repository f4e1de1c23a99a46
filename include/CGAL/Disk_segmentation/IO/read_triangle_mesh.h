// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Strict mesh file input: reading a mesh file with a one-line diagnosis of
// what is wrong with a bad one, optional repair and triangulation, and the
// checks a triangle mesh must pass.

#ifndef CGAL_DISK_SEGMENTATION_IO_READ_TRIANGLE_MESH_H
#define CGAL_DISK_SEGMENTATION_IO_READ_TRIANGLE_MESH_H

#include <CGAL/Disk_segmentation/IO/File_error.h>
#include <CGAL/Disk_segmentation/IO/Read_options.h>
#include <CGAL/Disk_segmentation/IO/internal/Input_file.h>
#include <CGAL/Disk_segmentation/IO/internal/Mesh_readers.h>
#include <CGAL/Disk_segmentation/IO/internal/Polygon_triangulation.h>

#include <CGAL/Disk_segmentation/IO/internal/Triangle_soup_to_mesh.h>
// Doxygen's preprocessor trips over a Boost header these include.
#ifndef DOXYGEN_RUNNING
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#endif
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cctype>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <unordered_set>
#include <utility>
#include <vector>

#include <unistd.h>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {
namespace internal {


inline std::string lower_extension(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// Names the first face that refers to a vertex the file does not have, or
// the first vertex with a non-finite coordinate; empty if there is none.
template <typename Point>
std::string soup_reference_problem(const std::vector<Point>& points,
                                   const std::vector<std::vector<std::size_t> >& polygons)
{
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t v : polygons[f])
      if(v >= points.size())
        return "face #" + std::to_string(f) + " refers to vertex #" + std::to_string(v) +
               ", but the file has only " + std::to_string(points.size()) + " vertices";
  for(std::size_t v = 0; v < points.size(); ++v)
    if(!std::isfinite(CGAL::to_double(points[v].x())) || !std::isfinite(CGAL::to_double(points[v].y())) ||
       !std::isfinite(CGAL::to_double(points[v].z())))
      return "vertex #" + std::to_string(v) + " has a non-finite (NaN or infinite) coordinate";
  return std::string();
}

// Names a triangle with the same three vertices as an earlier one, if any.
inline std::string duplicated_face_problem(const std::vector<std::vector<std::size_t> >& polygons)
{
  std::vector<std::array<std::size_t, 4> > sorted_faces(polygons.size());
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    sorted_faces[f] = {{ polygons[f][0], polygons[f][1], polygons[f][2], f }};
    std::sort(sorted_faces[f].begin(), sorted_faces[f].begin() + 3);
  }
  std::sort(sorted_faces.begin(), sorted_faces.end());
  for(std::size_t i = 1; i < sorted_faces.size(); ++i)
    if(std::equal(sorted_faces[i].begin(), sorted_faces[i].begin() + 3, sorted_faces[i - 1].begin()))
      return "face #" + std::to_string(sorted_faces[i][3]) + " duplicates face #" +
             std::to_string(sorted_faces[i - 1][3]) + " (same three vertices)";
  return std::string();
}

// Names the first reason why the soup is not a manifold, consistently
// oriented triangle mesh; empty if it is one. With `pinched_vertex_fans`,
// a vertex whose faces form several fans (a pinched vertex) is no problem:
// it is kept, and its fans but the first are added to the count. A copy of
// the vertex per fan made here would hide from the package's functions that
// the fans are one vertex of the file, and a chart could then hold two of
// them (no disk of the file's mesh); they cut the mesh there themselves and
// remember which copies are one vertex.
template <typename Point>
std::string triangle_soup_problem(const std::vector<Point>& points,
                                  const std::vector<std::vector<std::size_t> >& polygons,
                                  std::size_t* pinched_vertex_fans = nullptr)
{
  if(polygons.empty())
    return "the mesh has no face";
  const std::string reference_problem = soup_reference_problem(points, polygons);
  if(!reference_problem.empty())
    return reference_problem;
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    const auto& p = polygons[f];
    if(p.size() != 3)
      return "face #" + std::to_string(f) + " has " + std::to_string(p.size()) +
             " vertices; only triangle meshes are supported (--triangulate splits polygons)";
    if(p[0] == p[1] || p[1] == p[2] || p[2] == p[0])
      return "face #" + std::to_string(f) + " uses the same vertex twice";
  }

  // Duplicated faces first: they would otherwise be reported as a
  // non-manifold or inconsistently oriented edge.
  const std::string duplicate = duplicated_face_problem(polygons);
  if(!duplicate.empty())
    return duplicate;

  // Every directed edge as (smaller vertex, larger vertex, corner of the
  // smaller vertex, direction), sorted so that the uses of one undirected
  // edge are adjacent. 32-bit fields: CGAL's own check (a map of edges) took
  // 1 GB on a 2.2M-face mesh, this takes 16 bytes per corner.
  struct Edge_use
  {
    std::uint32_t low, high, low_corner, direction;
    bool operator<(const Edge_use& o) const
    {
      return std::tie(low, high, direction, low_corner) < std::tie(o.low, o.high, o.direction, o.low_corner);
    }
  };
  if(points.size() >= (std::size_t(1) << 32) || 3 * polygons.size() >= (std::size_t(1) << 32))
    return "the mesh is too large (more than 2^32 vertices or corners)";
  std::vector<Edge_use> uses;
  uses.reserve(3 * polygons.size());
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(int i = 0; i < 3; ++i)
    {
      const std::size_t a = polygons[f][i], b = polygons[f][(i + 1) % 3];
      const std::size_t low_corner = 3 * f + (a < b ? i : (i + 1) % 3);
      uses.push_back({ std::uint32_t((std::min)(a, b)), std::uint32_t((std::max)(a, b)),
                       std::uint32_t(low_corner), std::uint32_t(a < b ? 0 : 1) });
    }
  std::sort(uses.begin(), uses.end());

  // Corners of one vertex joined across the edges they share; a vertex is
  // manifold when all its corners end up in one fan.
  std::vector<std::uint32_t> fan(3 * polygons.size());
  for(std::size_t c = 0; c < fan.size(); ++c)
    fan[c] = std::uint32_t(c);
  // Ends: join links a root to a root (itself when they are equal), so fan
  // is a forest; at most 3 F steps.
  auto find = [&fan](std::uint32_t c) {
    while(fan[c] != c)
      c = fan[c] = fan[fan[c]];
    return c;
  };
  auto join = [&](std::uint32_t c, std::uint32_t d) { fan[find(c)] = find(d); };
  auto corner_of = [&polygons](std::uint32_t face, std::size_t v) {
    for(std::uint32_t i = 0; i < 3; ++i)
      if(polygons[face][i] == v)
        return 3 * face + i;
    return 3 * face;
  };

  // Each pass moves i past uses[i] at least.
  for(std::size_t i = 0; i < uses.size();)
  {
    std::size_t j = i;
    std::array<std::size_t, 2> per_direction{{ 0, 0 }};
    while(j < uses.size() && uses[j].low == uses[i].low && uses[j].high == uses[i].high)
      ++per_direction[uses[j++].direction];
    const std::size_t count = j - i;
    auto name = [&] { return "edge (" + std::to_string(uses[i].low) + ", " + std::to_string(uses[i].high) + ")"; };
    if(count > 2)
      return "the mesh is not manifold: " + name() + " is shared by " + std::to_string(count) + " faces";
    if(per_direction[0] > 1 || per_direction[1] > 1)
      return "the faces on both sides of " + name() + " are oriented inconsistently";
    if(count == 2)
    {
      const std::uint32_t f = uses[i].low_corner / 3, g = uses[i + 1].low_corner / 3;
      join(uses[i].low_corner, uses[i + 1].low_corner);
      join(corner_of(f, uses[i].high), corner_of(g, uses[i].high));
    }
    i = j;
  }
  std::vector<std::uint32_t> first_fan(points.size(), std::numeric_limits<std::uint32_t>::max());
  std::unordered_set<std::uint32_t> other_fans;  // by root
  for(std::uint32_t c = 0; c < fan.size(); ++c)
  {
    const std::size_t v = polygons[c / 3][c % 3];
    const std::uint32_t root = find(c);
    if(first_fan[v] == std::numeric_limits<std::uint32_t>::max())
      first_fan[v] = root;
    else if(first_fan[v] != root)
    {
      if(pinched_vertex_fans == nullptr)
        return "the mesh is not manifold: the faces around vertex #" + std::to_string(v) +
               " form more than one fan (a pinched vertex)";
      if(other_fans.insert(root).second)
        ++*pinched_vertex_fans;
    }
  }
  return std::string();
}

// Reads a polygon soup in the format named by `ext` (off, obj, ply, stl, ts)
// from the file's `bytes` (see internal/Mesh_readers.h). Throws File_error naming `name`.
template <typename Point>
void read_polygon_soup_from(std::string_view bytes, const std::string& ext, const std::string& name,
                            std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons)
{
  points.clear();
  polygons.clear();
  if(ext == "off")
    read_OFF_soup(bytes, name, points, polygons);
  else if(ext == "obj")
    read_OBJ_soup(bytes, name, points, polygons);
  else if(ext == "ply")
    read_PLY_soup(bytes, name, points, polygons);
  else if(ext == "stl")
    read_STL_soup(bytes, name, points, polygons);
  else if(ext == "ts")
    read_TS_soup(bytes, name, points, polygons);
  else
    throw File_error("'" + name + "': unknown mesh format '" + ext + "' (supported: .off .obj .ply .stl .ts)");
}

// Applies `options` to a soup just read, then checks that it is a manifold,
// consistently oriented triangle mesh. Throws File_error naming `name`.
template <typename Point>
Read_changes prepare_triangle_soup(std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons,
                                   const Read_options& options, const std::string& name)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  Read_changes changes;
  // Repair and triangulation compute with the coordinates: they must be finite.
  const std::string reference_problem = soup_reference_problem(points, polygons);
  if(!reference_problem.empty())
    throw File_error("'" + name + "': " + reference_problem);

  if(options.repair)
  {
    const std::size_t faces = polygons.size(), vertices = points.size();
    PMP::repair_polygon_soup(points, polygons);
    const std::size_t merged_vertices = points.size();
    PMP::orient_polygon_soup(points, polygons);
    changes.faces_removed = faces - polygons.size();
    changes.vertices_removed = vertices - merged_vertices;
    changes.vertices_added = points.size() - merged_vertices;
  }
  if(options.triangulate)
  {
    std::vector<std::vector<std::size_t> > triangles;
    triangles.reserve(polygons.size());
    changes.polygon_of_face.reserve(polygons.size());
    for(std::size_t p = 0; p < polygons.size(); ++p)
    {
      std::vector<std::size_t>& polygon = polygons[p];
      if(polygon.size() <= 3)
      {
        triangles.push_back(std::move(polygon));
        changes.polygon_of_face.push_back(p);
        continue;
      }
      bool used_fan = false;
      for(std::vector<std::size_t>& t : triangulate_polygon(points, polygon, used_fan))
      {
        triangles.push_back(std::move(t));
        changes.polygon_of_face.push_back(p);
      }
      ++changes.polygons_triangulated;
      changes.fan_triangulations += used_fan ? 1 : 0;
    }
    changes.faces_added = triangles.size() - polygons.size();
    polygons.swap(triangles);
  }

  // Pinched vertices are no error, and the mesh keeps them: the atlas cuts
  // the mesh there anyway.
  const std::string problem = triangle_soup_problem(points, polygons, &changes.pinched_vertices_split);
  if(!problem.empty())
  {
    std::string hint;
    if(!options.repair && problem.find("manifold") != std::string::npos)
      hint = " (--repair cuts the mesh there)";
    else if(!options.repair && (problem.find("duplicates") != std::string::npos ||
                                problem.find("oriented") != std::string::npos ||
                                problem.find("twice") != std::string::npos))
      hint = " (--repair fixes this)";
    throw File_error("'" + name + "': " + problem + hint);
  }
  return changes;
}

} // namespace internal

/// \ingroup PkgDiskSegmentationIO
/// Reads the triangle mesh of the file `path` (OFF, OBJ, PLY, STL or TS,
/// told by the extension) into `mesh`, keeping the file's face and vertex
/// order unless `options` change the mesh. A vertex where faces meet in
/// several fans (a pinched vertex) is kept as one vertex, as `Surface_mesh`
/// can hold it (CGAL's `is_valid_polygon_mesh()` rejects it, and
/// `Polygon_mesh_processing::duplicate_non_manifold_vertices()` splits it):
/// the package's functions cut the mesh there themselves, and none of their
/// patches holds two of its fans. A non-manifold edge, inconsistently
/// oriented or duplicated faces and polygons are refused unless `options`
/// repair or triangulate them.
///
/// \tparam Mesh a model of `MutableFaceGraph` whose points are 3D points
/// \returns what reading changed
/// \throws File_error with a one-line message naming the file and the
/// problem (the first bad line, token or element)
template <typename Mesh>
Read_changes read_triangle_mesh(const std::string& path, Mesh& mesh, const Read_options& options = Read_options())
{
  typedef typename boost::property_traits<
    typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point;

  const std::string ext = internal::lower_extension(path);
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl" && ext != "ts")
    throw File_error("'" + path + "': unknown mesh format '" + ext + "' (supported: .off .obj .ply .stl .ts)");

  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  {
    // The file's bytes are freed before the mesh is built.
    const std::string bytes =
      internal::read_input_file(path, options.allow_special_input, options.max_input_bytes, ext);
    internal::read_polygon_soup_from(bytes, ext, path, points, polygons);
  }
  const Read_changes changes = internal::prepare_triangle_soup(points, polygons, options, path);
  internal::checked_triangle_soup_to_mesh(points, polygons, mesh);
  return changes;
}

} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_READ_TRIANGLE_MESH_H
