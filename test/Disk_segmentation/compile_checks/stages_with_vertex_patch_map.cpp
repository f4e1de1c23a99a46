// EXPECT: the face patch map must have face_descriptor as key type
// EXPECT-ONE-ERROR
// Every function that takes a patch map checks its key as uv_atlas() does.
#include <CGAL/Disk_segmentation.h>
#include "common.h"

int main()
{
  Mesh m;
  auto uv = m.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
  auto ids = m.add_property_map<Mesh::Vertex_index, std::size_t>("v:patch").first;
  DS::segment_into_disks(m, ids);
  DS::voronoi_fps_segmentation(m, ids);
  DS::refine_to_topological_disks(m, ids);
  DS::merge_disk_regions(m, ids);
  DS::parameterize_patches(m, ids, uv);
  return int(DS::pack_patches(m, ids, uv).number_of_charts);
}
