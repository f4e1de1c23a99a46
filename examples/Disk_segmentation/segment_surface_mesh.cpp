// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Segments a Surface_mesh into topological disks, step by step, and checks
// every patch with is_topological_disk().

#include <CGAL/Disk_segmentation/patch_faces.h>
#include <CGAL/Disk_segmentation/segment_into_disks.h>
#include <CGAL/Disk_segmentation/topology.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace DS = CGAL::Disk_segmentation;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc < 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh))
  {
    std::cerr << "usage: segment_surface_mesh MESH (a triangle mesh)" << std::endl;
    return 1;
  }

  auto patch = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;

  // 1. Joint farthest-point sampling and geodesic Voronoi cells.
  std::vector<Mesh::Face_index> seeds;
  std::size_t count = DS::voronoi_fps_segmentation(
    mesh, patch, DS::parameters::number_of_seeds(10).seeds_output_iterator(std::back_inserter(seeds)));
  std::cout << count << " Voronoi cells\n";

  // 2. Re-sample the cells that are not disks.
  count = DS::refine_to_topological_disks(mesh, patch, DS::parameters::number_of_subsamples(5));
  std::cout << count << " disks after refinement\n";

  // 3. Merge neighbors whose union stays a disk and whose score is high.
  count = DS::merge_disk_regions(mesh, patch, DS::parameters::merge_threshold(DS::regular_polygon_threshold(5)));
  std::cout << count << " disks after merging\n";

  const std::vector<std::vector<Mesh::Face_index> > faces_of = DS::patch_faces(mesh, patch);
  if(faces_of.size() != count)
  {
    std::cerr << "patch ids are not 0.." << count - 1 << std::endl;
    return 1;
  }
  for(const auto& p : faces_of)
    if(!DS::is_topological_disk(p, mesh))
    {
      std::cerr << "a patch is not a disk" << std::endl;
      return 1;
    }
  std::cout << "every patch is a topological disk\n";
  return 0;
}
