// EXPECT-SUCCESS
// Every parameter of the package chains with CGAL's ones in either order,
// from CGAL::Disk_segmentation::parameters; a chain of CGAL's parameters
// alone, started from CGAL::parameters, is accepted too.
#include <CGAL/Disk_segmentation.h>
#include "common.h"

#include <iterator>
#include <string>
#include <vector>

int main()
{
  Mesh m;
  std::map<Mesh::Face_index, std::size_t> ids;
  auto patch = boost::make_assoc_property_map(ids);
  auto vpm = m.points();
  std::vector<Mesh::Face_index> seeds;
  DS::Merge_tree tree;
  std::size_t n = 0;
  n += DS::segment_into_disks(m, patch, DS::parameters::number_of_seeds(3).vertex_point_map(vpm));
  n += DS::segment_into_disks(m, patch, DS::parameters::vertex_point_map(vpm).number_of_seeds(3));
  n += DS::segment_into_disks(m, patch, DS::parameters::number_of_subsamples(3).geom_traits(K()));
  n += DS::segment_into_disks(m, patch, DS::parameters::geom_traits(K()).number_of_subsamples(3));
  n += DS::segment_into_disks(m, patch, DS::parameters::merge_threshold(0.5).random_seed(3u));
  n += DS::segment_into_disks(m, patch, DS::parameters::random_seed(3u).merge_threshold(0.5));
  n += DS::voronoi_fps_segmentation(m, patch, DS::parameters::seeds_output_iterator(std::back_inserter(seeds))
                                                .first_seed(*faces(m).begin()).vertex_point_map(vpm));
  n += DS::voronoi_fps_segmentation(m, patch, DS::parameters::vertex_point_map(vpm).first_seed(*faces(m).begin())
                                                .seeds_output_iterator(std::back_inserter(seeds)));
  n += DS::voronoi_fps_segmentation(m, patch, CGAL::parameters::vertex_point_map(vpm).random_seed(1u));
  n += DS::segment_into_disks(m, patch, DS::parameters::merge_tree(&tree).vertex_point_map(vpm)
                                          .smooth_borders(false));
  n += DS::segment_into_disks(m, patch, DS::parameters::smooth_borders(false).vertex_point_map(vpm)
                                          .merge_tree(&tree));
  Mesh::Property_map<Mesh::Halfedge_index, K::Point_2> uv =
    m.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
  const auto everything = DS::parameters::vertex_point_map(vpm)
    .parameterization_method(DS::Parameterization_method::ARAP).use_fallback(true).require_disk_patches(true)
    .max_area_distortion(1.).max_angle_distortion(1.).max_stretch(10.).max_area_scale(10.).max_stretch_p95(2.)
    .distortion_bound(DS::Distortion_bound()).max_chart_faces(1000u).number_of_threads(1u)
    .progress_callback([](const std::string&, std::size_t, std::size_t) {}).merge_charts(true).smooth_borders(true)
    .packing_method(DS::Packing_method::TIGHT).texture_resolution(512u).padding_in_texels(2.)
    .number_of_seeds(4).number_of_subsamples(3).merge_threshold(0.7).face_patch_map(patch);
  const auto reversed = DS::parameters::face_patch_map(patch).merge_threshold(0.7).number_of_subsamples(3)
    .number_of_seeds(4).padding_in_texels(2.).texture_resolution(512u).packing_method(DS::Packing_method::TIGHT)
    .smooth_borders(true).merge_charts(true).progress_callback([](const std::string&, std::size_t, std::size_t) {})
    .number_of_threads(1u).max_chart_faces(1000u).distortion_bound(DS::Distortion_bound())
    .max_stretch_p95(2.).max_area_scale(10.).max_stretch(10.).max_angle_distortion(1.).max_area_distortion(1.)
    .require_disk_patches(true).use_fallback(true).parameterization_method(DS::Parameterization_method::ARAP)
    .vertex_point_map(vpm);
  DS::uv_atlas(m, uv, everything);
  DS::uv_atlas(m, uv, reversed);
  return int(n);
}
