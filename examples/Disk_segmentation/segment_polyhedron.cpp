// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Segments a Polyhedron_3 into topological disks in the three steps of the
// method (Voronoi cells of farthest-point seeds, refinement, merging), then
// checks that segment_into_disks() gives the same patches in one call.
//
// Polyhedron_3 has no room for per-face data, so patch ids are kept in
// dynamic property maps, which live as long as the map object.

#include <CGAL/Disk_segmentation.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <iostream>
#include <iterator>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef boost::graph_traits<Polyhedron>::face_descriptor face_descriptor;
typedef boost::property_map<Polyhedron, CGAL::dynamic_face_property_t<std::size_t> >::type Patch_map;
namespace DS = CGAL::Disk_segmentation;

// The faces of each patch; patch ids are in [0, count).
std::vector<std::vector<face_descriptor> > faces_by_patch(const Polyhedron& mesh, Patch_map patch,
                                                         std::size_t count)
{
  std::vector<std::vector<face_descriptor> > faces_of(count);
  for(face_descriptor f : faces(mesh))
    faces_of[get(patch, f)].push_back(f);
  return faces_of;
}

int main(int argc, char** argv)
{
  Polyhedron mesh;
  if(argc < 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "usage: segment_polyhedron MESH (a triangle mesh)" << std::endl;
    return 1;
  }
  std::cout << num_faces(mesh) << " faces\n";

  Patch_map patch = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);

  // 1. Voronoi cells of 8 farthest-point seeds; the seed faces are collected
  //    in the order they were chosen. Cells need not be disks.
  std::vector<face_descriptor> seeds;
  const std::size_t cells = DS::voronoi_fps_segmentation(
    mesh, patch, DS::parameters::number_of_seeds(8).seeds_output_iterator(std::back_inserter(seeds)));
  std::size_t disk_cells = 0;
  for(const std::vector<face_descriptor>& cell : faces_by_patch(mesh, patch, cells))
    disk_cells += DS::is_topological_disk(cell, mesh) ? 1 : 0;
  std::cout << cells << " Voronoi cells from " << seeds.size() << " seeds, " << disk_cells
            << " of them topological disks\n";
  if(seeds.size() != cells)
    return 1;

  // 2. Re-sample every cell that is not a disk with 5 seeds, recursively.
  const std::size_t disks = DS::refine_to_topological_disks(mesh, patch, DS::parameters::number_of_subsamples(5));
  std::cout << disks << " disks after refinement\n";

  // 3. Merge neighboring disks while the union is a disk and their shared
  //    boundary is long enough (the default threshold is the paper's eps_5).
  const std::size_t count = DS::merge_disk_regions(mesh, patch);
  std::cout << count << " disks after merging (threshold " << DS::regular_polygon_threshold(5) << ")\n";

  for(const std::vector<face_descriptor>& p : faces_by_patch(mesh, patch, count))
    if(p.empty() || !DS::is_topological_disk(p, mesh))
    {
      std::cerr << "a patch is empty or not a topological disk" << std::endl;
      return 1;
    }

  // The three steps in one call, with the same parameters and without the
  // package's border smoothing: same patches.
  Patch_map patch_in_one_call = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const std::size_t count_in_one_call = DS::segment_into_disks(
    mesh, patch_in_one_call, DS::parameters::number_of_seeds(8).number_of_subsamples(5).smooth_borders(false));
  for(face_descriptor f : faces(mesh))
    if(count_in_one_call != count || get(patch_in_one_call, f) != get(patch, f))
    {
      std::cerr << "segment_into_disks differs from the three steps" << std::endl;
      return 1;
    }
  std::cout << "every patch is a topological disk; segment_into_disks gives the same " << count << " patches\n";
  return 0;
}
