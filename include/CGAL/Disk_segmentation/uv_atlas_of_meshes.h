// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_UV_ATLAS_OF_MESHES_H
#define CGAL_DISK_SEGMENTATION_UV_ATLAS_OF_MESHES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Multi_mesh_atlas_report.h>
#include <CGAL/Disk_segmentation/uv_atlas.h>

#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <boost/graph/graph_traits.hpp>

#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {

namespace internal {

// Room in `all` for a copy of each mesh of `meshes` (pointers): without it,
// copy_face_graph() reserves the copy so far plus one mesh, to the element,
// so that every mesh moved the copy (3000 tetrahedra: 0.6 s and 400 MB,
// quadratic in the meshes).
template <typename Copy, typename MeshPointers>
void reserve_for_copies(Copy& all, const MeshPointers& meshes)
{
  std::size_t vertices = 0, edges = 0, faces = 0;
  for(const auto* tm : meshes)
  {
    vertices += static_cast<std::size_t>(num_vertices(*tm));
    edges += static_cast<std::size_t>(num_edges(*tm));
    faces += static_cast<std::size_t>(num_faces(*tm));
  }
  all.reserve(vertices, edges, faces);
}

} // namespace internal

/// \ingroup PkgDiskSegmentationRef
///
/// Computes one UV atlas for several meshes (xatlas' `AddMesh` for each
/// mesh, then `Generate`): every mesh is segmented and parameterized alone,
/// exactly as `uv_atlas()` would (its charts do not depend on the other
/// meshes), and the charts of all meshes are then packed together into the
/// unit square, at one texel density with `Packing_method::TIGHT`.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` whose faces are triangles
/// @tparam UVMap a model of `WritablePropertyMap` with `halfedge_descriptor` as key type and a 2D point
///         type as value type
/// @tparam FacePatchMap a model of `WritablePropertyMap` with `face_descriptor` as key type and an
///         integral value type
/// @tparam NamedParameters a sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters"
///
/// @param meshes the meshes (not null), each manifold and without garbage
/// @param uv_maps one per mesh: receives its per-corner UVs in the common atlas
/// @param face_patch_maps one per mesh: receives the chart id of every face; ids are numbered across
///        the meshes (see `Multi_mesh_atlas_report::first_chart`)
/// @param np the named parameters of `uv_atlas()`, read for every mesh (a `vertex_point_map`, a
///        `face_material_map` or a `face_polygon_map` must then be valid for all of them), except
///        `face_patch_map`, `merge_tree` and `seeds_output_iterator`, which do not apply
///
/// @throws Input_error on a bad mesh (naming its position) or parameter, or when the charts of all
///         meshes are more than the padding leaves room for
/// @throws Cancelled when `progress_callback` returns `false`
///
/// Whatever it throws, the caller's maps are as they were. Time: the sum of `uv_atlas()` on each
/// mesh without its packing, plus one packing of all charts; memory: that of the largest mesh's
/// atlas, plus a copy of all meshes for the packing.
template <typename TriangleMesh, typename UVMap, typename FacePatchMap,
          typename NamedParameters = parameters::Default_named_parameters>
