// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The patch map feeds CGAL's own Surface_mesh_parameterization: each patch,
// seen through a Face_filtered_graph, is flattened by SMP's discrete
// conformal map. SMP gives one UV per vertex of the patch; a vertex on the
// border between two patches has a UV in each, so the atlas is stored per
// corner (halfedge), as uv_atlas() does.
//
// The same SMP class can also be handed to parameterize_patches() (named
// parameter `parameterizer`, over the package's DS::Chart_mesh): the package
// then runs it on a copy of every patch, in parallel, checks each chart,
// redoes a chart it folds with an injective method, and splits charts over
// the distortion bound.

#include <CGAL/Disk_segmentation/parameterize_patches.h>
#include <CGAL/Disk_segmentation/patch_faces.h>
#include <CGAL/Disk_segmentation/segment_into_disks.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>

#include <boost/property_map/property_map.hpp>

#include <iostream>
#include <unordered_map>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Face_filtered_graph<Mesh> Patch;
namespace DS = CGAL::Disk_segmentation;
namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc < 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh))
  {
    std::cerr << "usage: parameterize_with_smp MESH (a triangle mesh)" << std::endl;
    return 1;
  }
  auto patch = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  auto uv = mesh.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;  // per corner
  DS::segment_into_disks(mesh, patch);

  const auto faces_of = DS::patch_faces(mesh, patch);
  std::size_t flipped = 0;
  for(std::size_t p = 0; p < faces_of.size(); ++p)
  {
    Patch piece(mesh, p, patch);
    const auto border = CGAL::Polygon_mesh_processing::longest_border(piece).first;
    // SMP's maps over the patch's vertices: UV, index, "already placed".
    std::unordered_map<Mesh::Vertex_index, K::Point_2> vertex_uv;
    std::unordered_map<Mesh::Vertex_index, int> index;
    std::unordered_map<Mesh::Vertex_index, bool> placed;
    for(Mesh::Vertex_index v : vertices(piece))
      index.emplace(v, int(index.size()));
    SMP::Discrete_conformal_map_parameterizer_3<Patch> conformal;
    if(conformal.parameterize(piece, border, boost::make_assoc_property_map(vertex_uv),
                              boost::make_assoc_property_map(index), boost::make_assoc_property_map(placed)) != SMP::OK)
    {
      std::cerr << "SMP failed on patch " << p << std::endl;
      return 1;
    }
    for(Mesh::Face_index f : faces_of[p])
    {
      for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
        uv[h] = vertex_uv.at(mesh.target(h));
      const Mesh::Halfedge_index h = mesh.halfedge(f);
      if(CGAL::orientation(uv[h], uv[mesh.next(h)], uv[mesh.prev(h)]) != CGAL::LEFT_TURN)
        ++flipped;
    }
  }
  std::cout << faces_of.size() << " patches parameterized by SMP, " << flipped << " flipped triangles\n";

  // The same parameterizer, run by the package on every patch.
  auto chart = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:chart", 0).first;
  for(Mesh::Face_index f : faces(mesh))
    chart[f] = patch[f];
  const DS::Parameterization_report report = DS::parameterize_patches(
    mesh, chart, uv, DS::parameters::parameterizer(SMP::Discrete_conformal_map_parameterizer_3<DS::Chart_mesh>()));
  std::cout << report.charts.size() << " charts from parameterize_patches() with SMP's conformal map, "
            << report.number_of_fallbacks << " redone by a fallback, " << report.number_of_invalid_charts
            << " invalid\n";
  return (flipped == 0 && report.number_of_invalid_charts == 0) ? 0 : 1;
}
