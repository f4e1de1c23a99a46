// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// File input and output of the disk_uv tool: reading any mesh format CGAL
// reads with a one-line diagnosis of what is wrong with a bad file, and
// writing outputs so that a failure never leaves a half-written file.

#ifndef DISK_SEGMENTATION_EXAMPLES_MESH_IO_H
#define DISK_SEGMENTATION_EXAMPLES_MESH_IO_H

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

namespace disk_uv {

struct Tool_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

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

// Names the first reason why the soup is not a manifold, consistently
// oriented triangle mesh; empty if it is one.
template <typename Point>
std::string triangle_soup_problem(const std::vector<Point>& points,
                                  const std::vector<std::vector<std::size_t> >& polygons)
{
  if(polygons.empty())
    return "the mesh has no face";
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    const auto& p = polygons[f];
    if(p.size() != 3)
      return "face #" + std::to_string(f) + " has " + std::to_string(p.size()) +
             " vertices; only triangle meshes are supported (triangulate it first)";
    for(std::size_t v : p)
      if(v >= points.size())
        return "face #" + std::to_string(f) + " refers to vertex #" + std::to_string(v) +
               ", but the file has only " + std::to_string(points.size()) + " vertices";
    if(p[0] == p[1] || p[1] == p[2] || p[2] == p[0])
      return "face #" + std::to_string(f) + " uses the same vertex twice";
  }
  for(std::size_t v = 0; v < points.size(); ++v)
    if(!std::isfinite(CGAL::to_double(points[v].x())) || !std::isfinite(CGAL::to_double(points[v].y())) ||
       !std::isfinite(CGAL::to_double(points[v].z())))
      return "vertex #" + std::to_string(v) + " has a non-finite (NaN or infinite) coordinate";

  // Every directed edge as (smaller vertex, larger vertex, direction),
  // sorted so that the uses of one undirected edge are adjacent.
  std::vector<std::array<std::size_t, 3> > uses;
  uses.reserve(3 * polygons.size());
  for(const auto& p : polygons)
    for(int i = 0; i < 3; ++i)
    {
      const std::size_t a = p[i], b = p[(i + 1) % 3];
      uses.push_back({{ (std::min)(a, b), (std::max)(a, b), std::size_t(a < b ? 0 : 1) }});
    }
  std::sort(uses.begin(), uses.end());
  for(std::size_t i = 0; i < uses.size();)
  {
    std::size_t j = i;
    std::array<std::size_t, 2> per_direction{{ 0, 0 }};
    while(j < uses.size() && uses[j][0] == uses[i][0] && uses[j][1] == uses[i][1])
      ++per_direction[uses[j++][2]];
    const std::size_t count = j - i;
    auto name = [&] { return "edge (" + std::to_string(uses[i][0]) + ", " + std::to_string(uses[i][1]) + ")"; };
    if(count > 2)
      return "the mesh is not manifold: " + name() + " is shared by " + std::to_string(count) + " faces";
    if(per_direction[0] > 1 || per_direction[1] > 1)
      return "the faces on both sides of " + name() + " are oriented inconsistently";
    i = j;
  }
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    return "the mesh is not manifold: the faces around some vertex form more than one fan";
  return std::string();
}

// Reads a triangle mesh in any format CGAL reads (OFF, OBJ, PLY, STL, TS),
// keeping the file's face and vertex order. Throws Tool_error with a one-line
// message naming the problem.
template <typename Mesh>
void read_triangle_mesh(const std::string& path, Mesh& mesh)
{
  typedef typename boost::property_traits<
    typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point;

  std::ifstream probe(path, std::ios::binary);
  if(!probe)
    throw Tool_error("cannot open '" + path + "' for reading");
  probe.close();

  const std::string ext = lower_extension(path);
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl" && ext != "ts")
    throw Tool_error("'" + path + "': unknown mesh format '" + ext +
                     "' (supported: .off .obj .ply .stl .ts)");

  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  bool ok = false;
  try
  {
    ok = CGAL::IO::read_polygon_soup(path, points, polygons);
  }
  catch(const std::exception& e)
  {
    throw Tool_error("'" + path + "' is not a valid ." + ext + " file (" + e.what() + ")");
  }
  if(!ok)
    throw Tool_error("'" + path + "' is not a valid ." + ext + " file (it may be empty or truncated)");

  const std::string problem = triangle_soup_problem(points, polygons);
  if(!problem.empty())
    throw Tool_error("'" + path + "': " + problem);

  mesh.clear();
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
}

// Writes `path` through a temporary file in the same folder renamed at the
// end: on any failure the previous content of `path` is left untouched.
inline void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write)
{
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary);
    if(!out)
      throw Tool_error("cannot write '" + path + "'");
    try
    {
      write(out);
      out.flush();
    }
    catch(...)
    {
      out.close();
      std::remove(temporary.c_str());
      throw;
    }
    if(!out)
    {
      out.close();
      std::remove(temporary.c_str());
      throw Tool_error("error while writing '" + path + "' (disk full?)");
    }
  }
  if(std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    throw Tool_error("cannot replace '" + path + "'");
  }
}

} // namespace disk_uv

#endif // DISK_SEGMENTATION_EXAMPLES_MESH_IO_H