Multi_mesh_atlas_report uv_atlas_of_meshes(const std::vector<const TriangleMesh*>& meshes,
                                           const std::vector<UVMap>& uv_maps,
                                           const std::vector<FacePatchMap>& face_patch_maps,
                                           const NamedParameters& np = parameters::default_values())
{
  static_assert(internal::Check_named_parameters<NamedParameters>::value, "");
  static_assert(internal::Check_patch_map<FacePatchMap>::value, "");
  static_assert(CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::face_patch_t>::value,
                "CGAL::Disk_segmentation::uv_atlas_of_meshes: give the patch maps as its third argument, "
                "not as face_patch_map");
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<UVMap>::value_type UV_point;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<std::size_t> >::const_type
    Staged_patch_map;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_halfedge_property_t<UV_point> >::const_type
    Staged_uv_map;

  CGAL::Real_timer total;
  total.start();
  if(uv_maps.size() != meshes.size() || face_patch_maps.size() != meshes.size())
    throw Input_error("uv_atlas_of_meshes: " + std::to_string(meshes.size()) + " meshes, " +
                      std::to_string(uv_maps.size()) + " UV maps and " + std::to_string(face_patch_maps.size()) +
                      " patch maps: give one of each per mesh");
  for(std::size_t i = 0; i < meshes.size(); ++i)
    if(meshes[i] == nullptr)
      throw Input_error("uv_atlas_of_meshes: mesh #" + std::to_string(i) + " is null");
  check_uv_atlas_parameters(np);
  internal::Packing_settings packing = internal::packing_settings(np);
  internal::Progress progress = internal::Progress::from(np);
  packing.progress = &progress;
  const internal::Parameterization_settings settings = internal::parameterization_settings(np);
  const internal::Segmentation_settings segmentation = internal::segmentation_settings(np);
  const auto stage_parameters = internal::stage_parameters(np, segmentation);

  // Each mesh alone, into maps of its own.
  Multi_mesh_atlas_report report;
  std::vector<Staged_patch_map> staged_patches;
  std::vector<Staged_uv_map> staged_uvs;
  report.first_chart.push_back(0);
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    const TriangleMesh& tm = *meshes[i];
    staged_patches.push_back(get(CGAL::dynamic_face_property_t<std::size_t>(), tm));
    staged_uvs.push_back(get(CGAL::dynamic_halfedge_property_t<UV_point>(), tm));
    Merge_tree tree;
    std::vector<face_descriptor> seeds;
    try
    {
      report.meshes.push_back(internal::segment_and_parameterize(tm, staged_patches.back(), staged_uvs.back(),
                                                                 stage_parameters, segmentation, settings, packing,
                                                                 progress, tree,
                                                                 seeds));
    }
    catch(const Input_error& e)
    {
      throw Input_error("mesh #" + std::to_string(i) + ": " + e.what());
    }
    report.first_chart.push_back(report.first_chart.back() + report.meshes.back().number_of_charts);
  }
  internal::check_packing_capacity(packing, report.first_chart.back());

  // All charts packed together, on a copy of the meshes.
  CGAL::Real_timer timer;
  timer.start();
  progress("packing", 0, 1);
  // The copy holds the points the packing measures: those of `vertex_point_map`.
  auto vpm = [&np](const TriangleMesh& tm) { return internal::vertex_point_map_parameter(tm, np); };
  typedef typename boost::property_traits<decltype(vpm(*meshes.front()))>::value_type Point;
  typedef CGAL::Surface_mesh<Point> Copy;
  Copy all;
  auto all_patch = all.template add_property_map<typename Copy::Face_index, std::size_t>("f:patch", 0).first;
  auto all_uv = all.template add_property_map<typename Copy::Halfedge_index, UV_point>("h:uv").first;
  std::vector<std::vector<std::pair<halfedge_descriptor, typename Copy::Halfedge_index> > > copied(meshes.size());
  internal::reserve_for_copies(all, meshes);
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    std::vector<std::pair<face_descriptor, typename Copy::Face_index> > faces_copied;
    CGAL::copy_face_graph(*meshes[i], all,
                          CGAL::parameters::halfedge_to_halfedge_output_iterator(std::back_inserter(copied[i]))
                            .face_to_face_output_iterator(std::back_inserter(faces_copied))
                            .vertex_point_map(vpm(*meshes[i])));
    for(const auto& f : faces_copied)
      all_patch[f.second] = report.first_chart[i] + get(staged_patches[i], f.first);
    for(const auto& h : copied[i])
      if(!is_border(h.first, *meshes[i]))
        all_uv[h.second] = get(staged_uvs[i], h.first);
  }
  report.packing = internal::pack_checked_patches(all, all_patch, all_uv, packing, parameters::default_values());
  report.packing_seconds = timer.time();
  progress("packing", 1, 1);

  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    const TriangleMesh& tm = *meshes[i];
    typedef typename boost::property_traits<FacePatchMap>::value_type Id;
    for(face_descriptor f : faces(tm))
      put(face_patch_maps[i], f, static_cast<Id>(report.first_chart[i] + get(staged_patches[i], f)));
    for(const auto& h : copied[i])
      if(!is_border(h.first, tm))
        put(uv_maps[i], h.first, all_uv[h.second]);
  }
  report.total_seconds = total.time();
  return report;
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_UV_ATLAS_OF_MESHES_H
