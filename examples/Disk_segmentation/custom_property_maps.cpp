// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Segments a Polyhedron_3 with property maps held in standard containers:
//
// - face and vertex indices in std::unordered_map, seen as property maps
//   through boost::associative_property_map and passed with the
//   face_index_map and vertex_index_map named parameters;
// - patch ids in a std::vector, seen as a property map through
//   boost::iterator_property_map with the face index as position.
//
// This is how to use indices that already exist elsewhere, or a mesh type
// without internal indices (Polyhedron_3 with its default items). Any
// numbering of the faces in [0, #faces) works, and the patches do not depend
// on it: the example checks this against a run with the default maps.

#include <CGAL/Disk_segmentation.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <boost/property_map/property_map.hpp>

#include <iostream>
#include <unordered_map>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef boost::graph_traits<Polyhedron>::face_descriptor face_descriptor;
typedef boost::graph_traits<Polyhedron>::vertex_descriptor vertex_descriptor;
namespace DS = CGAL::Disk_segmentation;

int main(int argc, char** argv)
{
  Polyhedron mesh;
  if(argc < 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "usage: custom_property_maps MESH (a triangle mesh)" << std::endl;
    return 1;
  }

  // Indices held in hash maps; faces are numbered backwards here, to show
  // that any one-to-one numbering in [0, #faces) is accepted.
  std::unordered_map<face_descriptor, std::size_t> face_ids;
  std::unordered_map<vertex_descriptor, std::size_t> vertex_ids;
  const std::size_t number_of_faces = num_faces(mesh);
  for(face_descriptor f : faces(mesh))
    face_ids.emplace(f, number_of_faces - 1 - face_ids.size());
  for(vertex_descriptor v : vertices(mesh))
    vertex_ids.emplace(v, vertex_ids.size());
  boost::associative_property_map<std::unordered_map<face_descriptor, std::size_t> > face_index(face_ids);
  boost::associative_property_map<std::unordered_map<vertex_descriptor, std::size_t> > vertex_index(vertex_ids);

  // Patch ids in a vector: the patch of face f is patch_of[face_ids[f]].
  std::vector<std::size_t> patch_of(number_of_faces);
  auto patch = boost::make_iterator_property_map(patch_of.begin(), face_index);

  const std::size_t count = DS::segment_into_disks(
    mesh, patch,
    DS::parameters::face_index_map(face_index).vertex_index_map(vertex_index).number_of_seeds(12));
  std::cout << count << " patches on " << number_of_faces << " faces\n";

  std::vector<std::vector<face_descriptor> > faces_of(count);
  for(face_descriptor f : faces(mesh))
    faces_of[patch_of[face_ids.at(f)]].push_back(f);
  for(const std::vector<face_descriptor>& p : faces_of)
    if(p.empty() || !DS::is_topological_disk(p, mesh))
    {
      std::cerr << "a patch is empty or not a topological disk" << std::endl;
      return 1;
    }

  // The same segmentation with the default (internally built) index maps.
  auto default_patch = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const std::size_t default_count =
    DS::segment_into_disks(mesh, default_patch, DS::parameters::number_of_seeds(12));
  for(face_descriptor f : faces(mesh))
    if(default_count != count || get(default_patch, f) != get(patch, f))
    {
      std::cerr << "the patches depend on the index maps" << std::endl;
      return 1;
    }
  std::cout << "every patch is a topological disk, the same as with the default maps\n";
  return 0;
}
