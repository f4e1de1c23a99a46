// EXPECT: count parameters (number_of_seeds
// A count given as a double would be truncated (40.7 seeds -> 40).
#include <CGAL/Disk_segmentation/voronoi_fps_segmentation.h>
#include "common.h"

int main()
{
  Mesh m;
  std::map<Mesh::Face_index, int> ids;
  return int(DS::voronoi_fps_segmentation(m, boost::make_assoc_property_map(ids),
                                          DS::parameters::number_of_seeds(40.7)));
}
