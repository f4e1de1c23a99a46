// EXPECT: the face patch map must have face_descriptor as key type
// EXPECT-ONE-ERROR
// A patch id belongs to a face; a vertex lies in several patches.
#include <CGAL/Disk_segmentation/uv_atlas.h>
#include "common.h"

int main()
{
  Mesh m;
  auto uv = m.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
  auto ids = m.add_property_map<Mesh::Vertex_index, std::size_t>("v:patch").first;
  return int(DS::uv_atlas(m, uv, CGAL::parameters::face_patch_map(ids)).number_of_charts);
}
