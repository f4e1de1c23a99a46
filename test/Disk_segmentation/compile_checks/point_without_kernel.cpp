// EXPECT: must be a CGAL point with a kernel
// EXPECT-ONE-ERROR
// A vertex point map of plain arrays: one readable error, not a page of
// template errors from inside the package.
#include <CGAL/Disk_segmentation/voronoi_fps_segmentation.h>
#include "common.h"

int main()
{
  Mesh m;
  std::map<Mesh::Vertex_index, std::array<double, 3> > coordinates;
  std::map<Mesh::Face_index, int> ids;
  return int(DS::voronoi_fps_segmentation(m, boost::make_assoc_property_map(ids),
                                          DS::parameters::vertex_point_map(
                                            boost::make_assoc_property_map(coordinates))));
}
