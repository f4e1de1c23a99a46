// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// disk_uv: segments a triangle mesh into topological disks.
//
//   disk_uv INPUT [-n 10] [-k 5] [--threshold 0.7624]
//           [--patch-ids FILE] [--colored FILE.ply]
//
// Prints a one-line summary; on any error prints one line on stderr and
// exits with status 1 (2 for bad command-line usage).

#include "mesh_io.h"

#include <CGAL/Disk_segmentation.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <CLI/CLI.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

namespace DS = CGAL::Disk_segmentation;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Property_map<Mesh::Face_index, std::size_t> Patch_map;

namespace {

// Well-separated colors: hues spaced by the golden angle.
std::array<int, 3> patch_color(std::size_t patch)
{
  const double hue = std::fmod(patch * 0.618033988749895, 1.0) * 6.0;
  const double saturation = (patch % 3 == 0) ? 0.55 : 0.75, value = (patch % 2 == 0) ? 0.95 : 0.8;
  const int sector = static_cast<int>(hue);
  const double f = hue - sector;
  const double p = value * (1 - saturation), q = value * (1 - saturation * f), t = value * (1 - saturation * (1 - f));
  double r = value, g = t, b = p;
  switch(sector)
  {
    case 1: r = q; g = value; b = p; break;
    case 2: r = p; g = value; b = t; break;
    case 3: r = p; g = q; b = value; break;
    case 4: r = t; g = p; b = value; break;
    case 5: r = value; g = p; b = q; break;
    default: break;
  }
  return {{ int(r * 255 + 0.5), int(g * 255 + 0.5), int(b * 255 + 0.5) }};
}

void write_colored_ply(std::ostream& out, const Mesh& mesh, const Patch_map& patch)
{
  out << "ply\nformat ascii 1.0\ncomment patches of disk_uv\n"
      << "element vertex " << mesh.number_of_vertices() << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << mesh.number_of_faces() << "\nproperty list uchar int vertex_indices\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  out.precision(17);
  for(Mesh::Vertex_index v : mesh.vertices())
    out << mesh.point(v).x() << ' ' << mesh.point(v).y() << ' ' << mesh.point(v).z() << '\n';
  for(Mesh::Face_index f : mesh.faces())
  {
    out << 3;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      out << ' ' << std::size_t(v);
    const std::array<int, 3> c = patch_color(patch[f]);
    out << ' ' << c[0] << ' ' << c[1] << ' ' << c[2] << '\n';
  }
}

void write_patch_ids(std::ostream& out, const Mesh& mesh, const Patch_map& patch)
{
  for(Mesh::Face_index f : mesh.faces())
    out << patch[f] << '\n';
}

} // namespace

int main(int argc, char** argv)
{
  CLI::App app{"disk_uv: segments a triangle mesh into topological disks "
               "(Maggioli & Melzi, EG 2025)"};
  std::string input, patch_ids_path, colored_path;
  std::size_t n = 10, k = 5;
  double threshold = DS::regular_polygon_threshold(5);
  app.add_option("INPUT", input, "input triangle mesh (.off .obj .ply .stl .ts)")->required();
  app.add_option("-n,--seeds", n, "number of farthest-point seeds")->capture_default_str();
  app.add_option("-k,--subsamples", k, "seeds used to re-sample a region that is not a disk")->capture_default_str();
  app.add_option("--threshold", threshold, "merge score threshold (eps_5 = 0.7624 by default)")->capture_default_str();
  app.add_option("--patch-ids", patch_ids_path, "write one patch id per face, in input face order");
  app.add_option("--colored", colored_path, "write a PLY mesh with one color per patch");
  try
  {
    app.parse(argc, argv);
  }
  catch(const CLI::ParseError& e)
  {
    return app.exit(e) == 0 ? 0 : 2;
  }

  try
  {
    for(const std::string& out : { patch_ids_path, colored_path })
      if(!out.empty() && out == input)
        throw disk_uv::Tool_error("refusing to overwrite the input file '" + input + "'");

    CGAL::Real_timer timer;
    timer.start();
    Mesh mesh;
    disk_uv::read_triangle_mesh(input, mesh);
    const double read_time = timer.time();
    Patch_map patch = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;

    timer.reset();
    const std::size_t seeds = DS::voronoi_fps_segmentation(mesh, patch, DS::parameters::number_of_seeds(n));
    const double voronoi_time = timer.time();
    timer.reset();
    const std::size_t refined = DS::refine_to_topological_disks(mesh, patch, DS::parameters::number_of_subsamples(k));
    const double refine_time = timer.time();
    timer.reset();
    const std::size_t patches = DS::merge_disk_regions(mesh, patch, DS::parameters::merge_threshold(threshold));
    const double merge_time = timer.time();

    if(!patch_ids_path.empty())
      disk_uv::write_file_atomically(patch_ids_path, [&](std::ostream& out) { write_patch_ids(out, mesh, patch); });
    if(!colored_path.empty())
      disk_uv::write_file_atomically(colored_path, [&](std::ostream& out) { write_colored_ply(out, mesh, patch); });

    std::printf("%s: %zu faces -> %zu patches (voronoi %zu, refined %zu); "
                "time read %.3f s, voronoi %.3f s, refine %.3f s, merge %.3f s\n",
                input.c_str(), static_cast<std::size_t>(mesh.number_of_faces()), patches, seeds, refined,
                read_time, voronoi_time, refine_time, merge_time);
  }
  catch(const std::exception& e)
  {
    std::cerr << "disk_uv: error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
