// EXPECT: the UV map must have halfedge_descriptor as key type
// EXPECT-ONE-ERROR
// UVs are per corner: a vertex on a seam has one UV in each chart.
#include <CGAL/Disk_segmentation.h>
#include "common.h"

int main()
{
  Mesh m;
  auto uv = m.add_property_map<Mesh::Vertex_index, K::Point_2>("v:uv").first;
  auto ids = m.add_property_map<Mesh::Face_index, std::size_t>("f:patch").first;
  DS::uv_atlas(m, uv);
  DS::parameterize_patches(m, ids, uv);
  return int(DS::pack_patches(m, ids, uv).number_of_charts);
}
