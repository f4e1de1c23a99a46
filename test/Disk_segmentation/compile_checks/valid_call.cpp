// EXPECT-SUCCESS
// The control: a correct call compiles, so the failures below come from
// the checks and not from the set-up.
#include <CGAL/Disk_segmentation/voronoi_fps_segmentation.h>
#include "common.h"

int main()
{
  Mesh m;
  std::map<Mesh::Face_index, int> ids;
  return int(DS::voronoi_fps_segmentation(m, boost::make_assoc_property_map(ids),
                                          DS::parameters::number_of_seeds(12).vertex_point_map(m.points())));
}
