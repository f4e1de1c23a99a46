// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Computes a UV atlas of a Surface_mesh twice:
//
// 1. in one call, uv_atlas(), with the defaults (ARAP charts, tight packing);
// 2. step by step: segment_into_disks(), parameterize_patches() with a chosen
//    method (discrete conformal, the paper's "harmonic"), and pack_patches()
//    with the paper's grid packer.
//
// UVs are per corner: uv[h] is the UV of target(h) as seen from face(h).
// Both atlases are checked: every chart is a topological disk, every UV lies
// in the unit square, every triangle keeps a positive (counterclockwise) area.
// With a second argument, the first atlas is saved there as an OBJ file
// (a `vt` per corner, one group per chart).
//
// 3. Then a third atlas is started with a progress callback that stops it
//    once the segmentation is done: uv_atlas() throws DS::Cancelled, and
//    the maps keep the second atlas, as after any exception.

#include <CGAL/Disk_segmentation.h>
#include <CGAL/Disk_segmentation/IO/write_atlas_OBJ.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Property_map<Mesh::Face_index, std::size_t> Chart_map;
typedef Mesh::Property_map<Mesh::Halfedge_index, K::Point_2> UV_map;
namespace DS = CGAL::Disk_segmentation;

bool check_atlas(const Mesh& mesh, Chart_map chart, UV_map uv, std::size_t number_of_charts)
{
  std::vector<std::vector<Mesh::Face_index> > faces_of(number_of_charts);
  for(Mesh::Face_index f : faces(mesh))
  {
    if(chart[f] >= number_of_charts)
      return false;
    faces_of[chart[f]].push_back(f);

    const Mesh::Halfedge_index h = halfedge(f, mesh);
    const K::Point_2 a = uv[h], b = uv[next(h, mesh)], c = uv[next(next(h, mesh), mesh)];
    for(const K::Point_2& p : { a, b, c })
      if(!(p.x() >= 0 && p.x() <= 1 && p.y() >= 0 && p.y() <= 1))
        return false;
    if(CGAL::orientation(a, b, c) != CGAL::COUNTERCLOCKWISE)
      return false;
  }
  for(const std::vector<Mesh::Face_index>& c : faces_of)
    if(c.empty() || !DS::is_topological_disk(c, mesh))
      return false;
  return true;
}

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc < 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh))
  {
    std::cerr << "usage: uv_atlas_example MESH [ATLAS.obj] (a triangle mesh)" << std::endl;
    return 1;
  }

  UV_map uv = mesh.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(0, 0)).first;
  Chart_map chart = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:chart", 0).first;

  // 1. The whole atlas in one call. face_patch_map is optional: it receives
  //    the chart of every face.
  const DS::Atlas_report atlas = DS::uv_atlas(mesh, uv, DS::parameters::face_patch_map(chart));
  std::cout << "uv_atlas: " << atlas.number_of_faces << " faces, " << atlas.number_of_voronoi_cells
            << " Voronoi cells, " << atlas.number_of_refined_regions << " disks after refinement, "
            << atlas.number_of_charts << " charts, " << atlas.parameterization.number_of_fallbacks
            << " fallbacks, packing efficiency " << 100 * atlas.packing.efficiency << "%, "
            << atlas.packing.texels_per_unit << " texels per unit length, " << atlas.total_seconds << " s\n";
  if(atlas.parameterization.number_of_invalid_charts != 0 ||
     !check_atlas(mesh, chart, uv, atlas.number_of_charts))
  {
    std::cerr << "uv_atlas gave an invalid atlas" << std::endl;
    return 1;
  }
  if(argc > 2)
  {
    std::ofstream out(argv[2]);
    if(!DS::IO::write_atlas_OBJ(out, mesh, chart, uv) || !out.flush())
    {
      std::cerr << "cannot write " << argv[2] << std::endl;
      return 1;
    }
    std::cout << "atlas written to " << argv[2] << "\n";
  }

  // 2. The same steps by hand.
  const std::size_t patches = DS::segment_into_disks(mesh, chart, DS::parameters::number_of_seeds(10));

  // Every chart is parameterized on its own; one that comes out invalid is
  // redone with mean value coordinates (or split), and the report says so.
  const DS::Parameterization_report charts = DS::parameterize_patches(
    mesh, chart, uv, DS::parameters::parameterization_method(DS::Parameterization_method::DISCRETE_CONFORMAL));
  for(const DS::Chart_report& r : charts.charts)
    if(r.fallback)
      std::cout << "  chart " << r.patch << " (" << r.faces << " faces): " << DS::to_string(r.requested)
                << " rejected (" << r.problem << "), kept " << DS::to_string(r.used) << "\n";

  // The paper's packer: a grid of equal cells, each chart as large as possible in its cell.
  const DS::Packing_report packing = DS::pack_patches(
    mesh, chart, uv, DS::parameters::packing_method(DS::Packing_method::GRID).padding_in_texels(2.));
  std::cout << "step by step: " << patches << " patches, " << charts.charts.size() << " charts ("
            << charts.number_of_split_patches << " patches split), " << charts.number_of_fallbacks
            << " fallbacks, grid packing efficiency " << 100 * packing.efficiency << "%\n";
  if(charts.number_of_invalid_charts != 0 || packing.number_of_charts != charts.charts.size() ||
     !check_atlas(mesh, chart, uv, charts.charts.size()))
  {
    std::cerr << "the step-by-step atlas is invalid" << std::endl;
    return 1;
  }
  std::cout << "both atlases: every chart is a topological disk inside the unit square, no flipped triangle\n";

  // 3. A callback that returns bool may stop the work (one that returns
  //    nothing only follows it). Calls come one at a time, from any thread.
  const std::vector<K::Point_2> grid_uvs(uv.begin(), uv.end());
  try
  {
    DS::uv_atlas(mesh, uv, DS::parameters::face_patch_map(chart).progress_callback(
      [](const std::string& stage, std::size_t done, std::size_t total) {
        std::cout << "  " << stage << ' ' << done << '/' << total << "\n";
        return stage == "segmentation";
      }));
    std::cerr << "the atlas was not cancelled" << std::endl;
    return 1;
  }
  catch(const DS::Cancelled& e)
  {
    std::cout << "cancelled during the " << e.stage() << "\n";
  }
  if(!std::equal(grid_uvs.begin(), grid_uvs.end(), uv.begin()) ||
     !check_atlas(mesh, chart, uv, charts.charts.size()))
  {
    std::cerr << "the cancelled call changed the maps" << std::endl;
    return 1;
  }
  std::cout << "the maps still hold the grid atlas\n";
  return 0;
}
