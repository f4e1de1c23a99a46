// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Built against an installed Disk_segmentation (see CMakeLists.txt next to
// this file): segments a mesh into topological disks and prints the number
// of patches. Without an argument it segments a generated icosahedron.
// Exits with 1 on any failure.

#include <CGAL/Disk_segmentation.h>
#include <CGAL/Disk_segmentation/IO/write_atlas_GLB.h>
#include <CGAL/Disk_segmentation/IO/write_atlas_OBJ.h>
#include <CGAL/Disk_segmentation/IO/write_atlas_PNG.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace DS = CGAL::Disk_segmentation;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc > 1)
  {
    if(!CGAL::IO::read_polygon_mesh(argv[1], mesh))
    {
      std::cerr << "consumer: cannot read " << argv[1] << std::endl;
      return 1;
    }
  }
  else
  {
    CGAL::make_icosahedron(mesh, K::Point_3(0, 0, 0), 1.);
  }

  try
  {
    auto patch = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
    const std::size_t count = DS::segment_into_disks(mesh, patch, DS::parameters::number_of_seeds(8));

    std::vector<std::vector<Mesh::Face_index> > faces_of(count);
    for(Mesh::Face_index f : faces(mesh))
    {
      if(patch[f] >= count)
      {
        std::cerr << "consumer: patch id out of range" << std::endl;
        return 1;
      }
      faces_of[patch[f]].push_back(f);
    }
    for(const std::vector<Mesh::Face_index>& p : faces_of)
      if(p.empty() || !DS::is_topological_disk(p, mesh))
      {
        std::cerr << "consumer: a patch is empty or not a topological disk" << std::endl;
        return 1;
      }

    std::cout << "patches: " << count << " (" << num_faces(mesh) << " faces)" << std::endl;

    // The installed atlas writer: one group per chart in the OBJ file.
    auto uv = mesh.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
    DS::uv_atlas(mesh, uv, DS::parameters::face_patch_map(patch));
    std::ostringstream obj;
    if(!DS::IO::write_atlas_OBJ(obj, mesh, patch, uv))
    {
      std::cerr << "consumer: write_atlas_OBJ failed" << std::endl;
      return 1;
    }
    std::size_t groups = 0;
    std::istringstream lines(obj.str());
    for(std::string line; std::getline(lines, line);)
      groups += line.compare(0, 8, "g chart_") == 0 ? 1 : 0;
    if(groups == 0)
    {
      std::cerr << "consumer: the OBJ atlas has no chart group" << std::endl;
      return 1;
    }
    std::cout << "OBJ atlas: " << groups << " chart groups" << std::endl;

    // The writers of the component IO, with their libraries found by the config.
    std::ostringstream glb, png;
    DS::IO::write_atlas_GLB(glb, mesh, patch, uv);
    DS::IO::write_atlas_PNG(png, mesh, patch, uv, 256);
    if(glb.str().compare(0, 4, "glTF") != 0 || png.str().compare(1, 3, "PNG") != 0)
    {
      std::cerr << "consumer: the GLB or PNG atlas lacks its signature" << std::endl;
      return 1;
    }
    std::cout << "GLB: " << glb.str().size() << " bytes, PNG: " << png.str().size() << " bytes" << std::endl;
#ifdef CGAL_LINKED_WITH_TBB
    std::cout << "TBB: yes" << std::endl;
#else
    std::cout << "TBB: no" << std::endl;
#endif
    return count > 0 ? 0 : 1;
  }
  catch(const std::exception& e)
  {
    std::cerr << "consumer: " << e.what() << std::endl;
    return 1;
  }
}
